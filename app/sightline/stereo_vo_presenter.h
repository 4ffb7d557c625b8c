// Stereo visual odometry in the GUI: the left image with tracks (inliers green, outliers red,
// new blue), the right image with stereo matches, and the trajectory growing in the 3D view
// beside the ground truth.
#pragma once

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

// Presenter of the "stereo-vo" pipeline (seed 003). Needs stereo frames.
class StereoVoPresenter : public PipelinePresenter {
  Q_OBJECT

 public:
  explicit StereoVoPresenter(QObject* parent = nullptr);

  QString Title() const override;
  Status DeclareOptions(OptionSet* options) const override;
  bool Accepts(SourceKind kind) const override;
  std::unique_ptr<FrameProcessor> CreateProcessor(const SourceInfo& info) override;
  void Attach(QMainWindow* window) override;
  void Detach() override;
  void Show(const PlaybackResult& result) override;

  // For tests: the views, and the estimated trajectory drawn so far.
  const ImageView* tracks_view() const { return tracks_view_; }
  const Trajectory& estimate() const { return estimate_; }

 private:
  QDockWidget* tracks_dock_ = nullptr;
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
