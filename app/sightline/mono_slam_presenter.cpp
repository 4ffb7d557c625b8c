#include "app/sightline/mono_slam_presenter.h"

#include <QDockWidget>
#include <QHBoxLayout>
#include <QLabel>
#include <QMainWindow>
#include <QPainter>
#include <QPushButton>
#include <QVBoxLayout>

#include "widgets/image_view.h"
#include "widgets/scene_view.h"

namespace sightline {

// The convergence of both scale estimates over the pairs (ML solid, single ratio dashed).
class ScalePlot : public QWidget {
  Q_OBJECT  // For tr(): without it the texts are looked up under QWidget and never translated.

      public : explicit ScalePlot(QWidget* parent)
      : QWidget(parent) {
    setMinimumHeight(120);
  }
  void SetHistory(std::vector<ScaleSample> history) {
    history_ = std::move(history);
    update();
  }

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter p(this);
    p.fillRect(rect(), QColor(30, 30, 34));
    double lo = 1e300, hi = -1e300;
    for (const ScaleSample& s : history_) {
      for (double v : {s.max_likelihood, s.single_ratio}) {
        if (v > 0) {
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
      }
    }
    p.setPen(QColor(200, 200, 200));
    if (history_.size() < 2 || hi <= lo) {
      p.drawText(rect(), Qt::AlignCenter, tr("scale: waiting for displacement pairs"));
      return;
    }
    const double pad = 0.1 * (hi - lo);
    lo -= pad;
    hi += pad;
    const QRectF area = QRectF(rect()).adjusted(50, 8, -8, -18);
    auto at = [&](size_t i, double v) {
      return QPointF(area.left() + area.width() * i / double(history_.size() - 1),
                     area.bottom() - area.height() * (v - lo) / (hi - lo));
    };
    p.drawText(QRectF(0, area.top() - 6, 48, 14), Qt::AlignRight, QString::number(hi, 'g', 4));
    p.drawText(QRectF(0, area.bottom() - 8, 48, 14), Qt::AlignRight, QString::number(lo, 'g', 4));
    p.drawText(QRectF(area.left(), area.bottom() + 2, area.width(), 14), Qt::AlignCenter,
               tr("pairs (map units per metre)"));
    for (int which = 0; which < 2; ++which) {
      QPen pen(which == 0 ? QColor(90, 200, 255) : QColor(255, 170, 60), 2.0);
      if (which == 1) pen.setStyle(Qt::DashLine);
      p.setPen(pen);
      QPolygonF line;
      for (size_t i = 0; i < history_.size(); ++i) {
        const double v = which == 0 ? history_[i].max_likelihood : history_[i].single_ratio;
        if (v > 0) line << at(i, v);
      }
      p.drawPolyline(line);
    }
  }

