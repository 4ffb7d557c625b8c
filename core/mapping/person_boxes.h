// People in the image, so that mapping never fits walls to them (seed 000: skeleton-tracked
// people are boxed and excluded). Boxes come from a dataset's ground truth (the simulator's
// people.csv) or from OpenCV's HOG people detector on the colour image.
#pragma once

#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/mapping/mapping_types.h"
#include "core/options/option_table.h"

namespace sightline {

// Where person boxes come from, and the detectors' settings. Keys "mapping.people.*".
struct PersonDetectorOptions {
  std::string source = "auto";  // auto: ground truth when the dataset has it, else depth;
                                // ground_truth, depth, hog or none.
  // depth (core/mapping/depth_person_detector.h): clusters standing on the floor.
  double depth_cell_m = 0.05;       // Floor grid cell [m].
  int depth_target_columns = 160;   // Depth is sampled to about this many columns.
  double depth_max_range_m = 6.0;   // Farther points are not looked at [m].
  double depth_min_height_m = 1.0;  // A person's top lies in [min, max] above the floor [m].
  double depth_max_height_m = 2.1;
  double depth_min_width_m = 0.15;  // A person's footprint (longer side) in [min, max] [m].
  double depth_max_width_m = 0.9;
  double depth_min_thickness_m = 0.22;  // The footprint's shorter side: legs, arms and the torso's
                                        // curve; a wall's end is one cell thick [m].
  double depth_max_foot_m = 0.9;        // The lowest point lies at most this high: it stands
                                        // (legs hidden by a bin or lost in far noise) [m].
  double depth_min_height_to_length = 1.5;  // Top at least this many footprint lengths high: a
                                            // desk, a table or a sofa is wider than tall.
  int depth_min_points = 40;                // Sampled points a person needs.
  double depth_head_radius_m = 0.3;  // Heads of people side by side are this far apart [m] ...
  double depth_head_drop_m = 0.2;    // ... with a dip this deep between them [m].
  bool depth_require_top = false;    // On: a cluster reaching the image's top row (its top out
                                     // of view) is not a person.
  // With colour of the depth image's shape (registered), HOG must agree with each depth
  // cluster: its best window score around the box at least depth_hog_min_score, or
  // depth_hog_min_score_cut when the box touches the image's border (a body cut off scores
  // lower). Chairs, desks and cabinets score below -1.4 on real frames.
  bool depth_hog_check = true;
  double depth_hog_min_score = -1.0;
  double depth_hog_min_score_cut = -1.3;
  double hog_hit_threshold = 0.3;  // SVM score a HOG window needs.
  int hog_max_columns = 320;       // The colour image is downscaled to at most this width first.
  double hog_scale_step = 1.08;    // Pyramid step of detectMultiScale.
  double hog_box_shrink = 0.1;     // HOG boxes are padded; shrink each side by this fraction.

  bool IsValid(std::string* error) const;
  static OptionTable<PersonDetectorOptions> Describe();
};

// OpenCV's HOG + linear SVM people detector (Dalal and Triggs; getDefaultPeopleDetector).
// About 20-60 ms per 320 x 240 image on one core: far slower than the rest of mapping, so it is
// timed as its own stage and only runs when no ground-truth boxes exist.
//
//   HogPersonDetector detector(options);
//   StatusOr<std::vector<PersonBox>> people = detector.Detect(frame.color);
class HogPersonDetector {
 public:
  explicit HogPersonDetector(PersonDetectorOptions options = {});
  ~HogPersonDetector();
  HogPersonDetector(const HogPersonDetector&) = delete;
  HogPersonDetector& operator=(const HogPersonDetector&) = delete;

  // People in a BGR or grey image. An empty image gives no people.
  StatusOr<std::vector<PersonBox>> Detect(const cv::Mat& image);
  // The best SVM score of windows framing `box` (a person's full body in `image`'s pixels) at
  // a few places and sizes around it; the image's border is replicated where the window
  // leaves it. -inf for an empty image or box.
  double Score(const cv::Mat& image, const cv::Rect2d& box);

 private:
  struct Impl;
  PersonDetectorOptions options_;
  std::unique_ptr<Impl> impl_;
};

// Ground-truth person boxes per frame, read from a CSV file.
class PersonBoxTable {
 public:
  // Reads a people.csv written by the simulator ("# frame,person,u0,v0,u1,v1,pixels", inclusive
  // corners, pixels = 0 when out of view) or any CSV whose header names frame (or time_s),
  // x_min, y_min and x_max, y_max (or width, height). Boxes carry no image size unless the file
  // has image_width and image_height columns; set it with SetImageSize. Errors name the file and
  // line.
  static StatusOr<PersonBoxTable> Read(const std::string& path);

  // Boxes of one frame (by frame index); empty when none.
  const std::vector<PersonBox>& ForFrame(int64_t frame) const;
  // Boxes nearest in time within tolerance_s; empty when none. For tables with times.
  const std::vector<PersonBox>& ForTime(double time_s, double tolerance_s) const;
  size_t frames() const { return by_frame_.size(); }
  // Adds one box (for tests and other sources).
  void Add(int64_t frame, double time_s, const PersonBox& box);
  // Sets the image size of every box that has none (the annotated camera's resolution).
  void SetImageSize(const cv::Size& size);

 private:
  std::map<int64_t, std::vector<PersonBox>> by_frame_;
  std::map<double, int64_t> frame_of_time_;
  std::vector<PersonBox> empty_;
};

}  // namespace sightline
