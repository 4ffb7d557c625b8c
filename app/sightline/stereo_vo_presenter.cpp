#include "app/sightline/stereo_vo_presenter.h"

#include <QDockWidget>
#include <QLabel>
#include <QMainWindow>
#include <QPainter>
#include <QVBoxLayout>

#include "core/io/dataset.h"
#include "core/stereo/stereo_odometry.h"
#include "widgets/image_view.h"
#include "widgets/scene_view.h"
#include "widgets/time_series_plot.h"

namespace sightline {

namespace {

// What the stereo processor hands the GUI for one frame.
struct StereoViewResult : PipelineFrameResult {
  std::shared_ptr<const StereoOdometryResult> odometry;
  std::optional<Eigen::Isometry3d> ground_truth;  // world_from_camera, in the estimate's frame.
};

// Runs StereoOdometry on the playback worker. The estimate starts at the first frame's camera;
// ground truth is re-expressed relative to that frame so both share one frame in the 3D view.
class StereoVoProcessor : public FrameProcessor {
 public:
  StereoVoProcessor(SourceInfo info, std::shared_ptr<const Trajectory> ground_truth)
      : info_(std::move(info)), ground_truth_(std::move(ground_truth)) {}

  Status Configure(const OptionSet& options) override {
    StereoOdometryOptions parsed = options.Extract(StereoOdometryOptions::Describe());
    if (!info_.stereo) {
      return FailedPrecondition(info_.path +
                                ": no stereo calibration; open a live pair with one, "
                                "aravis://LEFT,RIGHT?calibration_file=FILE");
    }
    auto odometry = std::make_unique<StereoOdometry>(parsed);
    SIGHTLINE_RETURN_IF_ERROR(odometry->Configure(*info_.stereo));
    odometry_ = std::move(odometry);
    first_gt_.reset();
    return Status::Ok();
  }

  std::shared_ptr<const PipelineFrameResult> ProcessFrame(const Frame& frame) override {
    auto result = std::make_shared<StereoViewResult>();
    result->stamp = StampOf(frame);
    const auto* stereo = std::get_if<StereoFrame>(&frame);
    if (stereo == nullptr || !odometry_) {
      result->status = FailedPrecondition("stereo odometry needs stereo frames");
      return result;
    }
    StatusOr<std::shared_ptr<const StereoOdometryResult>> r = odometry_->Process(*stereo);
    if (!r.ok()) {
      result->status = r.status();
      return result;
    }
    result->odometry = *r;
    const FrameStats& s = (*r)->stats;
    result->stats = {{"vo/tracked", double(s.tracked)},
                     {"vo/inliers", double(s.inliers)},
                     {"vo/ransac_iterations", double(s.ransac_iterations)},
                     {"vo/residual_px", s.residual_px}};
    if (ground_truth_) {
      if (auto i = ground_truth_->Nearest(stereo->stamp.sensor_time_s, 0.02)) {
        const Eigen::Isometry3d& world_from_camera = ground_truth_->poses()[*i].world_from_sensor;
        if (!first_gt_) first_gt_ = world_from_camera;
        result->ground_truth = first_gt_->inverse() * world_from_camera;
      }
    }
    return result;
  }

  // Odometry integrates motion: a re-run restarts it from the current frame.
  std::shared_ptr<const PipelineFrameResult> ReprocessFrame(const Frame& frame) override {
    Reset();
    return ProcessFrame(frame);
  }

  void Reset() override {
    if (odometry_) odometry_->Reset();
    first_gt_.reset();
  }

 private:
  SourceInfo info_;
  std::shared_ptr<const Trajectory> ground_truth_;
  std::unique_ptr<StereoOdometry> odometry_;
  std::optional<Eigen::Isometry3d> first_gt_;
};

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

}  // namespace

StereoVoPresenter::StereoVoPresenter(QObject* parent) : PipelinePresenter(parent) {}

const char* StereoVoPresenter::TitleSource() const { return QT_TR_NOOP("Stereo visual odometry"); }

Status StereoVoPresenter::DeclareOptions(OptionSet* options) const {
  return options->Declare(StereoOdometryOptions::Describe());
}

bool StereoVoPresenter::Accepts(SourceKind kind) const { return kind == SourceKind::kStereo; }

std::unique_ptr<Pipeline> StereoVoPresenter::CreateProcessor(const PipelineSource& source) {
  const SourceInfo& info = source.info;
  // The recording's ground truth, if any, to draw beside the estimate.
  std::shared_ptr<const Trajectory> ground_truth;
  if (info.has_ground_truth && !info.live) {
    StatusOr<std::unique_ptr<Source>> source = OpenDataset(info.path, SourceKind::kStereo);
    if (source.ok() && (*source)->ground_truth() != nullptr) {
      ground_truth = std::make_shared<const Trajectory>(*(*source)->ground_truth());
    }
  }
  return std::make_unique<StereoVoProcessor>(info, std::move(ground_truth));
}

void StereoVoPresenter::Attach(QMainWindow* window) {
  if (tracks_dock_ == nullptr) {
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
    counts_plot_ = new TimeSeriesPlot(tr("per frame: counts"), plots);
    timing_plot_ = new TimeSeriesPlot(tr("ms per stage"), plots);
    residual_plot_ = new TimeSeriesPlot(tr("residual [px]; red: gated"), plots);
    for (TimeSeriesPlot* plot : {counts_plot_, timing_plot_, residual_plot_}) {
      plot->SetCapacity(300);
      plots_layout->addWidget(plot, 1);
    }
    stats_dock_ = new QDockWidget(tr("Statistics over time"), window);
    stats_dock_->setObjectName("vo_stats_dock");
    stats_dock_->setWidget(plots);
  }
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
  }
}

