#include "core/mapping/person_boxes.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <opencv2/objdetect.hpp>
#include <sstream>

#include "core/common/text_file.h"
#include "core/mapping/option_check.h"

namespace sightline {

using mapping_internal::Invalid;

bool PersonDetectorOptions::IsValid(std::string* error) const {
  if (source != "auto" && source != "ground_truth" && source != "depth" && source != "hog" &&
      source != "none") {
    return Invalid(error, "mapping.people.source must be auto, ground_truth, depth, hog or none");
  }
  if (!(depth_cell_m >= 0.01 && depth_cell_m <= 0.5)) {
    return Invalid(error, "mapping.people.depth_cell_m must lie in [0.01, 0.5]");
  }
  if (depth_target_columns < 16) {
    return Invalid(error, "mapping.people.depth_target_columns must be >= 16");
  }
  if (!(depth_max_range_m >= 0.5 && depth_max_range_m <= 20)) {
    return Invalid(error, "mapping.people.depth_max_range_m must lie in [0.5, 20]");
  }
  if (!(depth_min_height_m > 0 && depth_max_height_m > depth_min_height_m)) {
    return Invalid(error,
                   "mapping.people.depth_min_height_m must be > 0 and below depth_max_height_m");
  }
  if (!(depth_min_width_m > 0 && depth_max_width_m > depth_min_width_m)) {
    return Invalid(error,
                   "mapping.people.depth_min_width_m must be > 0 and below depth_max_width_m");
  }
  if (!(depth_min_thickness_m >= 0)) {
    return Invalid(error, "mapping.people.depth_min_thickness_m must be >= 0");
  }
  if (!(depth_max_foot_m > 0)) return Invalid(error, "mapping.people.depth_max_foot_m must be > 0");
  if (!(depth_min_height_to_length >= 0 && depth_min_height_to_length <= 20)) {
    return Invalid(error, "mapping.people.depth_min_height_to_length must lie in [0, 20]");
  }
  if (!std::isfinite(depth_hog_min_score) || !std::isfinite(depth_hog_min_score_cut)) {
    return Invalid(error,
                   "mapping.people.depth_hog_min_score and depth_hog_min_score_cut must be finite");
  }
  if (depth_min_points < 1) return Invalid(error, "mapping.people.depth_min_points must be >= 1");
  if (!(depth_head_drop_m > 0))
    return Invalid(error, "mapping.people.depth_head_drop_m must be > 0");
  if (!(depth_head_radius_m > 0)) {
    return Invalid(error, "mapping.people.depth_head_radius_m must be > 0");
  }
  if (hog_max_columns < 64) return Invalid(error, "mapping.people.hog_max_columns must be >= 64");
  if (!(hog_scale_step > 1.0)) return Invalid(error, "mapping.people.hog_scale_step must be > 1");
  if (!(hog_box_shrink >= 0 && hog_box_shrink < 0.5)) {
    return Invalid(error, "mapping.people.hog_box_shrink must lie in [0, 0.5)");
  }
  return true;
}

OptionTable<PersonDetectorOptions> PersonDetectorOptions::Describe() {
  using O = PersonDetectorOptions;
  return OptionTable<O>("mapping.people")
      .Choice("source", &O::source, {"auto", "ground_truth", "depth", "hog", "none"},
              "Where person boxes come from: the dataset's ground truth, clusters of a person's "
              "size standing on the floor in the depth image (depth), OpenCV's HOG detector on "
              "the colour image, auto (ground truth when present, else depth) or none.")
      .Double("depth_cell_m", &O::depth_cell_m, "m", 0.01, 0.5, 0.01,
              "depth: floor grid cell in which points are clustered.")
      .Int("depth_target_columns", &O::depth_target_columns, "px", 16, 4096, 16,
           "depth: the depth image is sampled to about this many columns.")
      .Double("depth_max_range_m", &O::depth_max_range_m, "m", 0.5, 20, 0.5,
              "depth: points farther away are not looked at.")
      .Double("depth_min_height_m", &O::depth_min_height_m, "m", 0.05, 5, 0.05,
              "depth: a person's top lies at least this high above the floor.")
      .Double("depth_max_height_m", &O::depth_max_height_m, "m", 0.1, 5, 0.05,
              "depth: a person's top lies at most this high (walls and pillars go higher).")
      .Double("depth_min_width_m", &O::depth_min_width_m, "m", 0.01, 5, 0.05,
              "depth: a person's footprint is at least this long.")
      .Double("depth_max_width_m", &O::depth_max_width_m, "m", 0.05, 5, 0.05,
              "depth: a person's footprint is at most this long (walls are longer); wider "
              "clusters are split at their heads.")
      .Double("depth_min_thickness_m", &O::depth_min_thickness_m, "m", 0, 2, 0.02,
              "depth: the shorter side of a person's footprint is at least this (legs, arms and "
              "the torso's curve); the end of a wall seen at the edge of view is one cell "
              "thick.")
      .Double("depth_max_foot_m", &O::depth_max_foot_m, "m", 0.01, 2, 0.05,
              "depth: a person's lowest point lies at most this high above the floor.")
      .Double("depth_min_height_to_length", &O::depth_min_height_to_length, "", 0, 20, 0.1,
              "depth: a person's top lies at least this many footprint lengths above the floor "
              "(a desk, a table or a sofa is wider than it is tall).")
      .Int("depth_min_points", &O::depth_min_points, "", 1, 100000, 10,
           "depth: sampled points a person needs.")
      .Double("depth_head_radius_m", &O::depth_head_radius_m, "m", 0.05, 2, 0.05,
              "depth: a head is the highest point within this radius; people side by side are "
              "split at their heads.")
      .Double("depth_head_drop_m", &O::depth_head_drop_m, "m", 0.01, 2, 0.05,
              "depth: between two heads the tops dip at least this much (neck, shoulders); the "
              "cut-off top of a wall is flat and is not split.")
      .Bool("depth_require_top", &O::depth_require_top,
            "depth: when on, a cluster reaching the image's top row (its top out of view) is not "
            "a person: fewer false people at the edge of view, but people near enough to have "
            "their heads cut off are missed.")
      .Bool("depth_hog_check", &O::depth_hog_check,
            "depth: when the colour image is registered to the depth image, OpenCV's HOG "
            "people detector must also score each cluster's box (a chair or a desk of a "
            "person's size is dropped).")
      .Double("depth_hog_min_score", &O::depth_hog_min_score, "", -10, 10, 0.1,
              "depth: the HOG score a cluster's box needs when the whole box is in view.")
      .Double("depth_hog_min_score_cut", &O::depth_hog_min_score_cut, "", -10, 10, 0.1,
              "depth: the HOG score a cluster's box needs when it touches the image's border "
              "(a body cut off scores lower).");
}

struct HogPersonDetector::Impl {
  cv::HOGDescriptor hog;
  cv::Mat small;
  cv::Mat gray;
};

HogPersonDetector::HogPersonDetector(PersonDetectorOptions options)
    : options_(std::move(options)), impl_(std::make_unique<Impl>()) {
  impl_->hog.setSVMDetector(cv::HOGDescriptor::getDefaultPeopleDetector());
}

HogPersonDetector::~HogPersonDetector() = default;

StatusOr<std::vector<PersonBox>> HogPersonDetector::Detect(const cv::Mat& image) {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  std::vector<PersonBox> people;
  if (image.empty()) return people;
  if (image.type() != CV_8UC3 && image.type() != CV_8UC1) {
    return InvalidArgument("person detector: expected an 8-bit BGR or grey image");
  }
  const double scale = image.cols > options_.hog_max_columns
                           ? static_cast<double>(options_.hog_max_columns) / image.cols
                           : 1.0;
  const cv::Mat* input = &image;
  if (scale < 1.0) {
    cv::resize(image, impl_->small, cv::Size(), scale, scale, cv::INTER_AREA);
    input = &impl_->small;
  }
  if (input->rows < impl_->hog.winSize.height || input->cols < impl_->hog.winSize.width) {
    return people;
  }
  std::vector<cv::Rect> found;
  std::vector<double> weights;
  impl_->hog.detectMultiScale(*input, found, weights, options_.hog_hit_threshold, cv::Size(8, 8),
                              cv::Size(), options_.hog_scale_step, 2.0);
  for (size_t i = 0; i < found.size(); ++i) {
    const cv::Rect& r = found[i];
    const double sx = options_.hog_box_shrink * r.width, sy = options_.hog_box_shrink * r.height;
    PersonBox person;
    person.box = cv::Rect2d((r.x + sx) / scale, (r.y + sy) / scale, (r.width - 2 * sx) / scale,
                            (r.height - 2 * sy) / scale);
    person.image_size = image.size();
    person.score = i < weights.size() ? weights[i] : 1.0;
    people.push_back(person);
  }
  return people;
}

double HogPersonDetector::Score(const cv::Mat& image, const cv::Rect2d& box) {
  if (image.empty() || box.width < 1 || box.height < 1) {
    return -std::numeric_limits<double>::infinity();
  }
  // The default people detector's 64 x 128 window holds a person about 96 px tall, centred.
  const cv::Size win = impl_->hog.winSize;
  const double body = 96.0;
  double best = -std::numeric_limits<double>::infinity();
  for (double grow : {0.9, 1.0, 1.12}) {
    const double scale = body / (box.height * grow);  // Image pixels to window pixels.
    // A region one window plus a cell margin around the box's centre, in the image.
    const double w = (win.width + 16) / scale, h = (win.height + 16) / scale;
    const cv::Point2d c(box.x + box.width / 2, box.y + box.height / 2);
    const cv::Rect region(static_cast<int>(std::floor(c.x - w / 2)),
                          static_cast<int>(std::floor(c.y - h / 2)), static_cast<int>(std::ceil(w)),
                          static_cast<int>(std::ceil(h)));
    const cv::Rect inside = region & cv::Rect(0, 0, image.cols, image.rows);
    if (inside.empty()) continue;
    cv::Mat padded;
    cv::copyMakeBorder(image(inside), padded, inside.y - region.y, region.br().y - inside.br().y,
                       inside.x - region.x, region.br().x - inside.br().x, cv::BORDER_REPLICATE);
    cv::resize(padded, impl_->small, cv::Size(win.width + 16, win.height + 16), 0, 0,
               cv::INTER_AREA);
    std::vector<cv::Point> hits;
    std::vector<double> weights;
    impl_->hog.detect(impl_->small, hits, weights, -1e9, cv::Size(8, 8));
    for (double s : weights) best = std::max(best, s);
  }
  return best;
}

// --- Ground-truth table ---------------------------------------------------------------------

void PersonBoxTable::Add(int64_t frame, double time_s, const PersonBox& box) {
  by_frame_[frame].push_back(box);
  if (std::isfinite(time_s)) frame_of_time_[time_s] = frame;
}

void PersonBoxTable::SetImageSize(const cv::Size& size) {
  for (auto& [frame, boxes] : by_frame_) {
    for (PersonBox& box : boxes) {
      if (box.image_size.area() == 0) box.image_size = size;
    }
  }
}

const std::vector<PersonBox>& PersonBoxTable::ForFrame(int64_t frame) const {
  auto it = by_frame_.find(frame);
  return it == by_frame_.end() ? empty_ : it->second;
}

const std::vector<PersonBox>& PersonBoxTable::ForTime(double time_s, double tolerance_s) const {
  if (frame_of_time_.empty()) return empty_;
  auto it = frame_of_time_.lower_bound(time_s);
  const std::pair<const double, int64_t>* best = nullptr;
  if (it != frame_of_time_.end()) best = &*it;
  if (it != frame_of_time_.begin()) {
    auto prev = std::prev(it);
    if (best == nullptr || time_s - prev->first < best->first - time_s) best = &*prev;
  }
  if (best == nullptr || std::abs(best->first - time_s) > tolerance_s) return empty_;
  return ForFrame(best->second);
}

StatusOr<PersonBoxTable> PersonBoxTable::Read(const std::string& path) {
  std::ifstream in(path);
  if (!in) return NotFound("person boxes " + path + " not found");
  std::string line;
  int number = 0;
  std::vector<std::string> header;
  while (header.empty() && std::getline(in, line)) {
    ++number;
    if (!line.empty() && line[0] == '#') line = line.substr(1);
    header = SplitFields(line.substr(0, line.find('(')));  // Drop a trailing "(comment)".
  }
  if (header.empty()) return ParseError(path + ": empty file, expected a header line");
  auto column = [&header](std::initializer_list<const char*> names) {
    for (const char* name : names) {
      for (size_t i = 0; i < header.size(); ++i) {
        if (header[i] == name) return static_cast<int>(i);
      }
    }
    return -1;
  };
  const int c_frame = column({"frame", "frame_index", "index"});
  const int c_time = column({"time_s", "timestamp", "time", "t"});
  const int c_id = column({"person", "person_id", "id"});
  // Corner columns: u0, v0, u1, v1 (the simulator's, inclusive) or x_min, ... (exclusive).
  const int c_u0 = column({"u0"}), c_v0 = column({"v0"}), c_u1 = column({"u1"}),
            c_v1 = column({"v1"});
  const bool inclusive = c_u0 >= 0 && c_v0 >= 0 && c_u1 >= 0 && c_v1 >= 0;
  const int c_x0 = inclusive ? c_u0 : column({"u_min", "x_min", "left", "x"});
  const int c_y0 = inclusive ? c_v0 : column({"v_min", "y_min", "top", "y"});
  const int c_x1 = inclusive ? c_u1 : column({"u_max", "x_max", "right"});
  const int c_y1 = inclusive ? c_v1 : column({"v_max", "y_max", "bottom"});
  const int c_pixels = column({"pixels"});
  const int c_w = column({"width", "w"});
  const int c_h = column({"height", "h"});
  const int c_iw = column({"image_width", "image_w"});
  const int c_ih = column({"image_height", "image_h"});
  if ((c_frame < 0 && c_time < 0) || c_x0 < 0 || c_y0 < 0 || (c_x1 < 0 && c_w < 0) ||
      (c_y1 < 0 && c_h < 0)) {
    return ParseError(path + " line " + std::to_string(number) +
                      ": expected a header with frame (or time_s), x_min, y_min and x_max, "
                      "y_max (or width, height)");
  }
  PersonBoxTable table;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    DataLine data{number, line};
    StatusOr<std::vector<double>> values = ParseNumbers(data, header.size(), path);
    if (!values.ok()) return values.status();
    const std::vector<double>& v = *values;
    if (c_pixels >= 0 && v[c_pixels] <= 0) continue;  // Person out of view.
    PersonBox box;
    box.id = c_id >= 0 ? static_cast<int>(v[c_id]) : -1;
    const double x0 = v[c_x0], y0 = v[c_y0];
    const double x1 = c_x1 >= 0 ? v[c_x1] + (inclusive ? 1 : 0) : x0 + v[c_w];
    const double y1 = c_y1 >= 0 ? v[c_y1] + (inclusive ? 1 : 0) : y0 + v[c_h];
    if (x1 < x0 || y1 < y0) {
      return ParseError(path + " line " + std::to_string(number) + ": box has negative size");
    }
    box.box = cv::Rect2d(x0, y0, x1 - x0, y1 - y0);
    if (c_iw >= 0 && c_ih >= 0) {
      box.image_size = cv::Size(static_cast<int>(v[c_iw]), static_cast<int>(v[c_ih]));
    }
    const int64_t frame = c_frame >= 0 ? static_cast<int64_t>(v[c_frame]) : -1;
    const double time_s = c_time >= 0 ? v[c_time] : NAN;
    table.Add(frame >= 0 ? frame : static_cast<int64_t>(table.by_frame_.size()), time_s, box);
  }
  return table;
}

}  // namespace sightline
