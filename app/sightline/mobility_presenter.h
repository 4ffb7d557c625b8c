// The mobility map in the GUI (seed 001): the cloud coloured by score or by segment in 3D, the
// scores projected on the colour image, the top-view grid, the GPR score surface and the
// per-stage timing table, updated every frame; option changes re-run the current frame.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "app/sightline/pipeline_presenter.h"

class QDockWidget;

namespace sightline {

class MobilityImagePanel;
class MobilityTimingPanel;
class SceneView;

// Presenter of the "mobility" pipeline: draws the results of the registry's MobilityPipeline
// (core/pipeline/mobility_pipeline.h), the object `sightline-cli run mobility` runs. Needs
// RGB-D frames or point clouds.
class MobilityPresenter : public PipelinePresenter {
  Q_OBJECT

 public:
  explicit MobilityPresenter(QObject* parent = nullptr);

  const char* TitleSource() const override;
  void Attach(QMainWindow* window) override;
  void Detach() override;
  void Show(const PlaybackResult& result) override;

  // The views, for tests.
  const MobilityImagePanel* images() const { return images_; }
  const MobilityTimingPanel* timing() const { return timing_; }
  // Names of the 3D layers it draws.
  static std::vector<std::string> SceneLayers();

 private:
  void ApplyColorChoice();

  QDockWidget* images_dock_ = nullptr;
  QDockWidget* timing_dock_ = nullptr;
  MobilityImagePanel* images_ = nullptr;
  MobilityTimingPanel* timing_ = nullptr;
  SceneView* scene_ = nullptr;
};

}  // namespace sightline
