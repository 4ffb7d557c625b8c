#include "widgets/scene_view.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>

#include <QLabel>
#include <algorithm>
#include <functional>
#include <map>

#include "core/common/frame.h"
#include "core/common/trajectory.h"
#include "widgets/scene_geometry.h"

namespace sightline {
namespace {

Rgb8 ToRgb8(const QColor& color) {
  return Rgb8{static_cast<uint8_t>(color.red()), static_cast<uint8_t>(color.green()),
              static_cast<uint8_t>(color.blue())};
}

// An unlit actor that shows the poly data's RGB scalars exactly as given.
vtkSmartPointer<vtkActor> MakeActor(vtkPolyData* poly, bool cell_colors) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->ScalarVisibilityOn();
  mapper->SetColorModeToDirectScalars();
  if (cell_colors) {
    mapper->SetScalarModeToUseCellData();
  } else {
    mapper->SetScalarModeToUsePointData();
  }
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  return actor;
}

vtkSmartPointer<vtkActor> MakeSegmentsActor(const std::vector<ColoredSegment>& segments,
                                            double line_width_px) {
  vtkSmartPointer<vtkActor> actor = MakeActor(MakeSegmentsPolyData(segments), true);
  actor->GetProperty()->SetLineWidth(static_cast<float>(line_width_px));
  return actor;
}

}  // namespace

struct SceneView::Impl {
  struct Layer {
    vtkSmartPointer<vtkActor> actor;
    Eigen::Isometry3d world_from_layer = Eigen::Isometry3d::Identity();
    bool visible = true;
    // A cloud set while the layer was hidden: built only when the layer is shown again, so
    // hidden layers cost nothing per frame.
    std::function<void()> build_when_shown;
  };

  SceneView* view = nullptr;
  vtkRenderer* renderer = nullptr;  // Owned by VtkGlWidget.
  std::map<std::string, Layer> layers;
  vtkSmartPointer<vtkActor> grid;
  bool grid_visible = true;
  double grid_spacing_m = 1.0;
  int grid_cells = 20;
  double grid_height_m = 0.0;
  Eigen::Vector3d up = -Eigen::Vector3d::UnitY();
  Eigen::Vector3d forward = Eigen::Vector3d::UnitZ();

  static void ApplyPose(vtkActor* actor, const Eigen::Isometry3d& world_from_layer) {
    vtkNew<vtkMatrix4x4> matrix;
    const Eigen::Matrix4d& m = world_from_layer.matrix();
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) matrix->SetElement(r, c, m(r, c));
    }
    actor->SetUserMatrix(matrix);
  }

  static bool HasGeometry(vtkActor* actor) {
    const double* b = actor->GetBounds();
    return b != nullptr && b[0] <= b[1];
  }

  bool ShowsGeometry() const {
    return std::any_of(layers.begin(), layers.end(), [](const auto& entry) {
      return entry.second.visible && HasGeometry(entry.second.actor);
    });
  }

  // Shows `poly` in the layer: the layer's own actor gets the new data in place (no actor,
  // mapper or renderer change per frame); a layer that is new or was an image plane gets an
  // actor. `point_size_px` / `line_width_px` apply when > 0.
  void SetPolyData(const std::string& name, vtkSmartPointer<vtkPolyData> poly, bool cell_colors,
                   double point_size_px, double line_width_px) {
    const auto it = layers.find(name);
    vtkActor* existing = it != layers.end() ? it->second.actor.Get() : nullptr;
    auto* mapper =
        existing != nullptr ? vtkPolyDataMapper::SafeDownCast(existing->GetMapper()) : nullptr;
    if (mapper == nullptr || existing->GetTexture() != nullptr) {
      vtkSmartPointer<vtkActor> actor = MakeActor(poly, cell_colors);
      if (point_size_px > 0) actor->GetProperty()->SetPointSize(static_cast<float>(point_size_px));
      if (line_width_px > 0) actor->GetProperty()->SetLineWidth(static_cast<float>(line_width_px));
      Replace(name, actor);
      return;
    }
    const bool was_empty = !ShowsGeometry();
    it->second.build_when_shown = nullptr;
    mapper->SetInputData(poly);
    if (cell_colors) {
      mapper->SetScalarModeToUseCellData();
    } else {
      mapper->SetScalarModeToUsePointData();
    }
    if (point_size_px > 0) existing->GetProperty()->SetPointSize(static_cast<float>(point_size_px));
    if (line_width_px > 0) existing->GetProperty()->SetLineWidth(static_cast<float>(line_width_px));
    if (was_empty && it->second.visible && HasGeometry(existing)) {
      view->ResetView();
    } else {
      Changed();
    }
  }

  // Puts `actor` in place of the layer's previous one, keeping its pose and visibility.
  void Replace(const std::string& name, const vtkSmartPointer<vtkActor>& actor) {
    const bool was_empty = !ShowsGeometry();
    Layer& layer = layers[name];
    layer.build_when_shown = nullptr;
    if (layer.actor) renderer->RemoveActor(layer.actor);
    layer.actor = actor;
    ApplyPose(layer.actor, layer.world_from_layer);
    layer.actor->SetVisibility(layer.visible);
    renderer->AddActor(layer.actor);
    // The first geometry shown in an empty scene gets a fitted view; later updates (a new frame
    // of the same stream) keep the camera where the user put it.
    if (was_empty && layer.visible && HasGeometry(layer.actor)) {
      view->ResetView();
    } else {
      Changed();
    }
  }

  void RebuildGrid() {
    if (grid) renderer->RemoveActor(grid);
    grid = nullptr;
    if (!grid_visible) return;
    const Eigen::Vector3d u = (forward - forward.dot(up) * up).normalized();
    const Eigen::Vector3d v = up.cross(u);
    std::vector<ColoredSegment> segments;
    AppendGrid(grid_height_m * up, u, v, grid_spacing_m, grid_cells / 2, Rgb8{80, 80, 88},
               &segments);
    grid = MakeSegmentsActor(segments, 1.0);
    grid->PickableOff();
    renderer->AddActor(grid);
  }

  void Changed() {
    renderer->ResetCameraClippingRange();
    view->ScheduleRender();
  }
};

