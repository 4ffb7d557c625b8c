#include "app/sightline/stereo_vo_presenter.h"

#include <QDockWidget>
#include <QLabel>
#include <QMainWindow>
#include <QPainter>
#include <QVBoxLayout>

#include "core/pipeline/stereo_vo_result.h"
#include "widgets/image_view.h"
#include "widgets/scene_view.h"
#include "widgets/time_series_plot.h"

namespace sightline {

namespace {

QColor RoleColor(FeatureRole role) {
  switch (role) {
    case FeatureRole::kInlier:
      return QColor(40, 220, 40);
    case FeatureRole::kOutlier:
      return QColor(230, 40, 40);
    case FeatureRole::kNew:
      return QColor(60, 120, 255);
  }
  return Qt::white;
}

constexpr const char* kEstimateLayer = "vo/estimate";
constexpr const char* kGroundTruthLayer = "vo/ground_truth";
constexpr const char* kCameraLayer = "vo/camera";

// A plotted statistic: its key, its series name and colour.
struct Series {
  const char* key;
  const char* label;  // Translated in the presenter's context.
  QColor color;
};

const Series kCountSeries[] = {
    {"vo/tracked", QT_TRANSLATE_NOOP("sightline::StereoVoPresenter", "tracks"),
     QColor(60, 120, 255)},
    {"vo/anchored", QT_TRANSLATE_NOOP("sightline::StereoVoPresenter", "anchored"),
     QColor(0, 200, 200)},
    {"vo/stereo_matches", QT_TRANSLATE_NOOP("sightline::StereoVoPresenter", "stereo"),
     QColor(255, 200, 0)},
    {"vo/inliers", QT_TRANSLATE_NOOP("sightline::StereoVoPresenter", "inliers"),
     QColor(40, 220, 40)},
    {"vo/ransac_iterations", QT_TRANSLATE_NOOP("sightline::StereoVoPresenter", "RANSAC it."),
     QColor(230, 120, 230)}};

const Series kTimingSeries[] = {
    {"vo/rectify_ms", QT_TRANSLATE_NOOP("sightline::StereoVoPresenter", "rectify"),
     QColor(150, 150, 150)},
    {"vo/pyramid_ms", QT_TRANSLATE_NOOP("sightline::StereoVoPresenter", "pyramid"),
     QColor(0, 200, 200)},
    {"vo/tracking_ms", QT_TRANSLATE_NOOP("sightline::StereoVoPresenter", "tracking"),
     QColor(60, 120, 255)},
    {"vo/detection_ms", QT_TRANSLATE_NOOP("sightline::StereoVoPresenter", "detection"),
     QColor(255, 140, 0)},
    {"vo/matching_ms", QT_TRANSLATE_NOOP("sightline::StereoVoPresenter", "matching"),
     QColor(255, 200, 0)},
    {"vo/ransac_ms", QT_TRANSLATE_NOOP("sightline::StereoVoPresenter", "RANSAC"),
     QColor(230, 120, 230)},
    {"vo/refine_ms", QT_TRANSLATE_NOOP("sightline::StereoVoPresenter", "refine"),
     QColor(40, 220, 40)},
    {"vo/window_ms", QT_TRANSLATE_NOOP("sightline::StereoVoPresenter", "window BA"),
     QColor(200, 80, 80)},
    {"vo/total_ms", QT_TRANSLATE_NOOP("sightline::StereoVoPresenter", "total"),
     QColor(240, 240, 240)}};

// The unit of statistic `key` from the pipeline's table.
QString Unit(const char* key) {
  const StatisticInfo* info = FindStatistic(StereoVoStatistics(), key);
  return info != nullptr ? QString::fromStdString(info->unit) : QString();
}

// A frame's value of `key`; 0 when the frame has none (a stage that did not run).
double Value(const StereoVoResult& result, const char* key) {
  return result.Stat(key).value_or(0.0);
}

}  // namespace

StereoVoPresenter::StereoVoPresenter(QObject* parent)
    : PipelinePresenter(*BuiltinPipelines().Find("stereo-vo"), parent) {}

const char* StereoVoPresenter::TitleSource() const { return QT_TR_NOOP("Stereo visual odometry"); }

void StereoVoPresenter::CreateViews(QMainWindow* window) {
  auto* panel = new QWidget(window);
  auto* layout = new QVBoxLayout(panel);
  layout->setContentsMargins(0, 0, 0, 0);
  stats_label_ = new QLabel(panel);
  tracks_view_ = new ImageView(panel);
  layout->addWidget(stats_label_);
  layout->addWidget(tracks_view_, 1);
  tracks_dock_ = new QDockWidget(tr("Tracks (inliers green, outliers red, new blue)"), window);
  tracks_dock_->setObjectName("vo_tracks_dock");
  tracks_dock_->setWidget(panel);
  matches_view_ = new ImageView(window);
  matches_dock_ = new QDockWidget(tr("Stereo matches (right image)"), window);
  matches_dock_->setObjectName("vo_matches_dock");
  matches_dock_->setWidget(matches_view_);
  auto* plots = new QWidget(window);
  auto* plots_layout = new QVBoxLayout(plots);
  plots_layout->setContentsMargins(0, 0, 0, 0);
  // Plot titles carry the units of the pipeline's statistics table.
  counts_plot_ = new TimeSeriesPlot(tr("per frame [%1]").arg(Unit("vo/tracked")), plots);
  timing_plot_ = new TimeSeriesPlot(tr("%1 per stage").arg(Unit("vo/tracking_ms")), plots);
  residual_plot_ =
      new TimeSeriesPlot(tr("residual [%1]; red: gated").arg(Unit("vo/residual_px")), plots);
  for (TimeSeriesPlot* plot : {counts_plot_, timing_plot_, residual_plot_}) {
    plot->SetCapacity(300);
    plots_layout->addWidget(plot, 1);
  }
  stats_dock_ = new QDockWidget(tr("Statistics over time"), window);
  stats_dock_->setObjectName("vo_stats_dock");
  stats_dock_->setWidget(plots);
}

void StereoVoPresenter::Attach(QMainWindow* window) {
  if (tracks_dock_ == nullptr) CreateViews(window);
  scene_ = window->findChild<SceneView*>();
  window->addDockWidget(Qt::LeftDockWidgetArea, tracks_dock_);
  window->addDockWidget(Qt::LeftDockWidgetArea, matches_dock_);
  window->addDockWidget(Qt::RightDockWidgetArea, stats_dock_);
  tracks_dock_->show();
  matches_dock_->show();
  stats_dock_->show();
  estimate_ = Trajectory();
  ground_truth_drawn_ = Trajectory();
  last_id_ = -1;
  for (TimeSeriesPlot* plot : {counts_plot_, timing_plot_, residual_plot_}) plot->Clear();
  fitted_box_.setEmpty();
}

void StereoVoPresenter::Detach() {
  if (tracks_dock_ != nullptr) tracks_dock_->hide();
  if (matches_dock_ != nullptr) matches_dock_->hide();
  if (stats_dock_ != nullptr) stats_dock_->hide();
  if (scene_ != nullptr) {
    for (const char* layer : {kEstimateLayer, kGroundTruthLayer, kCameraLayer}) {
      scene_->RemoveLayer(layer);
    }
    scene_->SetKeys({});
  }
}

void StereoVoPresenter::Show(const PlaybackResult& result) {
  const auto* view = dynamic_cast<const StereoVoResult*>(result.pipeline.get());
  if (view == nullptr || tracks_view_ == nullptr || !view->odometry) return;
  const std::shared_ptr<const StereoOdometryResult>& odometry = view->odometry;
  // A seek either way or a loop starts the drawn trajectories over, as the pipeline does.
  if (result.pipeline_restarted || odometry->stamp.sequence_id <= last_id_) {
    estimate_ = Trajectory();
    ground_truth_drawn_ = Trajectory();
    for (TimeSeriesPlot* plot : {counts_plot_, timing_plot_, residual_plot_}) plot->Clear();
    fitted_box_.setEmpty();
  }
  last_id_ = odometry->stamp.sequence_id;
  DrawImages(odometry);
  ShowSummary(*view);

  estimate_.Add(odometry->stamp.sensor_time_s, odometry->world_from_camera);
  if (view->ground_truth)
    ground_truth_drawn_.Add(odometry->stamp.sensor_time_s, *view->ground_truth);
  if (scene_ != nullptr) {
    scene_->SetTrajectory(kEstimateLayer, estimate_, QColor(255, 80, 80), 3.0);
    if (!ground_truth_drawn_.empty()) {
      scene_->SetTrajectory(kGroundTruthLayer, ground_truth_drawn_, QColor(80, 160, 255), 2.0);
    }
    scene_->SetFrusta(kCameraLayer, {odometry->world_from_camera}, QColor(255, 80, 80), 1.0);
    std::vector<SceneView::Key> keys = {{QColor(255, 80, 80), tr("estimate and camera")}};
    if (!ground_truth_drawn_.empty()) keys.push_back({QColor(80, 160, 255), tr("ground truth")});
    scene_->SetKeys(keys);
    FitViewIfGrown();
  }
  PlotStatistics(*view);
}

void StereoVoPresenter::DrawImages(const std::shared_ptr<const StereoOdometryResult>& odometry) {
  tracks_view_->SetImage(odometry->left_rectified);
  tracks_view_->SetKeys({{RoleColor(FeatureRole::kInlier), tr("inlier track")},
                         {RoleColor(FeatureRole::kOutlier), tr("outlier track")},
                         {RoleColor(FeatureRole::kNew), tr("new feature")}});
  tracks_view_->SetOverlayPainter([odometry](QPainter& painter, const QTransform& to_widget) {
    for (const TrackedFeature& f : odometry->features) {
      painter.setPen(QPen(RoleColor(f.role), 1.5));
      const QPointF now = to_widget.map(QPointF(f.left.x, f.left.y));
      if (f.role != FeatureRole::kNew) {
        painter.drawLine(to_widget.map(QPointF(f.previous_left.x, f.previous_left.y)), now);
      }
      painter.drawEllipse(now, 2.5, 2.5);
    }
  });
  matches_view_->SetImage(odometry->right_rectified);
  matches_view_->SetKeys({{QColor(255, 200, 0), tr("stereo match")}});
  matches_view_->SetOverlayPainter([odometry](QPainter& painter, const QTransform& to_widget) {
    painter.setPen(QPen(QColor(255, 200, 0), 1.5));
    for (const TrackedFeature& f : odometry->features) {
      painter.drawEllipse(to_widget.map(QPointF(f.right.x, f.right.y)), 2.5, 2.5);
    }
  });
}

void StereoVoPresenter::ShowSummary(const StereoVoResult& r) {
  stats_label_->setText(
      tr("tracked %1, new %2, stereo %3, inliers %4, RANSAC %5 it., residual %6 %7, %8 %9%10")
          .arg(Value(r, "vo/tracked"))
          .arg(Value(r, "vo/new_features"))
          .arg(Value(r, "vo/stereo_matches"))
          .arg(Value(r, "vo/inliers"))
          .arg(Value(r, "vo/ransac_iterations"))
          .arg(Value(r, "vo/residual_px"), 0, 'f', 2)
          .arg(Unit("vo/residual_px"))
          .arg(Value(r, "vo/total_ms"), 0, 'f', 1)
          .arg(Unit("vo/total_ms"))
          .arg(Value(r, "vo/gated") != 0 ? tr(", GATED: pose held") : QString()));
}

void StereoVoPresenter::PlotStatistics(const StereoVoResult& r) {
  const double x = static_cast<double>(r.stamp.sequence_id);
  for (const Series& s : kCountSeries)
    counts_plot_->Append(tr(s.label), x, Value(r, s.key), s.color);
  for (const Series& s : kTimingSeries)
    timing_plot_->Append(tr(s.label), x, Value(r, s.key), s.color);
  residual_plot_->Append(tr("residual"), x, Value(r, "vo/residual_px"), QColor(255, 200, 0));
  if (Value(r, "vo/gated") != 0) {
    counts_plot_->AddMarker(x);
    residual_plot_->AddMarker(x);
  }
}

void StereoVoPresenter::FitViewIfGrown() {
  Eigen::AlignedBox3d box;
  for (const Trajectory* t : {&estimate_, &ground_truth_drawn_}) {
    for (const TimedPose& p : t->poses()) box.extend(p.world_from_sensor.translation());
  }
  // View > Follow off: the user's own view stays.
  if (!scene_->follow() || box.isEmpty() || fitted_box_.contains(box)) return;
  // Fit with a margin of a quarter of the extent (at least 2 m) so that a growing trajectory
  // re-fits every few metres rather than every frame.
  const Eigen::Vector3d margin =
      (0.25 * (box.max() - box.min())).cwiseMax(Eigen::Vector3d::Constant(2.0));
  fitted_box_ = Eigen::AlignedBox3d(box.min() - margin, box.max() + margin);
  scene_->ResetView();
  ++view_fits_;
}

}  // namespace sightline
