// Reader for KITTI odometry sequences (rectified grey stereo, calib.txt, poses, times).
#pragma once

#include <string>
#include <vector>

#include "core/io/recorded_source.h"

namespace sightline {

// A KITTI odometry sequence folder as rectified stereo pairs.
//
// Layout: image_0/ + image_1/ (KITTI) or image_l/ + image_r/, with images of equal names;
// calib.txt with the 3x4 projection matrices P0 and P1, 12 numbers per line, either labelled
// ("P0: ...", KITTI's own file, which also has P2 P3 Tr) or unlabelled (first line P0, second
// P1). Baseline = (P0[0][3] - P1[0][3]) / P1[0][0]. times.txt (one time per image) when present,
// else times are synthesized at 10 Hz and info().notes says so. Ground truth from poses.txt in
// the folder, or KITTI's ../../poses/NN.txt for dataset/sequences/NN: the pose of the left
// camera in the frame of the left camera at image 0.
//
//   KittiSource source("../shared/data/kitti_clip1");
//   if (Status s = source.Open(); !s.ok()) return s;
//   double baseline_m = source.info().stereo->BaselineM();  // 0.537
class KittiSource : public RecordedSource {
 public:
  explicit KittiSource(std::string folder) : folder_(std::move(folder)) {}

  // File readers need no driver: always Ok.
  static Status Available() { return Status::Ok(); }

  // Lists the image pairs, reads calib.txt, times and poses, decodes the first image.
  Status Open() override;

 protected:
  // Decodes frame `index`.
  StatusOr<Frame> Load(int64_t index) override;
  std::string FrameFile(int64_t index) const override;

 private:
  std::string folder_;
  std::vector<std::string> left_files_;
  std::vector<std::string> right_files_;
};

}  // namespace sightline
