// Least-squares plane through 3D points, shared by the button locator and the panel normal.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace sightline {

// The plane through the centroid along the points' two principal directions.
struct LeastSquaresPlane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // Unit (sign arbitrary).
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d eigenvalues = Eigen::Vector3d::Zero();   // Of the covariance, ascending, >= 0.
  double offset() const { return -normal.dot(centroid); }  // normal . x + offset = 0.
};

// Needs at least one point; with fewer than three the normal is arbitrary.
LeastSquaresPlane FitLeastSquaresPlane(const std::vector<Eigen::Vector3d>& points);

}  // namespace sightline
