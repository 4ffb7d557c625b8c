// Monocular SLAM in the GUI ("PTAM point cloud"): the image with tracked features and the
// tracking quality, the map points (coloured by the keyframe that made them), keyframe frusta,
// the camera's trajectory and the current camera growing in the 3D view, and a scale panel with
// the single-ratio and maximum-likelihood estimates and their convergence plot. Draw-only: the
// registry's "mono-slam" pipeline computes everything; Reset map and Pause mapping reach it as
// commands (MonoSlamCommands).
#pragma once

#include <QString>
#include <atomic>
#include <cstdint>
#include <memory>

#include "app/sightline/pipeline_presenter.h"
#include "core/common/trajectory.h"
#include "core/pipeline/mono_slam_result.h"

class QDockWidget;
class QLabel;
class QPushButton;

namespace sightline {

class ImageView;
class SceneView;
class ScalePlot;

// Presenter of the "mono-slam" pipeline (seed 004). Needs mono frames or a stereo pair's left.
class MonoSlamPresenter : public PipelinePresenter {
  Q_OBJECT

 public:
  explicit MonoSlamPresenter(QObject* parent = nullptr);

  const char* TitleSource() const override;
  void Attach(QMainWindow* window) override;
  void Detach() override;
  void Show(const PlaybackResult& result) override;

  // For tests: the image view, map points and keyframes last drawn, the scale estimate.
  const ImageView* image_view() const { return image_view_; }
  size_t points_drawn() const { return points_drawn_; }
  size_t keyframes_drawn() const { return keyframes_drawn_; }
  double scale_ml() const { return scale_ml_; }

 protected:
  // A presenter of pipeline `info` whose objects take `commands` (the button picker's).
  MonoSlamPresenter(PipelineInfo info, std::shared_ptr<MonoSlamCommands> commands, QObject* parent);

 private:
  MonoSlamPresenter(std::shared_ptr<MonoSlamCommands> commands, QObject* parent);
  // The map, keyframes, trajectory and camera in the 3D view, in metres when the scale is known
  // (`divide` map units per metre); the view follows the growing path.
  void DrawScene(const MonoSlamFrameResult& view, double divide);

  std::shared_ptr<MonoSlamCommands> commands_;
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
