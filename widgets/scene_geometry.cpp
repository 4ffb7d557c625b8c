#include "widgets/scene_geometry.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "core/common/frame.h"

namespace sightline {
namespace {

// Indices 0..count-1 as fixed-size cells of `cell_size` points each.
vtkSmartPointer<vtkCellArray> SequentialCells(vtkIdType count, vtkIdType cell_size) {
  vtkNew<vtkTypeInt32Array> connectivity;
  connectivity->SetNumberOfValues(count);
  int32_t* ids = connectivity->GetPointer(0);
  std::iota(ids, ids + count, 0);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(cell_size, connectivity);
  return cells;
}

// The [2%, 98%] range of the scalar over a sample of at most 20000 points. The sample is
// pseudo-random with a fixed seed: a regular stride can alias with interleaved clouds (e.g. two
// merged scans) and see only one of them.
std::pair<float, float> RobustRange(const PointCloud& cloud, const Eigen::Vector3f& axis) {
  constexpr size_t kMaxSamples = 20000;
  std::vector<float> values;
  const auto take = [&](size_t i) {
    const Eigen::Vector3f& p = cloud.points[i];
    if (p.allFinite()) values.push_back(axis.dot(p));
  };
  if (cloud.size() <= kMaxSamples) {
    values.reserve(cloud.size());
    for (size_t i = 0; i < cloud.size(); ++i) take(i);
  } else {
    values.reserve(kMaxSamples);
    std::minstd_rand random(12345);  // Deterministic: the same cloud always gets the same colours.
    std::uniform_int_distribution<size_t> index(0, cloud.size() - 1);
    for (size_t k = 0; k < kMaxSamples; ++k) take(index(random));
  }
  if (values.empty()) return {0.f, 1.f};
  const auto at = [&values](double q) {
    auto nth = values.begin() + static_cast<ptrdiff_t>(q * (values.size() - 1));
    std::nth_element(values.begin(), nth, values.end());
    return *nth;
  };
  const float low = at(0.02);
  const float high = at(0.98);
  return {low, high > low ? high : low + 1e-3f};
}

}  // namespace

vtkSmartPointer<vtkPolyData> MakeCloudPolyData(const PointCloud& cloud,
                                               const CloudColoring& coloring) {
  size_t valid = 0;
  for (const Eigen::Vector3f& p : cloud.points) valid += p.allFinite() ? 1 : 0;

  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(valid));
  float* xyz = vtkFloatArray::SafeDownCast(points->GetData())->GetPointer(0);
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("colors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(static_cast<vtkIdType>(valid));
  uint8_t* rgb = colors->GetPointer(0);

  const bool use_rgb = coloring.use_rgb && cloud.has_colors();
  float low = 0, scale = 0;
  if (!use_rgb) {
    const auto [lo, hi] = RobustRange(cloud, coloring.scalar_axis);
    low = lo;
    scale = 255.f / (hi - lo);
  }
  const auto& lut = TurboColorMap();
  for (size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3f& p = cloud.points[i];
    if (!p.allFinite()) continue;
    xyz[0] = p.x();
    xyz[1] = p.y();
    xyz[2] = p.z();
    xyz += 3;
    if (use_rgb) {
      const auto& c = cloud.colors[i];
      rgb[0] = c[0];
      rgb[1] = c[1];
      rgb[2] = c[2];
    } else {
      const float t = (coloring.scalar_axis.dot(p) - low) * scale;
      const Rgb8 c = lut[static_cast<int>(std::clamp(t, 0.f, 255.f))];
      rgb[0] = c.r;
      rgb[1] = c.g;
      rgb[2] = c.b;
    }
    rgb += 3;
  }

  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetVerts(SequentialCells(static_cast<vtkIdType>(valid), 1));
  poly->GetPointData()->SetScalars(colors);
  return poly;
}

vtkSmartPointer<vtkPolyData> MakeSegmentsPolyData(const std::vector<ColoredSegment>& segments) {
  const vtkIdType count = static_cast<vtkIdType>(segments.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(2 * count);
  float* xyz = vtkFloatArray::SafeDownCast(points->GetData())->GetPointer(0);
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("colors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(count);
  uint8_t* rgb = colors->GetPointer(0);
  for (const ColoredSegment& s : segments) {
    for (const Eigen::Vector3d* p : {&s.a, &s.b}) {
      *xyz++ = static_cast<float>(p->x());
      *xyz++ = static_cast<float>(p->y());
      *xyz++ = static_cast<float>(p->z());
    }
    *rgb++ = s.color.r;
    *rgb++ = s.color.g;
    *rgb++ = s.color.b;
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetLines(SequentialCells(2 * count, 2));
  poly->GetCellData()->SetScalars(colors);
  return poly;
}

void AppendFrustum(const Eigen::Isometry3d& world_from_camera, double depth_m, Rgb8 color,
                   std::vector<ColoredSegment>* segments) {
  // A 4:3 image with a ~67 degree horizontal field of view.
  const double hw = 0.65 * depth_m;
  const double hh = 0.75 * hw;
  const Eigen::Vector3d apex = world_from_camera.translation();
  const Eigen::Vector3d c[4] = {world_from_camera * Eigen::Vector3d(-hw, -hh, depth_m),
                                world_from_camera * Eigen::Vector3d(hw, -hh, depth_m),
                                world_from_camera * Eigen::Vector3d(hw, hh, depth_m),
                                world_from_camera * Eigen::Vector3d(-hw, hh, depth_m)};
  for (int i = 0; i < 4; ++i) {
    segments->push_back({apex, c[i], color});
    segments->push_back({c[i], c[(i + 1) % 4], color});
  }
  // The image's top edge is at -y in the optical frame; mark it like a roof.
  const Eigen::Vector3d roof = world_from_camera * Eigen::Vector3d(0, -hh - 0.5 * hh, depth_m);
  segments->push_back({c[0], roof, color});
  segments->push_back({roof, c[1], color});
}

void AppendAxes(const Eigen::Isometry3d& world_from_frame, double length_m,
                const Rgb8* single_color, std::vector<ColoredSegment>* segments) {
  static constexpr Rgb8 kAxisColors[3] = {{230, 40, 40}, {40, 200, 40}, {50, 90, 255}};
  const Eigen::Vector3d origin = world_from_frame.translation();
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Vector3d tip = world_from_frame * (length_m * Eigen::Vector3d::Unit(axis));
    segments->push_back({origin, tip, single_color ? *single_color : kAxisColors[axis]});
  }
}

void AppendGrid(const Eigen::Vector3d& center, const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                double spacing_m, int half_cells, Rgb8 color,
                std::vector<ColoredSegment>* segments) {
  const double extent = spacing_m * half_cells;
  for (int i = -half_cells; i <= half_cells; ++i) {
    const double offset = spacing_m * i;
    segments->push_back(
        {center + offset * u - extent * v, center + offset * u + extent * v, color});
    segments->push_back(
        {center + offset * v - extent * u, center + offset * v + extent * u, color});
  }
}

vtkSmartPointer<vtkImageData> MakeTextureImage(const cv::Mat& image) {
  const bool usable =
      !image.empty() && image.dims == 2 && (image.type() == CV_8UC3 || image.type() == CV_8UC1);
  const int width = usable ? image.cols : 1;
  const int height = usable ? image.rows : 1;
  auto texels = vtkSmartPointer<vtkImageData>::New();
  texels->SetDimensions(width, height, 1);
  texels->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<uint8_t*>(texels->GetScalarPointer());
  if (!usable) {
    out[0] = out[1] = out[2] = 128;
    return texels;
  }
  for (int r = 0; r < height; ++r) {
    const uint8_t* in = image.ptr<uint8_t>(height - 1 - r);
    uint8_t* row = out + static_cast<size_t>(r) * width * 3;
    for (int c = 0; c < width; ++c) {
      if (image.channels() == 3) {
        row[3 * c + 0] = in[3 * c + 2];
        row[3 * c + 1] = in[3 * c + 1];
        row[3 * c + 2] = in[3 * c + 0];
      } else {
        row[3 * c + 0] = row[3 * c + 1] = row[3 * c + 2] = in[c];
      }
    }
  }
  return texels;
}

vtkSmartPointer<vtkPolyData> MakeTexturedQuad(const Eigen::Vector3d& origin,
                                              const Eigen::Vector3d& right,
                                              const Eigen::Vector3d& up) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const Eigen::Vector3d corners[4] = {origin, origin + right, origin + right + up, origin + up};
  for (const Eigen::Vector3d& p : corners) points->InsertNextPoint(p.data());
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetNumberOfComponents(2);
  tcoords->SetName("texture");
  const float uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const auto& t : uv) tcoords->InsertNextTuple(t);
  vtkNew<vtkCellArray> quads;
  const vtkIdType ids[4] = {0, 1, 2, 3};
  quads->InsertNextCell(4, ids);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(quads);
  poly->GetPointData()->SetTCoords(tcoords);
  return poly;
}

}  // namespace sightline
