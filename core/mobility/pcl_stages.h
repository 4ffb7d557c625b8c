// The seed's unorganized per-point stages on PCL (mode "pcl"): voxel grid, statistical outlier
// removal, k-d tree normals and the k-d tree neighbours of the region growing. PCL stays inside
// pcl_stages.cpp.
#pragma once

#include <memory>
#include <vector>

#include "core/common/frame.h"
#include "core/mobility/mobility_types.h"

namespace sightline {

// The finite points of a cloud (any layout) with their input indices.
WorkingCloud CloudPoints(const PointCloud& cloud);

// pcl::VoxelGrid: one centroid per occupied voxel (input indices are lost: pixel = -1).
void PclVoxelDownsample(double voxel_m, WorkingCloud* cloud);

// pcl::StatisticalOutlierRemoval with k neighbours and factor alpha (seed eq. 1).
void PclRemoveOutliers(int k, double alpha, WorkingCloud* cloud);

// A k-d tree over a cloud's points, built once and reused by the normals and the region growing.
class PclNeighborSearch {
 public:
  explicit PclNeighborSearch(const std::vector<Eigen::Vector3f>& points);
  ~PclNeighborSearch();
  PclNeighborSearch(const PclNeighborSearch&) = delete;
  PclNeighborSearch& operator=(const PclNeighborSearch&) = delete;

  // Normals by PCA of the k nearest neighbours (seed eqs. 2-3), oriented towards the origin.
  // Points whose surface variation exceeds max_curvature get none.
  void ComputeNormals(int k, double max_curvature, WorkingCloud* cloud) const;
  // Indices of the points within radius_m of point i (i itself excluded).
  void Radius(int i, double radius_m, std::vector<int>* out) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sightline
