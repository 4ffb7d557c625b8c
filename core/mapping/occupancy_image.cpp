#include "core/mapping/occupancy_image.h"

#include <algorithm>
#include <cmath>

#include "core/mapping/option_check.h"

namespace sightline {

using mapping_internal::Invalid;

bool OccupancyImageOptions::IsValid(std::string* error) const {
  if (width_cells < 8 || height_cells < 8 || width_cells > 8192 || height_cells > 8192) {
    return Invalid(error, "mapping.occupancy.width_cells and height_cells must lie in [8, 8192]");
  }
  if (!(cell_size_m > 0)) return Invalid(error, "mapping.occupancy.cell_size_m must be positive");
  if (!(max_height_m > 0)) return Invalid(error, "mapping.occupancy.max_height_m must be positive");
  if (min_occupied_points < 1 || min_occupied_points > 255) {
    return Invalid(error, "mapping.occupancy.min_occupied_points must lie in [1, 255]");
  }
  if (target_columns < 16) return Invalid(error, "mapping.occupancy.target_columns must be >= 16");
  if (!(person_depth_margin_m > 0)) {
    return Invalid(error, "mapping.occupancy.person_depth_margin_m must be positive");
  }
  return true;
}

OptionTable<OccupancyImageOptions> OccupancyImageOptions::Describe() {
  using O = OccupancyImageOptions;
  return OptionTable<O>("mapping.occupancy")
      .Int("width_cells", &O::width_cells, "cells", 8, 8192, 10,
           "Width of the occupancy image (published: 400); the robot sits at its bottom centre.")
      .Int("height_cells", &O::height_cells, "cells", 8, 8192, 10,
           "Height of the occupancy image (published: 400), i.e. the forward range in cells.")
      .Double("cell_size_m", &O::cell_size_m, "m", 0.001, 1, 0.005,
              "Edge of one occupancy cell; RANSAC's 5-cell error scales with it.")
      .Double("max_height_m", &O::max_height_m, "m", 0.05, 10, 0.1,
              "Points higher than this above the floor (ceiling, lamps) are ignored.")
      .Int(
          "min_occupied_points", &O::min_occupied_points, "points", 1, 255, 1,
          "Depth points a cell needs to count as occupied (1 = as published: any non-floor point).")
      .Int("target_columns", &O::target_columns, "px", 16, 4096, 16,
           "Depth images are sampled to about this many columns (published: 320 x 240).")
      .Double("person_depth_margin_m", &O::person_depth_margin_m, "m", 0.05, 3, 0.05,
              "Pixels in a person box within this depth of the box's median depth are the "
              "person.");
}

OccupancyImageBuilder::OccupancyImageBuilder(OccupancyImageOptions options)
    : options_(std::move(options)) {}

Status OccupancyImageBuilder::Configure(const FloorPlane& floor, const PinholeCamera& camera) {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  if (!floor.IsValid(&error)) return InvalidArgument(error);
  if (!(camera.fx > 0 && camera.fy > 0 && camera.width > 0 && camera.height > 0)) {
    return InvalidArgument("occupancy image: the depth camera has no valid intrinsics");
  }
  if (!floor.BaseFromCameraRotation(&base_from_camera_)) {
    return InvalidArgument(
        "occupancy image: the camera looks (almost) straight at the floor; "
        "no forward direction");
  }
  const Eigen::Vector3d forward = base_from_camera_.row(0).transpose();
  const Eigen::Vector3d left = base_from_camera_.row(1).transpose();
  floor_ = floor;
  camera_ = camera;
  // Field of view: the extreme bearings over the border pixels.
  fov_min_rad_ = 1e9;
  fov_max_rad_ = -1e9;
  auto visit = [&](double u, double v) {
    const Eigen::Vector3d ray((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1.0);
    const double x = forward.dot(ray), y = left.dot(ray);
    if (x <= 0) return;
    const double bearing = std::atan2(y, x);
    fov_min_rad_ = std::min(fov_min_rad_, bearing);
    fov_max_rad_ = std::max(fov_max_rad_, bearing);
  };
  for (int u = 0; u < camera.width; ++u) {
    visit(u, 0);
    visit(u, camera.height - 1);
  }
  for (int v = 0; v < camera.height; ++v) {
    visit(0, v);
    visit(camera.width - 1, v);
  }
  if (!(fov_max_rad_ > fov_min_rad_)) {
    return InvalidArgument("occupancy image: the camera sees nothing in front of the robot");
  }
  configured_ = true;
  table_cols_ = table_rows_ = 0;  // Rebuilt on the next Build.
  return Status::Ok();
}

Status OccupancyImageBuilder::PrepareTable(int depth_cols, int depth_rows) {
  if (depth_cols == table_cols_ && depth_rows == table_rows_ && !ray_table_.empty()) {
    return Status::Ok();
  }
  const PinholeCamera cam = (camera_.width == depth_cols && camera_.height == depth_rows)
                                ? camera_
                                : camera_.Scaled(depth_cols, depth_rows);
  step_ = std::max(
      1, static_cast<int>(std::lround(static_cast<double>(depth_cols) / options_.target_columns)));
  const Eigen::Vector3d forward = base_from_camera_.row(0).transpose();
  const Eigen::Vector3d left = base_from_camera_.row(1).transpose();
  const Eigen::Vector3d up = base_from_camera_.row(2).transpose();
  ray_table_.clear();
  for (int v = 0; v < depth_rows; v += step_) {
    for (int u = 0; u < depth_cols; u += step_) {
      const Eigen::Vector3d ray((u - cam.cx) / cam.fx, (v - cam.cy) / cam.fy, 1.0);
      ray_table_.emplace_back(static_cast<float>(up.dot(ray)), static_cast<float>(forward.dot(ray)),
                              static_cast<float>(left.dot(ray)));
    }
  }
  table_cols_ = depth_cols;
  table_rows_ = depth_rows;
  return Status::Ok();
}

StatusOr<OccupancyImage> OccupancyImageBuilder::Build(const cv::Mat& depth_m,
                                                      const std::vector<PersonBox>& people) {
  if (!configured_) return FailedPrecondition("occupancy image: Configure() was not called");
  if (!depth_m.empty() && depth_m.type() != CV_32FC1) {
    return InvalidArgument("occupancy image: depth must be CV_32FC1 metres");
  }
  const int w = options_.width_cells, h = options_.height_cells;
  OccupancyImage image;
  image.cell_size_m = options_.cell_size_m;
  // Reuse the last frame's cells unless a caller still holds them (results are immutable).
  if (cells_.rows != h || cells_.cols != w || cells_.u == nullptr || cells_.u->refcount > 1) {
    cells_ = cv::Mat(h, w, CV_8UC1);
  }
  cells_.setTo(0);
  image.cells = cells_;
  if (depth_m.empty()) return image;
  SIGHTLINE_RETURN_IF_ERROR(PrepareTable(depth_m.cols, depth_m.rows));
  occupied_counts_.assign(static_cast<size_t>(w) * h, 0);

  const int sampled_cols = (depth_m.cols + step_ - 1) / step_;
  const int sampled_rows = (depth_m.rows + step_ - 1) / step_;
  const float d = static_cast<float>(floor_.d);
  const float eps = static_cast<float>(floor_.epsilon_m);
  const float max_h = static_cast<float>(options_.max_height_m);
  const float inv_cell = static_cast<float>(1.0 / options_.cell_size_m);
  const float half_w = 0.5f * w;
  const float fh = static_cast<float>(h);
  const uint8_t min_points = static_cast<uint8_t>(options_.min_occupied_points);
  uint8_t* cells = image.cells.ptr<uint8_t>(0);

  // People: mark their pixels (inside the box and near the box's median depth).
  const bool with_people = !people.empty();
  // Index of each mask value's footprint (boxes without depth get none).
  int footprint_of[256];
  std::fill(std::begin(footprint_of), std::end(footprint_of), -1);
  if (with_people) {
    person_mask_.assign(static_cast<size_t>(sampled_cols) * sampled_rows, 0);
    std::vector<float> depths;
    for (size_t k = 0; k < people.size() && k < 255; ++k) {
      const PersonBox& person = people[k];
      const cv::Point2d scale = person.ScaleTo(depth_m.size());
      const double sx = scale.x, sy = scale.y;
      const int u0 = std::max(0, static_cast<int>(std::floor(person.box.x * sx)) / step_);
      const int v0 = std::max(0, static_cast<int>(std::floor(person.box.y * sy)) / step_);
      const int u1 =
          std::min(sampled_cols - 1,
                   static_cast<int>(std::ceil((person.box.x + person.box.width) * sx)) / step_);
      const int v1 =
          std::min(sampled_rows - 1,
                   static_cast<int>(std::ceil((person.box.y + person.box.height) * sy)) / step_);
      if (u1 < u0 || v1 < v0) continue;
      depths.clear();
      for (int sv = v0; sv <= v1; ++sv) {
        const float* row = depth_m.ptr<float>(sv * step_);
        for (int su = u0; su <= u1; ++su) {
          const float z = row[su * step_];
          if (!(z > 0)) continue;
          const float height = z * ray_table_[sv * sampled_cols + su].x() + d;
          if (height > eps && height <= max_h) depths.push_back(z);
        }
      }
      if (depths.empty()) continue;
      std::nth_element(depths.begin(), depths.begin() + depths.size() / 2, depths.end());
      const float median = depths[depths.size() / 2];
      const float margin = static_cast<float>(options_.person_depth_margin_m);
      for (int sv = v0; sv <= v1; ++sv) {
        const float* row = depth_m.ptr<float>(sv * step_);
        for (int su = u0; su <= u1; ++su) {
          const float z = row[su * step_];
          if (z > 0 && std::abs(z - median) < margin) {
            person_mask_[sv * sampled_cols + su] = static_cast<uint8_t>(k + 1);
          }
        }
      }
      footprint_of[k + 1] = static_cast<int>(image.people.size());
      PersonFootprint footprint;
      footprint.id = person.id;
      footprint.range_m = median;
      image.people.push_back(footprint);
    }
  }
  std::vector<cv::Point> person_min(image.people.size(), cv::Point(w, h));
  std::vector<cv::Point> person_max(image.people.size(), cv::Point(-1, -1));

  int invalid = 0, floor_count = 0, occupied = 0, person_count = 0, outside = 0;
  int min_col = w, max_col = -1, min_row = h, max_row = -1;
  for (int sv = 0; sv < sampled_rows; ++sv) {
    const float* row = depth_m.ptr<float>(sv * step_);
    const Eigen::Vector3f* rays = &ray_table_[static_cast<size_t>(sv) * sampled_cols];
    const uint8_t* mask =
        with_people ? &person_mask_[static_cast<size_t>(sv) * sampled_cols] : nullptr;
    for (int su = 0; su < sampled_cols; ++su) {
      const float z = row[su * step_];
      if (!(z > 0)) {
        ++invalid;
        continue;
      }
      const Eigen::Vector3f& r = rays[su];
      const float height = z * r.x() + d;
      const float cf = half_w - z * r.z() * inv_cell;
      const float rf = fh - z * r.y() * inv_cell;
      if (!(cf >= 0 && cf < half_w * 2 && rf >= 0 && rf < fh) || height < -eps || height > max_h) {
        ++outside;
        continue;
      }
      const int column = static_cast<int>(cf), cell_row = static_cast<int>(rf);
      const int index = cell_row * w + column;
      min_col = std::min(min_col, column);
      max_col = std::max(max_col, column);
      min_row = std::min(min_row, cell_row);
      max_row = std::max(max_row, cell_row);
      if (height <= eps) {
        ++floor_count;
        if (cells[index] == 0) cells[index] = static_cast<uint8_t>(OccupancyCell::kFree);
        continue;
      }
      if (mask != nullptr && mask[su] != 0) {
        ++person_count;
        cells[index] = static_cast<uint8_t>(OccupancyCell::kPerson);
        const int f = footprint_of[mask[su]];
        if (f >= 0) {
          person_min[f].x = std::min(person_min[f].x, column);
          person_min[f].y = std::min(person_min[f].y, cell_row);
          person_max[f].x = std::max(person_max[f].x, column);
          person_max[f].y = std::max(person_max[f].y, cell_row);
        }
        continue;
      }
      ++occupied;
      uint8_t& count = occupied_counts_[index];
      if (count < 255) ++count;
      if (count >= min_points && cells[index] != static_cast<uint8_t>(OccupancyCell::kPerson)) {
        cells[index] = static_cast<uint8_t>(OccupancyCell::kOccupied);
      }
    }
  }
  // Keep footprints that landed in the image.
  std::vector<PersonFootprint> kept;
  for (size_t f = 0; f < image.people.size(); ++f) {
    if (person_max[f].x < 0) continue;
    PersonFootprint footprint = image.people[f];
    footprint.cells = cv::Rect(person_min[f], person_max[f] + cv::Point(1, 1));
    kept.push_back(footprint);
  }
  image.people.swap(kept);
  if (max_col >= 0)
    image.known_cells = cv::Rect(min_col, min_row, max_col - min_col + 1, max_row - min_row + 1);
  image.sampled_pixels = sampled_cols * sampled_rows;
  image.invalid_pixels = invalid;
  image.floor_pixels = floor_count;
  image.occupied_pixels = occupied;
  image.person_pixels = person_count;
  image.outside_pixels = outside;
  return image;
}

}  // namespace sightline