SceneView::SceneView(QWidget* parent) : VtkGlWidget(parent), impl_(std::make_unique<Impl>()) {
  impl_->view = this;
  impl_->renderer = renderer();
  impl_->renderer->SetBackground(0.11, 0.11, 0.13);
  impl_->RebuildGrid();
  ResetView();
  keys_label_ = new QLabel(this);
  keys_label_->setObjectName("scene_keys");
  keys_label_->setStyleSheet(
      "QLabel { background: rgba(0, 0, 0, 170); color: white; padding: 4px; border-radius: 3px; }");
  keys_label_->setAttribute(Qt::WA_TransparentForMouseEvents);  // Drags still turn the view.
  keys_label_->move(8, 8);
  keys_label_->hide();
}

void SceneView::SetKeys(const std::vector<Key>& keys) {
  const bool same =
      keys.size() == keys_.size() &&
      std::equal(keys.begin(), keys.end(), keys_.begin(), [](const Key& a, const Key& b) {
        return a.color == b.color && a.label == b.label;
      });
  if (same) return;  // Presenters set their key with every frame.
  keys_ = keys;
  QString html;
  for (const Key& key : keys_) {
    if (!html.isEmpty()) html += QStringLiteral("<br>");
    html += QStringLiteral("<span style=\"color:%1\">&#9632;</span> %2")
                .arg(key.color.name(), key.label.toHtmlEscaped());
  }
  keys_label_->setText(html);
  keys_label_->adjustSize();
  keys_label_->setVisible(!keys_.empty());
}

SceneView::~SceneView() = default;

void SceneView::SetPointCloud(const std::string& layer,
                              const std::shared_ptr<const PointCloud>& cloud, ColorMode mode,
                              double point_size_px) {
  const auto it = impl_->layers.find(layer);
  if (it != impl_->layers.end() && !it->second.visible) {
    // A hidden layer (e.g. the frame's cloud while a pipeline shows its own): nothing is built
    // until it is shown; then its newest cloud is.
    it->second.build_when_shown = [this, layer, cloud, mode, point_size_px] {
      SetPointCloud(layer, cloud, mode, point_size_px);
    };
    return;
  }
  PointCloud empty;
  const PointCloud& points = cloud ? *cloud : empty;
  CloudColoring coloring;
  coloring.use_rgb = (mode == ColorMode::kAuto || mode == ColorMode::kRgb) && points.has_colors();
  coloring.scalar_axis =
      (mode == ColorMode::kHeight ? impl_->up : impl_->forward).normalized().cast<float>();
  impl_->SetPolyData(layer, MakeCloudPolyData(points, coloring), false, point_size_px, 0);
}

