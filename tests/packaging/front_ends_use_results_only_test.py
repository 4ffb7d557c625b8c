#!/usr/bin/env python3
"""Fails when a file in app/ or widgets/ includes, directly or through other project headers, a
header that declares an estimator or server class. Front ends feed frames to the core Pipeline
objects and draw their results; the estimators live behind them.

Usage: front_ends_use_results_only_test.py SOURCE_DIR"""
import os
import re
import sys

FORBIDDEN = {
    "core/stereo/stereo_odometry.h": "StereoOdometry",
    "core/mono/mono_slam.h": "MonoSlam",
    "core/mono/scale_estimator.h": "ScaleEstimator",
    "core/mobility/mobility_mapper.h": "MobilityMapper",
    "core/mapping/mapping_frame_processor.h": "MappingFrameProcessor",
    "core/mapping/floor_plane.h": "FloorPlane fitting",
    "core/button/button_picker.h": "ButtonPicker",
    "core/button/arm_server.h": "ArmServer",
}
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)


def project_includes(root, rel, cache):
    if rel not in cache:
        path = os.path.join(root, rel)
        found = []
        if os.path.isfile(path):
            with open(path, encoding="utf-8", errors="replace") as f:
                found = [h for h in INCLUDE.findall(f.read())
                         if os.path.isfile(os.path.join(root, h))]
        cache[rel] = found
    return cache[rel]


def first_forbidden_chain(root, rel, cache):
    """The include chain from `rel` to a forbidden header, or None."""
    seen = {rel}
    queue = [[rel]]
    while queue:
        chain = queue.pop(0)
        for header in project_includes(root, chain[-1], cache):
            if header in FORBIDDEN:
                return chain + [header]
            if header not in seen:
                seen.add(header)
                queue.append(chain + [header])
    return None


def main():
    root = sys.argv[1]
    cache = {}
    failures = 0
    checked = 0
    for top in ("app", "widgets"):
        for folder, _, files in os.walk(os.path.join(root, top)):
            for name in sorted(files):
                if not name.endswith((".h", ".cpp")):
                    continue
                rel = os.path.relpath(os.path.join(folder, name), root)
                checked += 1
                chain = first_forbidden_chain(root, rel, cache)
                if chain:
                    failures += 1
                    print("FAIL: %s reaches %s (%s): %s" % (
                        rel, chain[-1], FORBIDDEN[chain[-1]], " -> ".join(chain)))
    print("%d front-end files checked, %d include an estimator or server class" % (
        checked, failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
