// libFuzzer target: the parser of the arm's `arm_pose` line (core/button/PROTOCOL.md, client to
// server) and the pose buffer it feeds, on any bytes. A parsed pose must be finite with a unit
// quaternion; the buffer must interpolate without reading outside its poses.
#include <cmath>
#include <cstdlib>

#include "core/button/arm_pose_stream.h"
#include "tests/fuzz/fuzz_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static sightline::ArmPoseBuffer* buffer = new sightline::ArmPoseBuffer();
  const std::string line = sightline::fuzz::AsText(data, size);
  sightline::StatusOr<sightline::ArmPoseMessage> pose = sightline::ParseArmPoseLine(line);
  if (!pose.ok()) return 0;
  const Eigen::Quaterniond q(pose->base_from_end_effector.rotation());
  if (!std::isfinite(pose->stamp_s) || !pose->base_from_end_effector.matrix().allFinite() ||
      std::abs(q.norm() - 1) > 1e-6) {
    std::abort();  // The parser let a pose through that it promises to refuse.
  }
  buffer->Add(*pose);
  (void)buffer->At(pose->stamp_s);
  (void)buffer->At(pose->stamp_s - 0.001);
  return 0;
}
