#include "core/mobility/pcl_stages.h"

#include <pcl/features/normal_3d.h>
#include <pcl/filters/statistical_outlier_removal.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>

namespace sightline {
namespace {

pcl::PointCloud<pcl::PointXYZ>::Ptr ToPcl(const std::vector<Eigen::Vector3f>& points) {
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->points.reserve(points.size());
  for (const Eigen::Vector3f& p : points) cloud->points.emplace_back(p.x(), p.y(), p.z());
  cloud->width = static_cast<uint32_t>(cloud->points.size());
  cloud->height = 1;
  cloud->is_dense = true;
  return cloud;
}

}  // namespace

WorkingCloud CloudPoints(const PointCloud& cloud) {
  WorkingCloud out;
  out.points.reserve(cloud.size());
  for (size_t i = 0; i < cloud.size(); ++i) {
    if (!cloud.points[i].allFinite()) continue;
    out.points.push_back(cloud.points[i]);
    out.pixel.push_back(static_cast<int>(i));
  }
  return out;
}

void PclVoxelDownsample(double voxel_m, WorkingCloud* cloud) {
  if (cloud->points.empty()) return;
  pcl::VoxelGrid<pcl::PointXYZ> grid;
  grid.setInputCloud(ToPcl(cloud->points));
  const float leaf = static_cast<float>(voxel_m);
  grid.setLeafSize(leaf, leaf, leaf);
  pcl::PointCloud<pcl::PointXYZ> filtered;
  grid.filter(filtered);
  cloud->points.clear();
  for (const auto& p : filtered.points) cloud->points.emplace_back(p.x, p.y, p.z);
  cloud->pixel.assign(cloud->points.size(), -1);
  cloud->normals.clear();
}

void PclRemoveOutliers(int k, double alpha, WorkingCloud* cloud) {
  if (cloud->points.size() <= static_cast<size_t>(k)) return;
  pcl::StatisticalOutlierRemoval<pcl::PointXYZ> sor;
  sor.setInputCloud(ToPcl(cloud->points));
  sor.setMeanK(k);
  sor.setStddevMulThresh(alpha);
  pcl::Indices kept;
  sor.filter(kept);
  std::vector<uint8_t> keep(cloud->size(), 0);
  for (int i : kept) keep[i] = 1;
  cloud->Compact(keep);
}

struct PclNeighborSearch::Impl {
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
};

PclNeighborSearch::PclNeighborSearch(const std::vector<Eigen::Vector3f>& points)
    : impl_(std::make_unique<Impl>()) {
  impl_->cloud = ToPcl(points);
  if (!points.empty()) impl_->tree.setInputCloud(impl_->cloud);
}

PclNeighborSearch::~PclNeighborSearch() = default;

void PclNeighborSearch::ComputeNormals(int k, double max_curvature, WorkingCloud* cloud) const {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud->normals.assign(cloud->size(), Eigen::Vector3f(nan, nan, nan));
  if (cloud->size() < 3) return;
  pcl::Indices indices;
  std::vector<float> distances;
  Eigen::Vector4f plane;
  float curvature = 0;
  for (size_t i = 0; i < cloud->size(); ++i) {
    if (impl_->tree.nearestKSearch(impl_->cloud->points[i], k, indices, distances) < 3) continue;
    if (!pcl::computePointNormal(*impl_->cloud, indices, plane, curvature)) continue;
    if (curvature > max_curvature) continue;  // An edge or a corner.
    Eigen::Vector3f n = plane.head<3>();
    if (!n.allFinite() || n.squaredNorm() < 1e-12f) continue;
    if (n.dot(cloud->points[i]) > 0) n = -n;
    cloud->normals[i] = n.normalized();
  }
}

void PclNeighborSearch::Radius(int i, double radius_m, std::vector<int>* out) const {
  out->clear();
  pcl::Indices indices;
  std::vector<float> distances;
  impl_->tree.radiusSearch(impl_->cloud->points[i], radius_m, indices, distances);
  for (int j : indices) {
    if (j != i) out->push_back(j);
  }
}

}  // namespace sightline
