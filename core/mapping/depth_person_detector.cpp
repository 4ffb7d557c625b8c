#include "core/mapping/depth_person_detector.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace sightline {

namespace {
constexpr double kRangeMarginM = 1.0;
constexpr double kShoulders = 0.5;  // Shoulders reach this many head radii from the head.
constexpr int kJoin = 1;            // Cells up to this many apart join a cluster (8-neighbours).
}  // namespace

DepthPersonDetector::DepthPersonDetector(PersonDetectorOptions options)
    : options_(std::move(options)) {}

Status DepthPersonDetector::Configure(const FloorPlane& floor, const PinholeCamera& camera) {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  if (!floor.IsValid(&error)) return InvalidArgument(error);
  if (!(camera.fx > 0 && camera.fy > 0 && camera.width > 0 && camera.height > 0)) {
    return InvalidArgument("depth person detector: the depth camera has no valid intrinsics");
  }
  Eigen::Matrix3d base_from_camera;
  if (!floor.BaseFromCameraRotation(&base_from_camera)) {
    return InvalidArgument(
        "depth person detector: the camera looks (almost) straight at the floor");
  }
  forward_ = base_from_camera.row(0).transpose();
  left_ = base_from_camera.row(1).transpose();
  up_ = base_from_camera.row(2).transpose();
  floor_ = floor;
  camera_ = camera;
  const double range = options_.depth_max_range_m + kRangeMarginM;
  grid_rows_ = static_cast<int>(std::ceil(range / options_.depth_cell_m)) + 1;
  grid_cols_ = 2 * grid_rows_;
  cells_.assign(static_cast<size_t>(grid_rows_) * grid_cols_, Cell());
  used_.clear();
  label_.assign(cells_.size(), -1);
  configured_ = true;
  return Status::Ok();
}

namespace {

// A cluster's cells and what a person test needs of them.
struct Part {
  std::vector<int> cells;
  int points = 0;
  float top = -1e9f, bottom = 1e9f;
  double length_m = 0, width_m = 0;  // Footprint along its principal axes.
  double range_m = 0;                // Of its footprint's centre from the camera.
  Eigen::Vector2d centre{0, 0};      // Footprint's centre (forward, left) [m].
  cv::Rect box;
};

}  // namespace

cv::Rect2d DepthPersonDetector::BodyBox(const PinholeCamera& cam, const Eigen::Vector2d& centre,
                                        double height_m, const cv::Rect2d& box) const {
  // The footprint's centre on the floor and the head above it, in the camera's frame.
  const Eigen::Vector3d feet = centre.x() * forward_ + centre.y() * left_ - floor_.d * up_;
  const Eigen::Vector3d head = feet + height_m * up_;
  if (!(feet.z() > 0.05 && head.z() > 0.05)) return {};
  const double v_feet = cam.fy * feet.y() / feet.z() + cam.cy;
  const double v_head = cam.fy * head.y() / head.z() + cam.cy;
  // Only a body wholly in view: HOG on rows padded beyond the image's edge scores worse than on
  // the part in view.
  if (!(v_head >= 0 && v_feet <= cam.height && v_feet > v_head)) return {};
  return cv::Rect2d(box.x, v_head, box.width, v_feet - v_head);
}

