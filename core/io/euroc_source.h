// Reader for EuRoC MAV / ASL folders: mav0/cam0, mav0/cam1, state_groundtruth_estimate0.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/io/recorded_source.h"

namespace sightline {

// An EuRoC (ASL layout) recording as raw, unrectified stereo pairs.
//
// `path` is the dataset folder holding mav0/, or mav0/ itself. Each camera folder has data.csv
// ("timestamp [ns],filename"), data/*.png and sensor.yaml (pinhole intrinsics [fu fv cu cv],
// radial-tangential distortion, resolution, rate_hz, T_BS = body_from_sensor). Left = cam0,
// right = cam1; pairs are images with equal timestamps. right_from_left is
// inverse(body_from_cam1) * body_from_cam0.
//
// Ground truth (groundtruth_tum.txt, else EuRoC's data.csv) is of the body (IMU) frame; the
// reader transforms it with cam0's T_BS (and the ground-truth sensor's own T_BS) so that
// ground_truth() is, like for every source, the pose of the left camera: world_from_cam0 =
// world_from_body * body_from_cam0. info().notes says so.
//
//   EurocSource source("../shared/data/euroc_v1_01_static");
//   if (Status s = source.Open(); !s.ok()) return s;
//   double baseline_m = source.info().stereo->BaselineM();  // ~0.110
class EurocSource : public RecordedSource {
 public:
  explicit EurocSource(std::string path) : path_(std::move(path)) {}

  // File readers need no driver: always Ok.
  static Status Available() { return Status::Ok(); }

  // Reads both sensor.yaml and data.csv, pairs the images, checks they exist, decodes the first
  // pair and reads the ground truth.
  Status Open() override;

 protected:
  // Decodes frame `index`.
  StatusOr<Frame> Load(int64_t index) override;
  std::string FrameFile(int64_t index) const override;

 private:
  std::string path_;
  std::vector<std::string> left_files_;
  std::vector<std::string> right_files_;
};

}  // namespace sightline
