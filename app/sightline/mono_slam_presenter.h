// Monocular SLAM in the GUI ("PTAM point cloud"): the image with tracked features and the
// tracking quality, the map points (coloured by the keyframe that made them), keyframe frusta,
// the camera's trajectory and the current camera growing in the 3D view, and a scale panel with
// the single-ratio and maximum-likelihood estimates and their convergence plot. Reset map and
// Pause mapping reach the worker as atomic requests.
#pragma once

#include <QString>
#include <atomic>
#include <cstdint>
#include <memory>

#include "app/sightline/pipeline_presenter.h"
#include "core/common/trajectory.h"
#include "core/mono/mono_slam.h"
#include "core/mono/scale_estimator.h"

class QDockWidget;
class QLabel;
class QPushButton;

namespace sightline {

class ImageView;
class SceneView;
class ScalePlot;

// Requests from the GUI thread to the processor on the worker thread.
struct MonoSlamControls {
  std::atomic<bool> reset{false};          // Forget the map at the next frame.
  std::atomic<bool> pause_mapping{false};  // No new keyframes while set.
};

// What the mono processor hands the GUI for one frame.
struct MonoViewResult : PipelineFrameResult {
  std::shared_ptr<const MonoSlamResult> slam;
  std::shared_ptr<const std::vector<ScaleSample>> scale_history;  // Null when unchanged.
  double lambda = 0;  // ML map units per metre, 0 = unknown.
  double single_ratio = 0;
  std::string metric_source;  // "arm", "ground_truth" or "none".
};

// Presenter of the "mono-slam" pipeline (seed 004). Needs mono frames or a stereo pair's left.
class MonoSlamPresenter : public PipelinePresenter {
  Q_OBJECT

 public:
  explicit MonoSlamPresenter(QObject* parent = nullptr);

  const char* TitleSource() const override;
  Status DeclareOptions(OptionSet* options) const override;
  bool Accepts(SourceKind kind) const override;
  std::unique_ptr<Pipeline> CreateProcessor(const PipelineSource& source) override;
  void Attach(QMainWindow* window) override;
  void Detach() override;
  void Show(const PlaybackResult& result) override;

  // For tests: the image view, map points and keyframes last drawn, the scale estimate.
  const ImageView* image_view() const { return image_view_; }
  size_t points_drawn() const { return points_drawn_; }
  size_t keyframes_drawn() const { return keyframes_drawn_; }
  double scale_ml() const { return scale_ml_; }

 private:
  std::shared_ptr<MonoSlamControls> controls_ = std::make_shared<MonoSlamControls>();
  QDockWidget* image_dock_ = nullptr;
  QDockWidget* scale_dock_ = nullptr;
  ImageView* image_view_ = nullptr;
  QLabel* status_label_ = nullptr;
  QLabel* scale_label_ = nullptr;
  ScalePlot* scale_plot_ = nullptr;
  QPushButton* pause_button_ = nullptr;
  SceneView* scene_ = nullptr;
  Trajectory trajectory_;  // Map units.
  int64_t last_id_ = -1;
  size_t points_drawn_ = 0, keyframes_drawn_ = 0;
  double scale_ml_ = 0;
};

}  // namespace sightline
