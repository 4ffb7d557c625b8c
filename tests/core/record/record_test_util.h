// Helpers for recorder tests: simulated recordings made once per test binary and frame-by-frame
// comparison of two sources.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/io/dataset.h"

namespace sightline::testing {

// Every frame of a dataset, in order. Fails the test (and returns what it has) on a read error.
inline std::vector<Frame> ReadAllFrames(const std::string& path) {
  std::vector<Frame> frames;
  StatusOr<std::unique_ptr<Source>> source = OpenDataset(path);
  EXPECT_TRUE(source.ok()) << source.status().ToString();
  if (!source.ok()) return frames;
  while (true) {
    const Status grabbed = (*source)->Grab();
    if (grabbed.code() == StatusCode::kOutOfRange) break;
    EXPECT_TRUE(grabbed.ok()) << grabbed.ToString();
    if (!grabbed.ok()) break;
    StatusOr<Frame> frame = (*source)->Retrieve();
    EXPECT_TRUE(frame.ok()) << frame.status().ToString();
    if (!frame.ok()) break;
    frames.push_back(std::move(*frame));
  }
  return frames;
}

// True when two images have equal size, type and pixels (NaN equal to NaN).
inline bool SameImage(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size() || a.type() != b.type()) return false;
  if (a.empty()) return true;
  if (a.depth() == CV_32F) {
    cv::Mat a_nan = a != a, b_nan = b != b;
    if (cv::countNonZero(a_nan != b_nan) != 0) return false;
    cv::Mat a0 = a.clone(), b0 = b.clone();
    a0.setTo(0, a_nan);
    b0.setTo(0, b_nan);
    return cv::norm(a0, b0, cv::NORM_INF) == 0;
  }
  return cv::norm(a, b, cv::NORM_INF) == 0;
}

// True when the frames hold the same images (timestamps are compared by the caller).
inline bool SamePixels(const Frame& a, const Frame& b) {
  if (a.index() != b.index()) return false;
  if (const auto* x = std::get_if<RgbdFrame>(&a)) {
    const auto& y = std::get<RgbdFrame>(b);
    return SameImage(x->color, y.color) && SameImage(x->depth_m, y.depth_m);
  }
  if (const auto* x = std::get_if<StereoFrame>(&a)) {
    const auto& y = std::get<StereoFrame>(b);
    return SameImage(x->left, y.left) && SameImage(x->right, y.right);
  }
  if (const auto* x = std::get_if<MonoFrame>(&a)) {
    return SameImage(x->image, std::get<MonoFrame>(b).image);
  }
  return false;
}

// Checks that every recorded frame equals the original frame of the same timestamp (within
// `time_tolerance_s`) and returns how many matched.
inline int ExpectRecordedFramesMatch(const std::vector<Frame>& original,
                                     const std::vector<Frame>& recorded,
                                     double time_tolerance_s = 1e-6) {
  std::map<int64_t, size_t> by_time_us;
  for (size_t i = 0; i < original.size(); ++i) {
    by_time_us[std::llround(StampOf(original[i]).sensor_time_s * 1e6)] = i;
  }
  int matched = 0;
  for (size_t i = 0; i < recorded.size(); ++i) {
    const double t = StampOf(recorded[i]).sensor_time_s;
    auto it = by_time_us.find(std::llround(t * 1e6));
    EXPECT_NE(it, by_time_us.end())
        << "recorded frame " << i << " at " << t << " s has no original";
    if (it == by_time_us.end()) continue;
    EXPECT_NEAR(StampOf(original[it->second]).sensor_time_s, t, time_tolerance_s);
    EXPECT_TRUE(SamePixels(original[it->second], recorded[i])) << "recorded frame " << i;
    ++matched;
  }
  return matched;
}

}  // namespace sightline::testing