bool SceneView::IsLayerVisible(const std::string& layer) const {
  const auto it = impl_->layers.find(layer);
  return it == impl_->layers.end() || it->second.visible;
}

void SceneView::SetLines(const std::string& layer, const std::vector<Segment>& segments,
                         QColor color, double line_width_px) {
  std::vector<ColoredSegment> colored;
  colored.reserve(segments.size());
  const Rgb8 rgb = ToRgb8(color);
  for (const Segment& s : segments) colored.push_back({s.first, s.second, rgb});
  impl_->SetPolyData(layer, MakeSegmentsPolyData(colored), true, 0, line_width_px);
}

void SceneView::SetTrajectory(const std::string& layer, const Trajectory& trajectory, QColor color,
                              double line_width_px) {
  std::vector<ColoredSegment> colored;
  const Rgb8 rgb = ToRgb8(color);
  const auto& poses = trajectory.poses();
  for (size_t i = 1; i < poses.size(); ++i) {
    colored.push_back({poses[i - 1].world_from_sensor.translation(),
                       poses[i].world_from_sensor.translation(), rgb});
  }
  impl_->SetPolyData(layer, MakeSegmentsPolyData(colored), true, 0, line_width_px);
}

void SceneView::SetPoses(const std::string& layer, const std::vector<Eigen::Isometry3d>& poses,
                         QColor color, double size) {
  std::vector<ColoredSegment> colored;
  colored.reserve(3 * poses.size());
  const Rgb8 rgb = ToRgb8(color);
  for (const Eigen::Isometry3d& pose : poses) {
    AppendAxes(pose, size, color.isValid() ? &rgb : nullptr, &colored);
  }
  impl_->SetPolyData(layer, MakeSegmentsPolyData(colored), true, 0, 2.0);
}

void SceneView::SetFrusta(const std::string& layer, const std::vector<Eigen::Isometry3d>& poses,
                          QColor color, double size) {
  std::vector<ColoredSegment> colored;
  colored.reserve(10 * poses.size());
  for (const Eigen::Isometry3d& pose : poses) AppendFrustum(pose, size, ToRgb8(color), &colored);
  impl_->SetPolyData(layer, MakeSegmentsPolyData(colored), true, 0, 1.5);
}

void SceneView::SetImagePlane(const std::string& layer, const cv::Mat& image,
                              const Eigen::Vector3d& origin, const Eigen::Vector3d& right,
                              const Eigen::Vector3d& up, double opacity) {
  vtkSmartPointer<vtkImageData> texels = MakeTextureImage(image);
  vtkSmartPointer<vtkPolyData> plane = MakeTexturedQuad(origin, right, up);
  const auto it = impl_->layers.find(layer);
  vtkActor* existing = it != impl_->layers.end() ? it->second.actor.Get() : nullptr;
  if (existing != nullptr && existing->GetTexture() != nullptr) {
    // The same actor, new texels and corners: no renderer change, one scheduled render.
    existing->GetTexture()->SetInputData(texels);
    vtkPolyDataMapper::SafeDownCast(existing->GetMapper())->SetInputData(plane);
    existing->GetProperty()->SetOpacity(std::clamp(opacity, 0.0, 1.0));
    impl_->Changed();
    return;
  }
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(plane);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkTexture> texture;
  texture->SetInputData(texels);
  texture->InterpolateOff();  // Map cells stay sharp squares.
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->SetTexture(texture);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetOpacity(std::clamp(opacity, 0.0, 1.0));
  impl_->Replace(layer, actor);
}

void SceneView::RemoveLayer(const std::string& layer) {
  auto it = impl_->layers.find(layer);
  if (it == impl_->layers.end()) return;
  impl_->renderer->RemoveActor(it->second.actor);
  impl_->layers.erase(it);
  impl_->Changed();
}

void SceneView::ClearLayers() {
  for (auto& [name, layer] : impl_->layers) impl_->renderer->RemoveActor(layer.actor);
  impl_->layers.clear();
  followed_box_.setEmpty();
  SetKeys({});
  impl_->Changed();
}