void StereoVoPresenter::Show(const PlaybackResult& result) {
  const auto* view = dynamic_cast<const StereoViewResult*>(result.pipeline.get());
  if (view == nullptr || tracks_view_ == nullptr || !view->odometry) return;
  const std::shared_ptr<const StereoOdometryResult> odometry = view->odometry;
  // A jump back (seek, loop) starts the drawn trajectories over, as the processor does.
  if (odometry->stamp.sequence_id <= last_id_) {
    estimate_ = Trajectory();
    ground_truth_drawn_ = Trajectory();
    for (TimeSeriesPlot* plot : {counts_plot_, timing_plot_, residual_plot_}) plot->Clear();
    fitted_box_.setEmpty();
  }
  last_id_ = odometry->stamp.sequence_id;

  tracks_view_->SetImage(odometry->left_rectified);
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
  matches_view_->SetOverlayPainter([odometry](QPainter& painter, const QTransform& to_widget) {
    painter.setPen(QPen(QColor(255, 200, 0), 1.5));
    for (const TrackedFeature& f : odometry->features) {
      painter.drawEllipse(to_widget.map(QPointF(f.right.x, f.right.y)), 2.5, 2.5);
    }
  });
  const FrameStats& s = odometry->stats;
  stats_label_->setText(tr("tracked %1, new %2, stereo %3, inliers %4, RANSAC %5 it., residual "
                           "%6 px, %7 ms%8")
                            .arg(s.tracked)
                            .arg(s.new_features)
                            .arg(s.stereo_matches)
                            .arg(s.inliers)
                            .arg(s.ransac_iterations)
                            .arg(s.residual_px, 0, 'f', 2)
                            .arg(s.total_ms, 0, 'f', 1)
                            .arg(s.gated ? tr(", GATED: pose held") : QString()));

  estimate_.Add(odometry->stamp.sensor_time_s, odometry->world_from_camera);
  if (view->ground_truth)
    ground_truth_drawn_.Add(odometry->stamp.sensor_time_s, *view->ground_truth);
  if (scene_ != nullptr) {
    scene_->SetTrajectory(kEstimateLayer, estimate_, QColor(255, 80, 80), 3.0);
    if (!ground_truth_drawn_.empty()) {
      scene_->SetTrajectory(kGroundTruthLayer, ground_truth_drawn_, QColor(80, 160, 255), 2.0);
    }
    scene_->SetFrusta(kCameraLayer, {odometry->world_from_camera}, QColor(255, 80, 80), 1.0);
    FitViewIfGrown();
  }
  PlotStatistics(odometry->stamp.sequence_id, s);
}

void StereoVoPresenter::PlotStatistics(int64_t frame, const FrameStats& s) {
  const double x = static_cast<double>(frame);
  counts_plot_->Append(tr("tracks"), x, s.tracked, QColor(60, 120, 255));
  counts_plot_->Append(tr("anchored"), x, s.anchored, QColor(0, 200, 200));
  counts_plot_->Append(tr("stereo"), x, s.stereo_matches, QColor(255, 200, 0));
  counts_plot_->Append(tr("inliers"), x, s.inliers, QColor(40, 220, 40));
  counts_plot_->Append(tr("RANSAC it."), x, s.ransac_iterations, QColor(230, 120, 230));
  const std::pair<QString, double> stages[] = {
      {tr("rectify"), s.rectify_ms},   {tr("pyramid"), s.pyramid_ms},
      {tr("tracking"), s.tracking_ms}, {tr("detection"), s.detection_ms},
      {tr("matching"), s.matching_ms}, {tr("RANSAC"), s.ransac_ms},
      {tr("refine"), s.refine_ms},     {tr("window BA"), s.window_ms},
      {tr("total"), s.total_ms}};
  const QColor colors[] = {QColor(150, 150, 150), QColor(0, 200, 200), QColor(60, 120, 255),
                           QColor(255, 140, 0),   QColor(255, 200, 0), QColor(230, 120, 230),
                           QColor(40, 220, 40),   QColor(200, 80, 80), QColor(240, 240, 240)};
  for (size_t i = 0; i < std::size(stages); ++i) {
    timing_plot_->Append(stages[i].first, x, stages[i].second, colors[i]);
  }
  residual_plot_->Append(tr("residual"), x, s.residual_px, QColor(255, 200, 0));
  if (s.gated) {
    counts_plot_->AddMarker(x);
    residual_plot_->AddMarker(x);
  }
}

void StereoVoPresenter::FitViewIfGrown() {
  Eigen::AlignedBox3d box;
  for (const Trajectory* t : {&estimate_, &ground_truth_drawn_}) {
    for (const TimedPose& p : t->poses()) box.extend(p.world_from_sensor.translation());
  }
  if (box.isEmpty() || fitted_box_.contains(box)) return;
  // Fit with a margin of a quarter of the extent (at least 2 m) so that a growing trajectory
  // re-fits every few metres rather than every frame.
  const Eigen::Vector3d margin =
      (0.25 * (box.max() - box.min())).cwiseMax(Eigen::Vector3d::Constant(2.0));
  fitted_box_ = Eigen::AlignedBox3d(box.min() - margin, box.max() + margin);
  scene_->ResetView();
  ++view_fits_;
}

}  // namespace sightline
