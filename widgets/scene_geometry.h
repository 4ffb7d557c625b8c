// Internal to SceneView: turns clouds and line segments into VTK poly data in bulk (no per-point
// VTK calls), and generates the segments of frusta, axis triads and grids. Not a public header.
#pragma once

#include <vtkSmartPointer.h>

#include <Eigen/Geometry>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "widgets/color_map.h"

class vtkImageData;
class vtkPolyData;

namespace sightline {

struct PointCloud;

// A line segment with its colour.
struct ColoredSegment {
  Eigen::Vector3d a;
  Eigen::Vector3d b;
  Rgb8 color;
};

// How cloud points are coloured: their own RGB, or turbo over the scalar axis.dot(point).
struct CloudColoring {
  bool use_rgb = false;                                    // Needs cloud.has_colors().
  Eigen::Vector3f scalar_axis = Eigen::Vector3f::UnitZ();  // Unit vector.
};

// One vertex cell per finite point, with RGB point scalars. The scalar colour range spans the
// 2nd to 98th percentile, so a few far outliers do not wash out the colours.
vtkSmartPointer<vtkPolyData> MakeCloudPolyData(const PointCloud& cloud,
                                               const CloudColoring& coloring);

// One line cell per segment, with RGB cell scalars.
vtkSmartPointer<vtkPolyData> MakeSegmentsPolyData(const std::vector<ColoredSegment>& segments);

// The 8 edges of a frustum plus an "up" triangle over the image's top edge (optical frame:
// z forward, y down), scaled so the image plane lies `depth_m` ahead of the apex.
void AppendFrustum(const Eigen::Isometry3d& world_from_camera, double depth_m, Rgb8 color,
                   std::vector<ColoredSegment>* segments);

// Three axes of length `length_m`; x red, y green, z blue unless `single_color` is given.
void AppendAxes(const Eigen::Isometry3d& world_from_frame, double length_m,
                const Rgb8* single_color, std::vector<ColoredSegment>* segments);

// A square grid of 2 * half_cells cells per side centred on `center`, in the plane spanned by
// the unit vectors `u` and `v`.
void AppendGrid(const Eigen::Vector3d& center, const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                double spacing_m, int half_cells, Rgb8 color,
                std::vector<ColoredSegment>* segments);

// A texture's texels from a BGR (CV_8UC3) or grey (CV_8UC1) image as RGB, flipped so that the
// image's bottom row is the texture's first (VTK's origin is bottom-left). Other types give a
// 1 x 1 grey texel.
vtkSmartPointer<vtkImageData> MakeTextureImage(const cv::Mat& image);

// One quad with corners origin, origin + right, origin + right + up, origin + up and texture
// coordinates (0, 0), (1, 0), (1, 1), (0, 1).
vtkSmartPointer<vtkPolyData> MakeTexturedQuad(const Eigen::Vector3d& origin,
                                              const Eigen::Vector3d& right,
                                              const Eigen::Vector3d& up);

}  // namespace sightline
