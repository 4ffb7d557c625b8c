// Stereo visual odometry in the GUI: the left image with tracks (inliers green, outliers red,
// new blue), the right image with stereo matches, and the trajectory growing in the 3D view
// beside the ground truth.
#pragma once

#include <Eigen/Geometry>
#include <QString>
#include <cstdint>
#include <memory>

#include "app/sightline/pipeline_presenter.h"
#include "core/common/trajectory.h"

class QDockWidget;
class QLabel;

namespace sightline {

class ImageView;
class SceneView;
class TimeSeriesPlot;
struct StereoOdometryResult;
struct StereoVoResult;

// Presenter of the "stereo-vo" pipeline (seed 003): draws StereoVoPipeline's results.
class StereoVoPresenter : public PipelinePresenter {
  Q_OBJECT

 public:
  // The registry's "stereo-vo" entry: its options, sources and pipeline object.
  explicit StereoVoPresenter(QObject* parent = nullptr);

  const char* TitleSource() const override;
  void Attach(QMainWindow* window) override;
  void Detach() override;
  void Show(const PlaybackResult& result) override;

  // For tests: the views, and the estimated trajectory drawn so far.
  const ImageView* tracks_view() const { return tracks_view_; }
  const Trajectory& estimate() const { return estimate_; }
  // Per-frame statistics over time: counts (tracks, stereo matches, inliers, RANSAC
  // iterations), milliseconds per stage, and the residual with gated frames as markers.
  const TimeSeriesPlot* counts_plot() const { return counts_plot_; }
  const TimeSeriesPlot* timing_plot() const { return timing_plot_; }
  const TimeSeriesPlot* residual_plot() const { return residual_plot_; }
  // The 3D view is re-fitted whenever the trajectories leave the box it was last fitted to;
  // that box (min and max corner, world frame) and how often it happened.
  const Eigen::AlignedBox3d& fitted_box() const { return fitted_box_; }
  int view_fits() const { return view_fits_; }

 private:
  // Creates the docks, views and plots on the first Attach.
  void CreateViews(QMainWindow* window);
  // Draws the rectified images with the tracks and the stereo matches.
  void DrawImages(const std::shared_ptr<const StereoOdometryResult>& odometry);
  // The one-line summary above the tracks, from the frame's named statistics.
  void ShowSummary(const StereoVoResult& result);
  // Appends one frame's named statistics to the plots.
  void PlotStatistics(const StereoVoResult& result);
  // Re-fits the 3D view when the drawn trajectories leave the last fitted box.
  void FitViewIfGrown();

  QDockWidget* tracks_dock_ = nullptr;
  QDockWidget* stats_dock_ = nullptr;
  TimeSeriesPlot* counts_plot_ = nullptr;
  TimeSeriesPlot* timing_plot_ = nullptr;
  TimeSeriesPlot* residual_plot_ = nullptr;
  Eigen::AlignedBox3d fitted_box_;
  int view_fits_ = 0;
  QDockWidget* matches_dock_ = nullptr;
  ImageView* tracks_view_ = nullptr;
  ImageView* matches_view_ = nullptr;
  QLabel* stats_label_ = nullptr;
  SceneView* scene_ = nullptr;
  Trajectory estimate_;
  Trajectory ground_truth_drawn_;
  int64_t last_id_ = -1;
};

}  // namespace sightline
