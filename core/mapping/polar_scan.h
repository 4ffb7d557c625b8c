// Polar scan (seed 000, section 4.3.3): rays from the robot through the occupancy image, keeping
// the nearest occupied cell of each ray, like a laser scan. People's cells and footprints are
// skipped. The seed casts 180 / 0.2 = 900 rays over 180 deg; a Kinect only sees about 60 deg, so
// rays are cast only inside the field of view (about 300 at 0.2 deg) and the scan says so.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/mapping/mapping_types.h"
#include "core/mapping/occupancy_image.h"
#include "core/options/option_table.h"

namespace sightline {

// Options of the scan. Keys "mapping.scan.*".
struct PolarScanOptions {
  double resolution_deg = 0.2;  // Seed res_scan: angle between rays [deg].
  double fov_deg = 0;           // Field of view to scan [deg]; 0 = the camera's own.
  double min_range_m = 0.3;     // Cells closer to the robot are ignored (robot body) [m].
  double max_range_m = 0;       // Rays stop here [m]; 0 = at the image border.

  bool IsValid(std::string* error) const;
  static OptionTable<PolarScanOptions> Describe();
};

// Casts rays through occupancy images. The cells of every ray are precomputed once per image
// geometry (a table of cell indices), so Scan() is a walk along each ray until the first
// occupied cell.
//
//   PolarScanner scanner(options);
//   SIGHTLINE_RETURN_IF_ERROR(scanner.Configure(width, height, cell, fov_min, fov_max));
//   StatusOr<PolarScan> scan = scanner.Scan(image);
class PolarScanner {
 public:
  explicit PolarScanner(PolarScanOptions options = {});

  // Builds the ray table for images of this size and a camera field of view (bearings, rad).
  Status Configure(int width_cells, int height_cells, double cell_size_m, double fov_min_rad,
                   double fov_max_rad);
  // The scan of one occupancy image of the configured geometry.
  StatusOr<PolarScan> Scan(const OccupancyImage& image) const;

  const PolarScanOptions& options() const { return options_; }
  int rays() const { return static_cast<int>(ray_begin_.empty() ? 0 : ray_begin_.size() - 1); }

 private:
  PolarScanOptions options_;
  int width_ = 0, height_ = 0;
  double cell_size_m_ = 0;
  double fov_min_rad_ = 0, fov_max_rad_ = 0, resolution_rad_ = 0;
  std::vector<double> bearings_;
  std::vector<int> ray_begin_;      // Rays' ranges in ray_cells_ (size rays + 1).
  std::vector<int32_t> ray_cells_;  // Cell indices (row * width + column), near to far.
};

}  // namespace sightline
