#include "core/mapping/occupancy_grid_map.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/common/text_file.h"
#include "core/mapping/option_check.h"

namespace sightline {

using mapping_internal::Invalid;

bool OccupancyGridMapOptions::IsValid(std::string* error) const {
  if (!(resolution_m > 0)) return Invalid(error, "mapping.stitch.resolution_m must be positive");
  if (!(hit_log_odds > 0)) return Invalid(error, "mapping.stitch.hit_log_odds must be positive");
  if (!(miss_log_odds < 0)) return Invalid(error, "mapping.stitch.miss_log_odds must be negative");
  if (!(min_log_odds < 0 && max_log_odds > 0)) {
    return Invalid(error, "mapping.stitch.min_log_odds must be < 0 < max_log_odds");
  }
  if (!(free_threshold > 0 && free_threshold < 0.5 && occupied_threshold > 0.5 &&
        occupied_threshold < 1)) {
    return Invalid(error,
                   "mapping.stitch thresholds: need 0 < free_threshold < 0.5 < "
                   "occupied_threshold < 1");
  }
  if (!(grow_margin_m >= 0)) return Invalid(error, "mapping.stitch.grow_margin_m must be >= 0");
  if (render_every_n < 0) return Invalid(error, "mapping.stitch.render_every_n must be >= 0");
  if (occupied_from != "scan" && occupied_from != "image") {
    return Invalid(error, "mapping.stitch.occupied_from must be scan or image");
  }
  return true;
}

OptionTable<OccupancyGridMapOptions> OccupancyGridMapOptions::Describe() {
  using O = OccupancyGridMapOptions;
  return OptionTable<O>("mapping.stitch")
      .Double("resolution_m", &O::resolution_m, "m", 0.005, 1, 0.01, "Cell edge of the global map.")
      .Double("hit_log_odds", &O::hit_log_odds, "", 0.01, 10, 0.05,
              "Log-odds added when a frame sees a cell occupied.")
      .Double("miss_log_odds", &O::miss_log_odds, "", -10, -0.01, 0.05,
              "Log-odds added when a frame sees a cell free.")
      .Double("min_log_odds", &O::min_log_odds, "", -50, -0.01, 0.1,
              "Lower clamp of a cell's log-odds.")
      .Double("max_log_odds", &O::max_log_odds, "", 0.01, 50, 0.1,
              "Upper clamp of a cell's log-odds.")
      .Double("occupied_threshold", &O::occupied_threshold, "", 0.51, 0.99, 0.01,
              "Probability above which a cell is occupied (map.yaml occupied_thresh).")
      .Double("free_threshold", &O::free_threshold, "", 0.01, 0.49, 0.01,
              "Probability below which a cell is free (map.yaml free_thresh).")
      .Bool("clear_on_reset", &O::clear_on_reset,
            "Start a new map when the reset rule fires (as published); off keeps stitching.")
      .Choice(
          "occupied_from", &O::occupied_from, {"scan", "image"},
          "Occupied evidence: the polar scan's hits (visible surfaces, thin walls) or every "
          "occupied cell of the occupancy image (as published; depth noise behind walls stays).")
      .Double("grow_margin_m", &O::grow_margin_m, "m", 0, 100, 0.5,
              "The map grows by at least this much each time it must.")
      .Int("render_every_n", &O::render_every_n, "frames", 0, 100000, 1,
           "Frame results carry a rendered map image every n frames (0 = never).");
}

OccupancyGridMap::OccupancyGridMap(OccupancyGridMapOptions options)
    : options_(std::move(options)) {}

void OccupancyGridMap::Clear() {
  log_odds_.release();
  stamps_.release();
  observed_.release();
  origin_ = Eigen::Vector2d::Zero();
  frames_ = 0;
}

Eigen::Vector2i OccupancyGridMap::CellOf(const Eigen::Vector2d& p_in_world) const {
  return {static_cast<int>(std::floor((p_in_world.x() - origin_.x()) / options_.resolution_m)),
          static_cast<int>(std::floor((p_in_world.y() - origin_.y()) / options_.resolution_m))};
}

Eigen::Vector2d OccupancyGridMap::CellCenter(int ix, int iy) const {
  return origin_ + options_.resolution_m * Eigen::Vector2d(ix + 0.5, iy + 0.5);
}

double OccupancyGridMap::Probability(float log_odds) {
  return 1.0 - 1.0 / (1.0 + std::exp(static_cast<double>(log_odds)));
}

bool OccupancyGridMap::IsKnown(int ix, int iy) const {
  return ix >= 0 && iy >= 0 && ix < width() && iy < height() && observed_.at<uint8_t>(iy, ix) != 0;
}

bool OccupancyGridMap::IsOccupied(int ix, int iy) const {
  return IsKnown(ix, iy) && Probability(log_odds_.at<float>(iy, ix)) > options_.occupied_threshold;
}

bool OccupancyGridMap::IsFree(int ix, int iy) const {
  return IsKnown(ix, iy) && Probability(log_odds_.at<float>(iy, ix)) < options_.free_threshold;
}

void OccupancyGridMap::Cover(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
  const double res = options_.resolution_m;
  if (!log_odds_.empty()) {
    const Eigen::Vector2i a = CellOf(lo), b = CellOf(hi);
    if (a.x() >= 0 && a.y() >= 0 && b.x() < width() && b.y() < height()) return;
  }
  Eigen::Vector2d new_lo = lo.array() - options_.grow_margin_m;
  Eigen::Vector2d new_hi = hi.array() + options_.grow_margin_m;
  if (!log_odds_.empty()) {
    const Eigen::Vector2d old_hi = origin_ + res * Eigen::Vector2d(width(), height());
    new_lo = new_lo.cwiseMin(origin_);
    new_hi = new_hi.cwiseMax(old_hi);
  }
  // Keep cell boundaries on multiples of the resolution, so old cells map one to one.
  const Eigen::Vector2d new_origin((std::floor(new_lo.x() / res)) * res,
                                   (std::floor(new_lo.y() / res)) * res);
  const int new_w = static_cast<int>(std::ceil((new_hi.x() - new_origin.x()) / res)) + 1;
  const int new_h = static_cast<int>(std::ceil((new_hi.y() - new_origin.y()) / res)) + 1;
  cv::Mat log_odds(new_h, new_w, CV_32FC1, cv::Scalar(0));
  cv::Mat stamps(new_h, new_w, CV_32SC1, cv::Scalar(0));
  cv::Mat observed(new_h, new_w, CV_8UC1, cv::Scalar(0));
  if (!log_odds_.empty()) {
    const int dx = static_cast<int>(std::lround((origin_.x() - new_origin.x()) / res));
    const int dy = static_cast<int>(std::lround((origin_.y() - new_origin.y()) / res));
    const cv::Rect where(dx, dy, width(), height());
    log_odds_.copyTo(log_odds(where));
    stamps_.copyTo(stamps(where));
    observed_.copyTo(observed(where));
  }
  log_odds_ = log_odds;
  stamps_ = stamps;
  observed_ = observed;
  origin_ = new_origin;
}

Status OccupancyGridMap::Insert(const OccupancyImage& image, const Pose2d& world_from_base,
                                const PolarScan* surface) {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  if (image.cells.empty() || image.cells.type() != CV_8UC1) {
    return InvalidArgument("map stitching: the occupancy image is empty or not CV_8UC1");
  }
  ++frames_;
  const cv::Rect known = image.known_cells & cv::Rect(0, 0, image.width(), image.height());
  if (known.empty()) return Status::Ok();
  const double s = image.cell_size_m;
  const int w = image.width(), h = image.height();
  // Base-frame box of the known cells, then its world bounding box.
  const double x_lo = (h - known.y - known.height) * s, x_hi = (h - known.y) * s;
  const double y_lo = (0.5 * w - known.x - known.width) * s, y_hi = (0.5 * w - known.x) * s;
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const Eigen::Vector2d& corner : {Eigen::Vector2d(x_lo, y_lo), Eigen::Vector2d(x_lo, y_hi),
                                        Eigen::Vector2d(x_hi, y_lo), Eigen::Vector2d(x_hi, y_hi)}) {
    const Eigen::Vector2d p = world_from_base.Apply(corner);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  Cover(lo, hi);
  ++stamp_;
  const float hit = static_cast<float>(options_.hit_log_odds);
  const float miss = static_cast<float>(options_.miss_log_odds);
  const float l_min = static_cast<float>(options_.min_log_odds);
  const float l_max = static_cast<float>(options_.max_log_odds);
  const double res = options_.resolution_m;
  const double c = std::cos(world_from_base.heading_rad),
               sn = std::sin(world_from_base.heading_rad);
  const int map_w = width(), map_h = height();

  // Occupied evidence, forward-mapped: base (x, y) of local (col, row) is
  // ((h - row - 0.5) s, (w/2 - col - 0.5) s); world = t + R (x, y).
  auto add_hit = [&](int col, int row) {
    const double bx = (h - row - 0.5) * s, by = (0.5 * w - col - 0.5) * s;
    const double wx = world_from_base.x + c * bx - sn * by;
    const double wy = world_from_base.y + sn * bx + c * by;
    const int ix = static_cast<int>(std::floor((wx - origin_.x()) / res));
    const int iy = static_cast<int>(std::floor((wy - origin_.y()) / res));
    if (ix < 0 || iy < 0 || ix >= map_w || iy >= map_h) return;
    int32_t& stamp = stamps_.at<int32_t>(iy, ix);
    if (stamp == stamp_) return;
    stamp = stamp_;
    float& l = log_odds_.at<float>(iy, ix);
    l = std::min(l_max, l + hit);
    observed_.at<uint8_t>(iy, ix) = 1;
  };
  if (options_.occupied_from == "scan" && surface != nullptr) {
    for (const ScanPoint& p : surface->points) add_hit(p.cell.x, p.cell.y);
  } else {
    const uint8_t occupied = static_cast<uint8_t>(OccupancyCell::kOccupied);
    for (int row = known.y; row < known.y + known.height; ++row) {
      const uint8_t* cells = image.cells.ptr<uint8_t>(row);
      for (int col = known.x; col < known.x + known.width; ++col) {
        if (cells[col] == occupied) add_hit(col, row);
      }
    }
  }
  // Free cells, sampled at each global cell's centre: local column = w/2 - by / s,
  // row = h - bx / s, with (bx, by) = R^T (world - t).
  const Eigen::Vector2i a = CellOf(lo), b = CellOf(hi);
  const uint8_t free = static_cast<uint8_t>(OccupancyCell::kFree);
  const double inv_s = 1.0 / s;
  for (int iy = std::max(0, a.y()); iy <= std::min(map_h - 1, b.y()); ++iy) {
    float* l_row = log_odds_.ptr<float>(iy);
    const int32_t* stamp_row = stamps_.ptr<int32_t>(iy);
    uint8_t* observed_row = observed_.ptr<uint8_t>(iy);
    const double wy = origin_.y() + (iy + 0.5) * res - world_from_base.y;
    for (int ix = std::max(0, a.x()); ix <= std::min(map_w - 1, b.x()); ++ix) {
      if (stamp_row[ix] == stamp_) continue;
      const double wx = origin_.x() + (ix + 0.5) * res - world_from_base.x;
      const double bx = c * wx + sn * wy, by = -sn * wx + c * wy;
      const double colf = 0.5 * w - by * inv_s, rowf = h - bx * inv_s;
      if (!(colf >= known.x && colf < known.x + known.width && rowf >= known.y &&
            rowf < known.y + known.height)) {
        continue;
      }
      if (image.cells.at<uint8_t>(static_cast<int>(rowf), static_cast<int>(colf)) != free) continue;
      l_row[ix] = std::max(l_min, l_row[ix] + miss);
      observed_row[ix] = 1;
    }
  }
  return Status::Ok();
}

cv::Mat OccupancyGridMap::RenderGray() const {
  if (log_odds_.empty()) return cv::Mat();
  cv::Mat gray(height(), width(), CV_8UC1, cv::Scalar(205));
  for (int iy = 0; iy < height(); ++iy) {
    uint8_t* out = gray.ptr<uint8_t>(height() - 1 - iy);
    for (int ix = 0; ix < width(); ++ix) {
      if (IsOccupied(ix, iy))
        out[ix] = 0;
      else if (IsFree(ix, iy))
        out[ix] = 254;
    }
  }
  return gray;
}

cv::Mat OccupancyGridMap::RenderBgr(const std::vector<Pose2d>& trajectory) const {
  cv::Mat gray = RenderGray();
  if (gray.empty()) return gray;
  cv::Mat bgr;
  cv::cvtColor(gray, bgr, cv::COLOR_GRAY2BGR);
  std::vector<cv::Point> points;
  for (const Pose2d& pose : trajectory) {
    const Eigen::Vector2i cell = CellOf(pose.position());
    points.emplace_back(cell.x(), height() - 1 - cell.y());
  }
  if (points.size() >= 2) {
    cv::polylines(bgr, points, false, cv::Scalar(0, 0, 220), 1, cv::LINE_AA);
  }
  if (!points.empty()) cv::circle(bgr, points.back(), 3, cv::Scalar(0, 0, 255), cv::FILLED);
  return bgr;
}

Status OccupancyGridMap::SaveRos(const std::string& dir, const std::string& name) const {
  if (log_odds_.empty())
    return FailedPrecondition("map stitching: the map is empty, nothing to save");
  const cv::Mat gray = RenderGray();
  const std::string pgm_path = JoinPath(dir, name + ".pgm");
  {
    std::ofstream pgm(pgm_path, std::ios::binary);
    if (!pgm) return NotFound("cannot write " + pgm_path);
    pgm << "P5\n# Sightline occupancy map, " << options_.resolution_m << " m/cell\n"
        << gray.cols << " " << gray.rows << "\n255\n";
    for (int r = 0; r < gray.rows; ++r) {
      pgm.write(reinterpret_cast<const char*>(gray.ptr<uint8_t>(r)), gray.cols);
    }
    if (!pgm) return Unavailable("write to " + pgm_path + " failed (disk full?)");
  }
  const std::string yaml_path = JoinPath(dir, name + ".yaml");
  std::ofstream yaml(yaml_path);
  if (!yaml) return NotFound("cannot write " + yaml_path);
  char text[512];
  std::snprintf(text, sizeof(text),
                "image: %s.pgm\nresolution: %.6f\norigin: [%.6f, %.6f, 0.0]\nnegate: 0\n"
                "occupied_thresh: %.3f\nfree_thresh: %.3f\n",
                name.c_str(), options_.resolution_m, origin_.x(), origin_.y(),
                options_.occupied_threshold, options_.free_threshold);
  yaml << text;
  yaml.flush();
  if (!yaml) return Unavailable("write to " + yaml_path + " failed (disk full?)");
  return Status::Ok();
}

Status OccupancyGridMap::SavePng(const std::string& path,
                                 const std::vector<Pose2d>& trajectory) const {
  if (log_odds_.empty())
    return FailedPrecondition("map stitching: the map is empty, nothing to save");
  const cv::Mat bgr = RenderBgr(trajectory);
  bool written = false;
  try {
    written = cv::imwrite(path, bgr);
  } catch (const cv::Exception& e) {
    return Unavailable("cannot write " + path + ": " + e.what());
  }
  if (!written) return Unavailable("cannot write " + path);
  return Status::Ok();
}

}  // namespace sightline
