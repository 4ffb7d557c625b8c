#include "core/button/plane_fit.h"

#include <Eigen/Eigenvalues>

namespace sightline {

LeastSquaresPlane FitLeastSquaresPlane(const std::vector<Eigen::Vector3d>& points) {
  LeastSquaresPlane plane;
  for (const auto& p : points) plane.centroid += p;
  plane.centroid /= double(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto& p : points) scatter += (p - plane.centroid) * (p - plane.centroid).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter / double(points.size()));
  plane.normal = solver.eigenvectors().col(0).normalized();
  plane.eigenvalues = solver.eigenvalues().cwiseMax(0.0);
  return plane;
}

}  // namespace sightline
