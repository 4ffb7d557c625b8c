#include "core/mapping/polar_scan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/mapping/option_check.h"
#include "core/mapping/pose2d.h"

namespace sightline {

using mapping_internal::Invalid;

bool PolarScanOptions::IsValid(std::string* error) const {
  if (!(resolution_deg > 0 && resolution_deg <= 10)) {
    return Invalid(error, "mapping.scan.resolution_deg must lie in (0, 10]");
  }
  if (!(fov_deg >= 0 && fov_deg <= 360))
    return Invalid(error, "mapping.scan.fov_deg must lie in [0, 360]");
  if (!(min_range_m >= 0)) return Invalid(error, "mapping.scan.min_range_m must be >= 0");
  if (!(max_range_m >= 0)) return Invalid(error, "mapping.scan.max_range_m must be >= 0");
  if (max_range_m > 0 && max_range_m <= min_range_m) {
    return Invalid(error, "mapping.scan.max_range_m must exceed min_range_m (or be 0)");
  }
  return true;
}

OptionTable<PolarScanOptions> PolarScanOptions::Describe() {
  using O = PolarScanOptions;
  return OptionTable<O>("mapping.scan")
      .Double("resolution_deg", &O::resolution_deg, "deg", 0.01, 10, 0.05,
              "Angle between scan rays (published res_scan = 0.2 deg).")
      .Double("fov_deg", &O::fov_deg, "deg", 0, 360, 1,
              "Field of view to scan, centred on forward; 0 = the camera's own (rays outside it "
              "can never hit anything).")
      .Double("min_range_m", &O::min_range_m, "m", 0, 10, 0.05,
              "Occupied cells closer than this to the robot are ignored (robot body, noise).")
      .Double("max_range_m", &O::max_range_m, "m", 0, 100, 0.5,
              "Rays stop at this range; 0 = at the occupancy image border.");
}

std::string PolarScan::Describe() const {
  const double full = 180.0;
  const int seed_rays =
      resolution_rad > 0 ? static_cast<int>(std::lround(full / RadToDeg(resolution_rad))) : 0;
  char text[200];
  std::snprintf(text, sizeof(text),
                "%d of %d rays (%.2f deg over %.0f deg) lie in the %.1f deg field of view; %zu hit",
                rays_cast, seed_rays, RadToDeg(resolution_rad), full,
                RadToDeg(fov_max_rad - fov_min_rad), points.size());
  return text;
}

PolarScanner::PolarScanner(PolarScanOptions options) : options_(std::move(options)) {}

Status PolarScanner::Configure(int width_cells, int height_cells, double cell_size_m,
                               double fov_min_rad, double fov_max_rad) {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  if (width_cells < 1 || height_cells < 1 || !(cell_size_m > 0)) {
    return InvalidArgument("polar scan: invalid occupancy image geometry");
  }
  if (options_.fov_deg > 0) {
    const double half = 0.5 * DegToRad(options_.fov_deg);
    fov_min_rad = -half;
    fov_max_rad = half;
  }
  if (!(fov_max_rad > fov_min_rad)) return InvalidArgument("polar scan: empty field of view");
  width_ = width_cells;
  height_ = height_cells;
  cell_size_m_ = cell_size_m;
  resolution_rad_ = DegToRad(options_.resolution_deg);
  // Rays on a grid of the resolution anchored at forward (bearing 0), inside the FOV.
  const int first = static_cast<int>(std::ceil(fov_min_rad / resolution_rad_ - 1e-9));
  const int last = static_cast<int>(std::floor(fov_max_rad / resolution_rad_ + 1e-9));
  fov_min_rad_ = first * resolution_rad_;
  fov_max_rad_ = last * resolution_rad_;
  bearings_.clear();
  ray_begin_.clear();
  ray_cells_.clear();
  // Robot at continuous image position (width / 2, height); a bearing b points to
  // column - sin(b), row - cos(b).
  const double origin_c = 0.5 * width_cells, origin_r = height_cells;
  const double min_range_cells = options_.min_range_m / cell_size_m;
  const double max_range_cells =
      options_.max_range_m > 0 ? options_.max_range_m / cell_size_m : 1e9;
  for (int k = first; k <= last; ++k) {
    const double bearing = k * resolution_rad_;
    bearings_.push_back(bearing);
    ray_begin_.push_back(static_cast<int>(ray_cells_.size()));
    const double dc = -std::sin(bearing), dr = -std::cos(bearing);
    // Grid traversal (Amanatides and Woo) from the robot, visiting each cell once.
    double c = origin_c, r = origin_r - 1e-9;
    int ci = static_cast<int>(std::floor(c)), ri = static_cast<int>(std::floor(r));
    const int step_c = dc > 0 ? 1 : -1, step_r = dr > 0 ? 1 : -1;
    const double t_delta_c = dc != 0 ? std::abs(1.0 / dc) : 1e18;
    const double t_delta_r = dr != 0 ? std::abs(1.0 / dr) : 1e18;
    double t_max_c = dc > 0 ? (ci + 1 - c) / dc : (dc < 0 ? (c - ci) / -dc : 1e18);
    double t_max_r = dr > 0 ? (ri + 1 - r) / dr : (dr < 0 ? (r - ri) / -dr : 1e18);
    while (ci >= 0 && ci < width_cells && ri >= 0 && ri < height_cells) {
      // Range of the cell centre.
      const double ec = ci + 0.5 - origin_c, er = origin_r - (ri + 0.5);
      const double range = std::hypot(ec, er);
      if (range > max_range_cells) break;
      if (range >= min_range_cells) ray_cells_.push_back(ri * width_cells + ci);
      if (t_max_c < t_max_r) {
        t_max_c += t_delta_c;
        ci += step_c;
      } else {
        t_max_r += t_delta_r;
        ri += step_r;
      }
    }
  }
  ray_begin_.push_back(static_cast<int>(ray_cells_.size()));
  return Status::Ok();
}

StatusOr<PolarScan> PolarScanner::Scan(const OccupancyImage& image) const {
  if (ray_begin_.empty()) return FailedPrecondition("polar scan: Configure() was not called");
  if (image.width() != width_ || image.height() != height_ || image.cells.type() != CV_8UC1) {
    return InvalidArgument("polar scan: the occupancy image does not match the configured size");
  }
  PolarScan scan;
  scan.rays_cast = rays();
  scan.fov_min_rad = fov_min_rad_;
  scan.fov_max_rad = fov_max_rad_;
  scan.resolution_rad = resolution_rad_;
  scan.cell_size_m = image.cell_size_m;
  scan.points.reserve(scan.rays_cast);
  const uint8_t* cells = image.cells.ptr<uint8_t>(0);
  const uint8_t occupied = static_cast<uint8_t>(OccupancyCell::kOccupied);
  const uint8_t person = static_cast<uint8_t>(OccupancyCell::kPerson);
  const bool with_people = !image.people.empty();
  for (int k = 0; k < scan.rays_cast; ++k) {
    bool blocked = false;
    for (int i = ray_begin_[k]; i < ray_begin_[k + 1]; ++i) {
      const int32_t index = ray_cells_[i];
      const uint8_t value = cells[index];
      if (value == person) {
        blocked = true;
        continue;
      }
      if (value != occupied) continue;
      const int column = index % width_, row = index / width_;
      if (with_people) {
        bool inside = false;
        for (const PersonFootprint& p : image.people)
          inside = inside || p.cells.contains({column, row});
        if (inside) {
          blocked = true;
          continue;
        }
      }
      ScanPoint point;
      point.ray = k;
      point.bearing_rad = bearings_[k];
      point.cell = cv::Point(column, row);
      point.xy = image.CellCenter(column, row);
      point.range_m = point.xy.norm();
      scan.points.push_back(point);
      break;
    }
    if (blocked) ++scan.rays_blocked_by_people;
  }
  return scan;
}

}  // namespace sightline
