// The ground: not the largest plane, but the lowest large plane whose normal lies near the
// expected up direction (from a floor calibration, gravity or the camera's mounting).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/common/status.h"
#include "core/mobility/mobility_options.h"
#include "core/mobility/mobility_types.h"

namespace sightline {

// Published eq. 6: iterations k = log(1 - p) / log(1 - w^s) for success probability p, inlier ratio
// w and sample size s.
int RansacIterations(double success, double inlier_ratio, int sample_size = 3);

// The camera's up direction in the camera frame (x right, y down, z forward) for a camera
// pitched down by pitch_deg and rolled by roll_deg: -y for a level camera.
Eigen::Vector3d ExpectedUpFromMount(double pitch_deg, double roll_deg);

// Searches up to options.ground_candidates planes whose normals lie within up_tolerance_deg of
// `up` (RANSAC with eq. 6's iterations on points whose own normals could be ground, then a
// least-squares refit), keeps those holding at least min_ground_ratio of the points and the
// camera above them, and returns the lowest. is_ground[i] marks its points (distance and own
// normal within tolerance). NotFound, saying what was seen, when no plane qualifies.
StatusOr<GroundPlane> FindGround(const WorkingCloud& cloud, const Eigen::Vector3d& up,
                                 const MobilityOptions& options, std::vector<uint8_t>* is_ground,
                                 int* iterations = nullptr);

// Running sums for a least-squares plane, in double about the first point added (far points
// keep their spread). No per-point storage.
struct PlaneSums {
  int count = 0;
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();
  double sx = 0, sy = 0, sz = 0;                                // Sums of q = p - reference.
  double sxx = 0, sxy = 0, sxz = 0, syy = 0, syz = 0, szz = 0;  // Sums of q q^T.

  void Add(const Eigen::Vector3f& p) {
    if (count == 0) reference = p.cast<double>();
    const double x = p.x() - reference.x(), y = p.y() - reference.y(), z = p.z() - reference.z();
    ++count;
    sx += x, sy += y, sz += z;
    sxx += x * x, sxy += x * y, sxz += x * z, syy += y * y, syz += y * z, szz += z * z;
  }
  // Unit normal (smallest scatter direction) and centroid. False for < 3 points or a
  // degenerate set.
  bool Fit(Eigen::Vector3d* normal, Eigen::Vector3d* centroid) const;
};

// Least-squares plane (PCA) of points: unit normal and centroid. False for < 3 points or a
// degenerate set.
bool FitPlaneLeastSquares(const std::vector<Eigen::Vector3f>& points, Eigen::Vector3d* normal,
                          Eigen::Vector3d* centroid);

}  // namespace sightline
