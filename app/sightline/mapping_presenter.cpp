#include "app/sightline/mapping_presenter.h"

#include <QDockWidget>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QMainWindow>
#include <QPainter>
#include <QPushButton>
#include <QVBoxLayout>
#include <cstdio>

#include "app/sightline/statistics_text.h"
#include "core/io/floor_file.h"
#include "core/pipeline/mapping_pipeline.h"
#include "widgets/image_view.h"
#include "widgets/scene_view.h"

namespace sightline {

namespace {

// Free cells green, occupied red, people white, unknown dark grey (as in the published Fig. 4.19).
cv::Mat OccupancyToBgr(const OccupancyImage& occupancy) {
  cv::Mat bgr(occupancy.cells.size(), CV_8UC3, cv::Scalar(40, 40, 40));
  for (int r = 0; r < occupancy.height(); ++r) {
    const uint8_t* cells = occupancy.cells.ptr<uint8_t>(r);
    cv::Vec3b* out = bgr.ptr<cv::Vec3b>(r);
    for (int c = 0; c < occupancy.width(); ++c) {
      switch (static_cast<OccupancyCell>(cells[c])) {
        case OccupancyCell::kFree:
          out[c] = {60, 160, 60};
          break;
        case OccupancyCell::kOccupied:
          out[c] = {40, 40, 220};
          break;
        case OccupancyCell::kPerson:
          out[c] = {230, 230, 230};
          break;
        case OccupancyCell::kUnknown:
          break;
      }
    }
  }
  return bgr;
}

// The stitched map for the 3D view's floor, in the occupancy view's colours: free green,
// occupied red, unknown nearly the background (map_server grey levels: 254 free, 0 occupied).
cv::Mat StitchedMapForScene(const cv::Mat& gray) {
  cv::Mat bgr(gray.size(), CV_8UC3, cv::Scalar(48, 44, 44));
  for (int r = 0; r < gray.rows; ++r) {
    const uint8_t* in = gray.ptr<uint8_t>(r);
    cv::Vec3b* out = bgr.ptr<cv::Vec3b>(r);
    for (int c = 0; c < gray.cols; ++c) {
      if (in[c] == 254) out[c] = {60, 160, 60};
      if (in[c] == 0) out[c] = {40, 40, 220};
    }
  }
  return bgr;
}

// The walls (as upright rectangles up to `height_m`) and a patch of the floor, in the camera
// frame, for the 3D view beside the depth cloud. Walls are split by Manhattan class.
struct SceneLines {
  std::vector<SceneView::Segment> walls[3];  // Class 0, class 1, unclassified.
  std::vector<SceneView::Segment> floor;
};

SceneLines WallsAndFloorInCamera(const MappingFrameResult& mapping,
                                 const Eigen::Isometry3d& base_from_camera) {
  constexpr double kWallHeightM = 1.2;
  const Eigen::Isometry3d camera_from_base = base_from_camera.inverse();
  auto at = [&](const Eigen::Vector2d& xy, double z) {
    return Eigen::Vector3d(camera_from_base * Eigen::Vector3d(xy.x(), xy.y(), z));
  };
  SceneLines out;
  for (const WallSegment& line : mapping.lines.lines) {
    auto& segments = out.walls[line.direction_class == 0 ? 0 : line.direction_class == 1 ? 1 : 2];
    segments.push_back({at(line.start, 0), at(line.end, 0)});
    segments.push_back({at(line.start, kWallHeightM), at(line.end, kWallHeightM)});
    segments.push_back({at(line.start, 0), at(line.start, kWallHeightM)});
    segments.push_back({at(line.end, 0), at(line.end, kWallHeightM)});
  }
  // A 0.5 m grid on the calibrated floor plane, 0.5-4 m ahead and 2 m to each side.
  for (double x = 0.5; x <= 4.0 + 1e-9; x += 0.5)
    out.floor.push_back({at({x, -2}, 0), at({x, 2}, 0)});
  for (double y = -2; y <= 2 + 1e-9; y += 0.5)
    out.floor.push_back({at({0.5, y}, 0), at({4, y}, 0)});
  return out;
}

constexpr const char* kWallLayers[3] = {"mapping/walls_0", "mapping/walls_1",
                                        "mapping/walls_other"};
constexpr const char* kFloorLayer = "mapping/floor";
// The stitched map as a textured plane on the floor, and the estimated path above it, both in
// the map frame and placed in the camera's frame (the 3D view's) by the frame's pose.
constexpr const char* kMapLayer = "mapping/stitched_map";
constexpr const char* kPathLayer = "mapping/path";
constexpr double kMapBelowFloorM = 0.01;  // Under the floor grid's lines, not through them.
constexpr double kPathAboveFloorM = 0.03;

}  // namespace

MappingPresenter::MappingPresenter(QObject* parent)
    : MappingPresenter(std::make_shared<MappingRequests>(), parent) {}

MappingPresenter::MappingPresenter(std::shared_ptr<MappingRequests> requests, QObject* parent)
    : PipelinePresenter(MappingPipelineInfo(requests), parent), requests_(std::move(requests)) {}

const char* MappingPresenter::TitleSource() const {
  return QT_TR_NOOP("Indoor mapping (Manhattan walls)");
}

void MappingPresenter::Attach(QMainWindow* window) {
  if (occupancy_dock_ == nullptr) {
    occupancy_view_ = new ImageView(window);
    map_view_ = new ImageView(window);
    occupancy_dock_ = new QDockWidget(tr("Occupancy, scan and walls"), window);
    occupancy_dock_->setObjectName("mapping_occupancy_dock");
    auto* panel = new QWidget(window);
    auto* layout = new QVBoxLayout(panel);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* buttons = new QHBoxLayout;
    auto* calibrate = new QPushButton(tr("Calibrate floor"), panel);
    calibrate->setToolTip(
        tr("Fit the floor plane again from the next frames (the robot should "
           "see open floor)."));
    connect(calibrate, &QPushButton::clicked, this, &MappingPresenter::RecalibrateFloor);
    auto* save = new QPushButton(tr("Save floor..."), panel);
    save->setToolTip(
        tr("Save the floor calibration in use, for mapping.run.floor_file or "
           "`sightline-cli run mapping --set mapping.run.floor_file=...`."));
    connect(save, &QPushButton::clicked, this, [this, window] {
      const QString path = QFileDialog::getSaveFileName(window, tr("Save floor calibration"),
                                                        "floor.yaml", tr("YAML (*.yaml)"));
      if (!path.isEmpty()) static_cast<void>(SaveFloor(path));  // Its outcome is in the log.
    });
    buttons->addWidget(calibrate);
    buttons->addWidget(save);
    buttons->addStretch();
    layout->addLayout(buttons);
    layout->addWidget(occupancy_view_, 1);
    figures_ = new QLabel(panel);
    figures_->setWordWrap(true);
    layout->addWidget(figures_);
    occupancy_dock_->setWidget(panel);
    map_dock_ = new QDockWidget(tr("Stitched map"), window);
    map_dock_->setObjectName("mapping_map_dock");
    map_dock_->setWidget(map_view_);
  }
  scene_ = window->findChild<SceneView*>();
  window->addDockWidget(Qt::LeftDockWidgetArea, occupancy_dock_);
  window->addDockWidget(Qt::LeftDockWidgetArea, map_dock_);
  occupancy_dock_->show();
  map_dock_->show();
}

void MappingPresenter::Detach() {
  if (scene_ != nullptr) {
    for (const char* layer : kWallLayers) scene_->RemoveLayer(layer);
    scene_->RemoveLayer(kFloorLayer);
    scene_->RemoveLayer(kMapLayer);
    scene_->RemoveLayer(kPathLayer);
    scene_->SetKeys({});
  }
  if (occupancy_dock_ != nullptr) occupancy_dock_->hide();
  if (map_dock_ != nullptr) map_dock_->hide();
}

void MappingPresenter::Show(const PlaybackResult& result) {
  const auto* view = dynamic_cast<const MappingResult*>(result.pipeline.get());
  if (view == nullptr || occupancy_view_ == nullptr) return;
  if (!view->note.empty()) emit Message(0, QString::fromStdString(view->note));
  if (!view->mapping) return;
  floor_ = view->floor;
  figures_->setText(StatisticsText(*view, MappingStatistics()));
  const std::shared_ptr<const MappingFrameResult> mapping = view->mapping;
  occupancy_view_->SetImage(OccupancyToBgr(mapping->occupancy));
  occupancy_view_->SetKeys({{QColor(60, 160, 60), tr("free")},
                            {QColor(220, 40, 40), tr("occupied")},
                            {QColor(230, 230, 230), tr("person")},
                            {QColor(255, 170, 0), tr("scan rays")},
                            {QColor(0, 200, 255), tr("walls, first direction")},
                            {QColor(255, 0, 255), tr("walls, perpendicular")},
                            {QColor(255, 255, 0), tr("other lines")},
                            {QColor(255, 220, 0), tr("robot")}});
  // Rays from the robot to each scan point, and the wall lines by Manhattan direction.
  occupancy_view_->SetOverlayPainter([mapping](QPainter& painter, const QTransform& to_widget) {
    const OccupancyImage& occ = mapping->occupancy;
    const Eigen::Vector2d robot = occ.ToImage({0, 0});
    const QPointF origin = to_widget.map(QPointF(robot.x(), robot.y()));
    painter.setPen(QPen(QColor(255, 170, 0, 90), 1));
    for (size_t i = 0; i < mapping->scan.points.size(); i += 3) {
      const cv::Point& cell = mapping->scan.points[i].cell;
      painter.drawLine(origin, to_widget.map(QPointF(cell.x, cell.y)));
    }
    for (const WallSegment& line : mapping->lines.lines) {
      const QColor color = line.direction_class == 0   ? QColor(0, 200, 255)
                           : line.direction_class == 1 ? QColor(255, 0, 255)
                                                       : QColor(255, 255, 0);
      painter.setPen(QPen(color, 3));
      const Eigen::Vector2d a = occ.ToImage(line.start), b = occ.ToImage(line.end);
      painter.drawLine(to_widget.map(QPointF(a.x(), a.y())), to_widget.map(QPointF(b.x(), b.y())));
    }
    painter.setBrush(QColor(255, 220, 0));
    painter.setPen(Qt::NoPen);
    painter.drawRect(QRectF(origin - QPointF(5, 5), QSizeF(10, 10)));
  });
  if (mapping->map_image) {
    map_view_->SetImage(*mapping->map_image);
    map_view_->SetKeys({{QColor(254, 254, 254), tr("free")},
                        {QColor(205, 205, 205), tr("unknown")},
                        {QColor(0, 0, 0), tr("occupied")},
                        {QColor(220, 0, 0), tr("path and robot")}});
  }
  if (scene_ != nullptr) {
    const SceneLines lines = WallsAndFloorInCamera(*mapping, view->base_from_camera);
    const QColor colors[3] = {QColor(0, 200, 255), QColor(255, 0, 255), QColor(255, 255, 0)};
    for (int k = 0; k < 3; ++k) scene_->SetLines(kWallLayers[k], lines.walls[k], colors[k], 3.0);
    scene_->SetLines(kFloorLayer, lines.floor, QColor(60, 200, 60), 1.0);
    ShowStitchedMap(*mapping);
    std::vector<SceneView::Key> keys = {{colors[0], tr("walls, first direction")},
                                        {colors[1], tr("walls, perpendicular")},
                                        {colors[2], tr("other lines")},
                                        {QColor(60, 200, 60), tr("floor")}};
    if (scene_->HasLayer(kMapLayer)) {
      keys.push_back({QColor(60, 160, 60), tr("map: free")});
      keys.push_back({QColor(220, 40, 40), tr("map: occupied")});
      keys.push_back({QColor(255, 150, 0), tr("path")});
    }
    scene_->SetKeys(keys);
  }
  if (mapping->reset) {
    emit Message(1, tr("Manhattan reference reset: %1")
                        .arg(QString::fromStdString(mapping->rotation.reset_reason)));
  }
  // Degenerate frames are said once per change, not once per frame.
  if (mapping->status != last_status_) {
    if (mapping->status != "ok") emit Message(1, QString::fromStdString(mapping->status));
    last_status_ = mapping->status;
  }
}

void MappingPresenter::ShowStitchedMap(const MappingFrameResult& mapping) {
  if (mapping.map_gray && !mapping.map_gray->empty() && mapping.map_resolution_m > 0) {
    const cv::Mat& gray = *mapping.map_gray;
    const double width_m = gray.cols * mapping.map_resolution_m;
    const double height_m = gray.rows * mapping.map_resolution_m;
    // Row 0 of the map image is the largest world y; map_origin is its bottom-left corner.
    scene_->SetImagePlane(kMapLayer, StitchedMapForScene(gray),
                          {mapping.map_origin.x(), mapping.map_origin.y(), -kMapBelowFloorM},
                          {width_m, 0, 0}, {0, height_m, 0}, 0.9);
    if (mapping.trajectory && mapping.trajectory->size() >= 2) {
      std::vector<SceneView::Segment> path;
      const std::vector<Pose2d>& poses = *mapping.trajectory;
      for (size_t i = 1; i < poses.size(); ++i) {
        path.push_back({{poses[i - 1].x, poses[i - 1].y, kPathAboveFloorM},
                        {poses[i].x, poses[i].y, kPathAboveFloorM}});
      }
      scene_->SetLines(kPathLayer, path, QColor(255, 150, 0), 2.0);
    }
  }
  // Every frame: the map frame seen from the camera that took this frame.
  const Eigen::Isometry3d camera_from_world = mapping.world_from_camera.inverse();
  scene_->SetLayerPose(kMapLayer, camera_from_world);
  scene_->SetLayerPose(kPathLayer, camera_from_world);
}

std::vector<std::string> MappingPresenter::SceneLayers() {
  return {kWallLayers[0], kWallLayers[1], kWallLayers[2], kFloorLayer, kMapLayer, kPathLayer};
}

void MappingPresenter::RecalibrateFloor() {
  requests_->floor_calibrations.fetch_add(1);
  emit Message(0, tr("Calibrating the floor again from the next frames."));
}

Status MappingPresenter::SaveFloor(const QString& path) {
  if (!floor_) {
    Status none = FailedPrecondition("no floor calibration yet: play a few frames first");
    emit Message(2, QString::fromStdString(none.message()));
    return none;
  }
  FloorCalibration calibration;
  calibration.plane = *floor_;
  Status written = WriteFloorCalibration(calibration, path.toStdString());
  emit Message(written.ok() ? 0 : 2, written.ok()
                                         ? tr("Saved the floor calibration to %1").arg(path)
                                         : QString::fromStdString(written.ToString()));
  return written;
}

}  // namespace sightline