bool SceneView::FollowContent(const Eigen::AlignedBox3d& content, double min_margin) {
  if (!follow_ || content.isEmpty() || followed_box_.contains(content)) return false;
  const Eigen::Vector3d margin =
      (0.25 * (content.max() - content.min())).cwiseMax(Eigen::Vector3d::Constant(min_margin));
  followed_box_ = Eigen::AlignedBox3d(content.min() - margin, content.max() + margin);
  ResetView();
  ++follow_fits_;
  return true;
}

void SceneView::SetLayerPose(const std::string& layer, const Eigen::Isometry3d& world_from_layer) {
  auto it = impl_->layers.find(layer);
  if (it == impl_->layers.end()) return;
  it->second.world_from_layer = world_from_layer;
  Impl::ApplyPose(it->second.actor, world_from_layer);
  impl_->Changed();
}

void SceneView::SetLayerVisible(const std::string& layer, bool visible) {
  auto it = impl_->layers.find(layer);
  if (it == impl_->layers.end()) return;
  if (it->second.visible == visible) return;  // Presenters set visibility with every frame.
  it->second.visible = visible;
  it->second.actor->SetVisibility(visible);
  if (visible && it->second.build_when_shown) {
    const std::function<void()> build = std::move(it->second.build_when_shown);
    it->second.build_when_shown = nullptr;
    build();
  }
  impl_->Changed();
}

bool SceneView::HasLayer(const std::string& layer) const { return impl_->layers.count(layer) > 0; }

std::vector<std::string> SceneView::LayerNames() const {
  std::vector<std::string> names;
  for (const auto& [name, layer] : impl_->layers) names.push_back(name);
  return names;
}

void SceneView::SetGroundGrid(bool visible, double spacing_m, int cells_per_side, double height_m) {
  impl_->grid_visible = visible;
  impl_->grid_height_m = height_m;
  impl_->grid_spacing_m = spacing_m > 0 ? spacing_m : 1.0;
  impl_->grid_cells = std::max(2, cells_per_side);
  impl_->RebuildGrid();
  impl_->Changed();
}

void SceneView::SetViewAxes(const Eigen::Vector3d& up, const Eigen::Vector3d& forward) {
  const Eigen::Vector3d u = up.normalized();
  Eigen::Vector3d f = forward - forward.dot(u) * u;
  if (!u.allFinite() || f.norm() < 1e-9) return;  // Degenerate: keep the current axes.
  impl_->up = u;
  impl_->forward = f.normalized();
  impl_->RebuildGrid();
  ResetView();
}

void SceneView::ResetView() {
  double bounds[6] = {1, -1, 1, -1, 1, -1};  // Empty (min > max).
  const auto merge = [&bounds](vtkActor* actor) {
    if (!Impl::HasGeometry(actor)) return;
    const double* b = actor->GetBounds();
    for (int i = 0; i < 3; ++i) {
      if (bounds[2 * i] > bounds[2 * i + 1]) {
        bounds[2 * i] = b[2 * i];
        bounds[2 * i + 1] = b[2 * i + 1];
      } else {
        bounds[2 * i] = std::min(bounds[2 * i], b[2 * i]);
        bounds[2 * i + 1] = std::max(bounds[2 * i + 1], b[2 * i + 1]);
      }
    }
  };
  for (const auto& [name, layer] : impl_->layers) {
    if (layer.visible) merge(layer.actor);
  }
  if (bounds[0] > bounds[1] && impl_->grid) merge(impl_->grid);
  if (bounds[0] > bounds[1]) {
    for (int i = 0; i < 3; ++i) {
      bounds[2 * i] = -1;
      bounds[2 * i + 1] = 1;
    }
  }
  const Eigen::Vector3d center(0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
                               0.5 * (bounds[4] + bounds[5]));
  // Behind the scene along forward, raised a little along up, looking down at ~20 degrees.
  const Eigen::Vector3d direction = (impl_->forward - 0.35 * impl_->up).normalized();
  vtkCamera* camera = impl_->renderer->GetActiveCamera();
  camera->SetFocalPoint(center.data());
  const Eigen::Vector3d position = center - direction;
  camera->SetPosition(position.data());
  camera->SetViewUp(impl_->up.data());
  camera->OrthogonalizeViewUp();
  impl_->renderer->ResetCamera(bounds);  // Keeps the direction, fits the distance.
  impl_->Changed();
}

void SceneView::SetBackground(QColor color) {
  impl_->renderer->SetBackground(color.redF(), color.greenF(), color.blueF());
  ScheduleRender();
}

}  // namespace sightline
