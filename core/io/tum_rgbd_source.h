// Reader for TUM RGB-D benchmark folders (rgb/, depth/, rgb.txt, depth.txt, groundtruth.txt).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/io/recorded_source.h"
#include "core/io/timed_file_list.h"

namespace sightline {

// One colour image and the depth image taken with it.
struct TumAssociation {
  TimedFile rgb;
  TimedFile depth;
};

// Pairs colour and depth images by nearest timestamp, as TUM's associate.py does: candidate
// pairs closer than max_dt_s are taken in order of increasing time difference, each image used at
// most once. The result is ordered by colour time.
std::vector<TumAssociation> AssociateByTime(const std::vector<TimedFile>& rgb,
                                            const std::vector<TimedFile>& depth,
                                            double max_dt_s = 0.02);

// Which TUM Kinect (freiburg 1, 2 or 3) `text` names: "rgbd_dataset_freiburg1_desk",
// "tum_fr2_xyz". nullopt when none.
std::optional<int> DetectFreiburgCamera(const std::string& text);

// TUM's published intrinsics of Kinect `freiburg` (1, 2, 3) at 640x480; any other value gives
// the ROS default (525, 525, 319.5, 239.5) that TUM recommends for unknown sequences.
PinholeCamera TumCamera(int freiburg);

// A TUM RGB-D sequence folder as RGB-D frames (colour BGR, depth in metres, NaN = no reading).
//
// Pairs come from associations.txt (or associate.txt: "t_rgb rgb/x.png t_depth depth/y.png")
// when present, else from rgb.txt and depth.txt by nearest timestamp (at most 0.02 s apart).
// Intrinsics come from camera.yaml beside the lists (see camera_yaml.h), else from the sequence
// name (the lists' "# file: 'rgbd_dataset_freiburgN_...'" header, then the folder name), else
// the ROS default; info().notes says which. Depth PNGs are 16-bit, value / depth_scale metres
// (5000 unless camera.yaml says otherwise). groundtruth.txt, when present, is the pose of the
// colour camera. Frame times are the colour image times.
//
//   TumRgbdSource source("../shared/data/tum_fr1_desk");
//   if (Status s = source.Open(); !s.ok()) return s;
//   while (source.Grab().ok()) auto frame = source.Retrieve();  // RgbdFrame
class TumRgbdSource : public RecordedSource {
 public:
  explicit TumRgbdSource(std::string folder) : folder_(std::move(folder)) {}

  // File readers need no driver: always Ok.
  static Status Available() { return Status::Ok(); }

  // Reads the lists, checks every listed image exists, picks the intrinsics, decodes the first
  // pair and reads groundtruth.txt.
  Status Open() override;

  // The colour/depth pairs found by Open().
  const std::vector<TumAssociation>& associations() const { return pairs_; }

 protected:
  // Decodes frame `index`.
  StatusOr<Frame> Load(int64_t index) override;
  std::string FrameFile(int64_t index) const override;

 private:
  std::string folder_;
  std::vector<TumAssociation> pairs_;
  double depth_scale_ = 5000;
};

}  // namespace sightline