StatusOr<std::vector<PersonBox>> DepthPersonDetector::Detect(const cv::Mat& depth_m) {
  if (!configured_) return FailedPrecondition("depth person detector: Configure() was not called");
  std::vector<PersonBox> people;
  if (depth_m.empty()) return people;
  if (depth_m.type() != CV_32FC1) {
    return InvalidArgument("depth person detector: depth must be CV_32FC1 metres");
  }
  const PinholeCamera cam = (camera_.width == depth_m.cols && camera_.height == depth_m.rows)
                                ? camera_
                                : camera_.Scaled(depth_m.cols, depth_m.rows);
  const PersonDetectorOptions& o = options_;
  const int step = std::max(
      1, static_cast<int>(std::lround(static_cast<double>(depth_m.cols) / o.depth_target_columns)));
  const double cell = o.depth_cell_m;
  const float floor_band = static_cast<float>(std::max(2 * floor_.epsilon_m, 0.05));
  // Clusters are made of points up to a metre beyond the range, so that a wall there is not cut
  // into person-sized slices by the range noise; only clusters within the range are tested.
  const double range_cut = o.depth_max_range_m + kRangeMarginM;
  for (int i : used_) cells_[i] = Cell();  // Only the last frame's cells hold points.
  used_.clear();
  std::vector<int>& used = used_;

  // 1. Points into the floor grid.
  for (int v = 0; v < depth_m.rows; v += step) {
    const float* row = depth_m.ptr<float>(v);
    const double ry = (v - cam.cy) / cam.fy;
    for (int u = 0; u < depth_m.cols; u += step) {
      const float z = row[u];
      if (!(z > 0) || z > range_cut) continue;
      const Eigen::Vector3d x(z * (u - cam.cx) / cam.fx, z * ry, z);
      const float h = static_cast<float>(up_.dot(x) + floor_.d);
      if (h < floor_band) continue;
      const double f = forward_.dot(x), l = left_.dot(x);
      const int r = static_cast<int>(f / cell),
                c = static_cast<int>(std::floor(l / cell)) + grid_rows_;
      if (r < 0 || r >= grid_rows_ || c < 0 || c >= grid_cols_) continue;
      const int i = r * grid_cols_ + c;
      Cell& k = cells_[i];
      if (k.points == 0) used.push_back(i);
      ++k.points;
      k.top = std::max(k.top, h);
      k.bottom = std::min(k.bottom, h);
      k.u0 = std::min(k.u0, u), k.v0 = std::min(k.v0, v);
      k.u1 = std::max(k.u1, u), k.v1 = std::max(k.v1, v);
    }
  }

  // 2. Clusters of cells at most kJoin cells apart.
  for (int i : used) label_[i] = -1;
  std::vector<std::vector<int>> clusters;
  std::vector<int> stack;
  for (int seed : used) {
    if (label_[seed] >= 0) continue;
    const int id = static_cast<int>(clusters.size());
    clusters.emplace_back();
    label_[seed] = id;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      clusters[id].push_back(i);
      const int r = i / grid_cols_, c = i % grid_cols_;
      for (int dr = -kJoin; dr <= kJoin; ++dr) {
        for (int dc = -kJoin; dc <= kJoin; ++dc) {
          const int rr = r + dr, cc = c + dc;
          if (rr < 0 || rr >= grid_rows_ || cc < 0 || cc >= grid_cols_) continue;
          const int j = rr * grid_cols_ + cc;
          if (cells_[j].points == 0 || label_[j] >= 0) continue;
          label_[j] = id;
          stack.push_back(j);
        }
      }
    }
  }

  auto centre = [&](int i) {
    return Eigen::Vector2d((i / grid_cols_ + 0.5) * cell,
                           (i % grid_cols_ - grid_rows_ + 0.5) * cell);
  };
  auto measure = [&](std::vector<int> members) {
    Part p;
    p.cells = std::move(members);
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    int u0 = 1 << 30, v0 = 1 << 30, u1 = -1, v1 = -1;
    for (int i : p.cells) {
      const Cell& k = cells_[i];
      p.points += k.points;
      p.top = std::max(p.top, k.top);
      p.bottom = std::min(p.bottom, k.bottom);
      u0 = std::min(u0, k.u0), v0 = std::min(v0, k.v0);
      u1 = std::max(u1, k.u1), v1 = std::max(v1, k.v1);
      mean += centre(i);
    }
    mean /= static_cast<double>(p.cells.size());
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (int i : p.cells) {
      const Eigen::Vector2d d = centre(i) - mean;
      cov += d * d.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
    const Eigen::Vector2d major = eig.eigenvectors().col(1), minor = eig.eigenvectors().col(0);
    double a0 = 1e9, a1 = -1e9, b0 = 1e9, b1 = -1e9;
    for (int i : p.cells) {
      const Eigen::Vector2d d = centre(i) - mean;
      a0 = std::min(a0, d.dot(major)), a1 = std::max(a1, d.dot(major));
      b0 = std::min(b0, d.dot(minor)), b1 = std::max(b1, d.dot(minor));
    }
    p.length_m = a1 - a0 + cell;
    p.range_m = mean.norm();
    p.centre = mean;
    p.width_m = b1 - b0 + cell;
    p.box = cv::Rect(u0, v0, u1 - u0 + step, v1 - v0 + step);
    return p;
  };
  auto is_person = [&](const Part& p) {
    if (o.depth_require_top && p.box.y < step) return false;  // Its top is out of view.
    return p.range_m <= o.depth_max_range_m && p.points >= o.depth_min_points &&
           p.top >= o.depth_min_height_m && p.top <= o.depth_max_height_m &&
           (p.bottom <= o.depth_max_foot_m || p.box.br().y >= depth_m.rows - step) &&
           p.length_m >= o.depth_min_width_m && p.length_m <= o.depth_max_width_m &&
           p.width_m >= o.depth_min_thickness_m &&
           p.top >= o.depth_min_height_to_length * p.length_m;
  };

  for (std::vector<int>& members : clusters) {
    Part whole = measure(std::move(members));
    std::vector<Part> parts;
    if (whole.length_m <= o.depth_max_width_m || whole.top > o.depth_max_height_m ||
        whole.length_m > 4 * o.depth_max_width_m) {
      parts.push_back(std::move(whole));
    } else {
      // 3. Heads: cells at least min height whose top is the highest within the head radius,
      // and between any two of them a dip of depth_head_drop_m (a neck, shoulders or the gap
      // between two people; the cut-off top of a wall is flat).
      std::vector<int> peaks;
      for (int i : whole.cells) {
        const float top = cells_[i].top;
        if (top < o.depth_min_height_m) continue;
        bool highest = true;
        for (int j : whole.cells) {
          if (j == i || (centre(j) - centre(i)).norm() > o.depth_head_radius_m) continue;
          if (cells_[j].top > top || (cells_[j].top == top && j < i)) highest = false;
          if (!highest) break;
        }
        if (highest) peaks.push_back(i);
      }
      std::sort(peaks.begin(), peaks.end(),
                [&](int a, int b) { return cells_[a].top > cells_[b].top; });
      std::vector<int> heads;
      for (int i : peaks) {
        bool apart = true;
        for (int h : heads) {
          // Between the two heads (beyond the shoulders of each) every top within a cell of the
          // path lies depth_head_drop_m below the lower head.
          const Eigen::Vector2d a = centre(i), b = centre(h);
          const double limit = std::min(cells_[i].top, cells_[h].top) - o.depth_head_drop_m;
          for (int j : whole.cells) {
            const Eigen::Vector2d p = centre(j);
            const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
            if ((p - (a + t * (b - a))).norm() > cell) continue;
            if (cells_[j].top > limit && (p - a).norm() > kShoulders * o.depth_head_radius_m &&
                (p - b).norm() > kShoulders * o.depth_head_radius_m) {
              apart = false;
              break;
            }
          }
          if (!apart) break;
        }
        if (apart) heads.push_back(i);
      }

      // One head standing above everything between one and two head radii around it (a
      // person beside a bin, a box or a wall): the cells within half a person's width of it.
      bool alone = heads.size() == 1;
      if (alone) {
        const Eigen::Vector2d h = centre(heads[0]);
        const double limit = cells_[heads[0]].top - o.depth_head_drop_m;
        for (int j : whole.cells) {
          const double d = (centre(j) - h).norm();
          if (d > o.depth_head_radius_m && d <= 2 * o.depth_head_radius_m &&
              cells_[j].top > limit) {
            alone = false;
            break;
          }
        }
      }
      if (alone) {
        std::vector<int> near;
        for (int j : whole.cells) {
          if ((centre(j) - centre(heads[0])).norm() <= 0.5 * o.depth_max_width_m) near.push_back(j);
        }
        parts.push_back(measure(std::move(near)));
      } else if (heads.size() < 2) {
        parts.push_back(std::move(whole));
      } else {
        std::vector<std::vector<int>> split(heads.size());
        for (int i : whole.cells) {
          size_t best = 0;
          for (size_t h = 1; h < heads.size(); ++h) {
            if ((centre(i) - centre(heads[h])).squaredNorm() <
                (centre(i) - centre(heads[best])).squaredNorm()) {
              best = h;
            }
          }
          split[best].push_back(i);
        }
        for (std::vector<int>& s : split) parts.push_back(measure(std::move(s)));
      }
    }
    // 4.-5. The person test and the box.
    for (const Part& p : parts) {
      if (!is_person(p)) continue;
      PersonBox person;
      person.box = cv::Rect2d(p.box) & cv::Rect2d(0, 0, depth_m.cols, depth_m.rows);
      person.image_size = depth_m.size();
      person.score = 1;
      if (p.box.y >= step) person.body = BodyBox(cam, p.centre, p.top, person.box);
      people.push_back(person);
    }
  }
  return people;
}

}  // namespace sightline