 private:
  std::vector<ScaleSample> history_;
};

namespace {

constexpr const char* kMapLayer = "mono/map";
constexpr const char* kKeyFramesLayer = "mono/keyframes";
constexpr const char* kTrajectoryLayer = "mono/trajectory";
constexpr const char* kCameraLayer = "mono/camera";

// The source of the metric motion, in words (MonoSlamFrameResult::metric_source is a key).
QString MetricSourceText(const std::string& source) {
  if (source == "arm") return MonoSlamPresenter::tr("the arm's poses");
  if (source == "ground_truth") return MonoSlamPresenter::tr("the ground truth");
  if (source == "none") return MonoSlamPresenter::tr("none");
  return QString::fromStdString(source);
}

QColor QualityColor(TrackingQuality q) {
  switch (q) {
    case TrackingQuality::kGood:
      return QColor(40, 220, 40);
    case TrackingQuality::kPoor:
      return QColor(240, 200, 40);
    case TrackingQuality::kLost:
      return QColor(230, 40, 40);
    case TrackingQuality::kInitialising:
      return QColor(120, 160, 255);
  }
  return Qt::white;
}

// A colour per keyframe (golden-angle hues), as map.ply uses.
Eigen::Matrix<uint8_t, 3, 1> KeyFrameColour(int64_t keyframe) {
  const QColor c =
      QColor::fromHsv(static_cast<int>(std::fmod(keyframe * 137.508, 360.0)), 200, 255);
  return Eigen::Matrix<uint8_t, 3, 1>(c.red(), c.green(), c.blue());
}

}  // namespace

MonoSlamPresenter::MonoSlamPresenter(QObject* parent)
    : MonoSlamPresenter(std::make_shared<MonoSlamCommands>(), parent) {}

MonoSlamPresenter::MonoSlamPresenter(std::shared_ptr<MonoSlamCommands> commands, QObject* parent)
    : MonoSlamPresenter(MonoSlamPipelineInfo(commands), std::move(commands), parent) {}

MonoSlamPresenter::MonoSlamPresenter(PipelineInfo info, std::shared_ptr<MonoSlamCommands> commands,
                                     QObject* parent)
    : PipelinePresenter(std::move(info), parent), commands_(std::move(commands)) {}

const char* MonoSlamPresenter::TitleSource() const {
  return QT_TR_NOOP("Monocular SLAM (PTAM point cloud)");
}

void MonoSlamPresenter::Attach(QMainWindow* window) {
  if (image_dock_ == nullptr) {
    auto* panel = new QWidget(window);
    auto* layout = new QVBoxLayout(panel);
    layout->setContentsMargins(0, 0, 0, 0);
    status_label_ = new QLabel(panel);
    status_label_->setWordWrap(true);
    image_view_ = new ImageView(panel);
    auto* buttons = new QHBoxLayout();
    auto* reset = new QPushButton(tr("Reset map"), panel);
    pause_button_ = new QPushButton(tr("Pause mapping"), panel);
    pause_button_->setCheckable(true);
    buttons->addWidget(reset);
    buttons->addWidget(pause_button_);
    layout->addWidget(status_label_);
    layout->addWidget(image_view_, 1);
    layout->addLayout(buttons);
    connect(reset, &QPushButton::clicked, this, [this] {
      commands_->ResetMap();
      trajectory_ = Trajectory();
    });
    connect(pause_button_, &QPushButton::toggled, this,
            [this](bool paused) { commands_->PauseMapping(paused); });
    image_dock_ = new QDockWidget(tr("Tracked features (inliers green, outliers red)"), window);
    image_dock_->setObjectName("mono_image_dock");
    image_dock_->setWidget(panel);

    auto* scale_panel = new QWidget(window);
    auto* scale_layout = new QVBoxLayout(scale_panel);
    scale_label_ = new QLabel(scale_panel);
    scale_label_->setWordWrap(true);
    scale_plot_ = new ScalePlot(scale_panel);
    scale_layout->addWidget(scale_label_);
    scale_layout->addWidget(scale_plot_, 1);
    scale_dock_ = new QDockWidget(tr("Metric scale (ML solid, single ratio dashed)"), window);
    scale_dock_->setObjectName("mono_scale_dock");
    scale_dock_->setWidget(scale_panel);
  }
  scene_ = window->findChild<SceneView*>();
  window->addDockWidget(Qt::LeftDockWidgetArea, image_dock_);
  window->addDockWidget(Qt::LeftDockWidgetArea, scale_dock_);
  image_dock_->show();
  scale_dock_->show();
  trajectory_ = Trajectory();
  last_id_ = -1;
}

void MonoSlamPresenter::Detach() {
  if (image_dock_ != nullptr) image_dock_->hide();
  if (scale_dock_ != nullptr) scale_dock_->hide();
  if (scene_ != nullptr) {
    for (const char* layer : {kMapLayer, kKeyFramesLayer, kTrajectoryLayer, kCameraLayer}) {
      scene_->RemoveLayer(layer);
    }
    scene_->SetKeys({});
  }
}

void MonoSlamPresenter::Show(const PlaybackResult& result) {
  const auto* view = dynamic_cast<const MonoSlamFrameResult*>(result.pipeline.get());
  if (view == nullptr || image_view_ == nullptr || !view->slam) return;
  const std::shared_ptr<const MonoSlamResult> slam = view->slam;
  if (result.pipeline_restarted || slam->stamp.sequence_id <= last_id_) trajectory_ = Trajectory();
  last_id_ = slam->stamp.sequence_id;

  image_view_->SetImage(slam->image);
  image_view_->SetKeys({{QColor(40, 220, 40), tr("inlier")},
                        {QColor(230, 40, 40), tr("outlier")},
                        {QColor(150, 150, 150), tr("keypoint, unmatched")},
                        {QualityColor(slam->quality), tr("frame: tracking quality")}});
  image_view_->SetOverlayPainter([slam](QPainter& painter, const QTransform& to_widget) {
    for (size_t i = 0; i < slam->keypoints.size(); ++i) {
      const uint8_t state = slam->keypoint_state[i];
      painter.setPen(QPen(state == 1   ? QColor(40, 220, 40)
                          : state == 2 ? QColor(230, 40, 40)
                                       : QColor(150, 150, 150),
                          state == 0 ? 1.0 : 1.5));
      painter.drawEllipse(to_widget.map(QPointF(slam->keypoints[i].x, slam->keypoints[i].y)),
                          state == 0 ? 1.5 : 3.0, state == 0 ? 1.5 : 3.0);
    }
    painter.setPen(QPen(QualityColor(slam->quality), 6));
    painter.drawRect(to_widget.mapRect(QRectF(0, 0, slam->image.cols, slam->image.rows)));
  });
  auto stat = [view](const char* key) { return view->Stat(key).value_or(0); };
  status_label_->setText(tr("%1: %2 inliers of %3 matches, %4 map points, %5 keyframes, %6 ms")
                             .arg(QString::fromStdString(slam->stats.status))
                             .arg(stat("mono/inliers"))
                             .arg(stat("mono/matches"))
                             .arg(stat("mono/map_points"))
                             .arg(stat("mono/keyframes"))
                             .arg(stat("mono/tracking_ms"), 0, 'f', 1));
  scale_ml_ = view->lambda;
  const double divide = view->lambda > 0 ? view->lambda : 1.0;
  if (view->lambda > 0) {
    scale_label_->setText(tr("Metric scale from %1: ML %2, single ratio %3 map units per metre; "
                             "map and trajectory in metres.")
                              .arg(MetricSourceText(view->metric_source))
                              .arg(view->lambda, 0, 'g', 5)
                              .arg(view->single_ratio, 0, 'g', 5));
  } else {
    scale_label_->setText(tr("Scale unknown (measured motion: %1): the map is in arbitrary units "
                             "(first baseline = 0.1).")
                              .arg(MetricSourceText(view->metric_source)));
  }
  if (view->scale_history) scale_plot_->SetHistory(*view->scale_history);

  if (slam->tracked) trajectory_.Add(slam->stamp.sensor_time_s, slam->map_from_camera);
  if (scene_ != nullptr) DrawScene(*view, divide);
}

void MonoSlamPresenter::DrawScene(const MonoSlamFrameResult& view, double divide) {
  const std::shared_ptr<const MonoSlamResult>& slam = view.slam;
  auto metric = [divide](Eigen::Isometry3d pose) {
    pose.translation() /= divide;
    return pose;
  };
  auto cloud = std::make_shared<PointCloud>();
  for (const MapSnapshot::Point& p : slam->map->points) {
    cloud->points.push_back((p.position / divide).cast<float>());
    cloud->colors.push_back(KeyFrameColour(p.first_keyframe));
  }
  points_drawn_ = cloud->points.size();
  scene_->SetPointCloud(kMapLayer, cloud, SceneView::ColorMode::kRgb, 3.0);
  std::vector<Eigen::Isometry3d> keyframes;
  for (const MapSnapshot::Frame& k : slam->map->keyframes)
    keyframes.push_back(metric(k.map_from_camera));
  keyframes_drawn_ = keyframes.size();
  const double frustum = view.lambda > 0 ? 0.03 : 0.03 * divide;
  scene_->SetFrusta(kKeyFramesLayer, keyframes, QColor(90, 200, 255), frustum);
  Trajectory drawn;
  Eigen::AlignedBox3d path_box;
  for (const TimedPose& p : trajectory_.poses()) {
    drawn.Add(p.time_s, metric(p.world_from_sensor));
    path_box.extend(drawn.poses().back().world_from_sensor.translation());
  }
  scene_->SetTrajectory(kTrajectoryLayer, drawn, QColor(255, 80, 80), 2.0);
  // The view follows the camera's path as it grows (metres, or the map's units unscaled).
  scene_->FollowContent(path_box, view.lambda > 0 ? 2.0 : 0.2);
  scene_->SetFrusta(kCameraLayer, {metric(slam->map_from_camera)}, QualityColor(slam->quality),
                    1.5 * frustum);
  scene_->SetKeys({{QColor(255, 80, 80), tr("camera path")},
                   {QColor(90, 200, 255), tr("keyframes")},
                   {QualityColor(slam->quality), tr("camera: tracking quality")},
                   {QColor(200, 200, 200), tr("map points: colour of their first keyframe")}});
}

}  // namespace sightline

#include "mono_slam_presenter.moc"
