// Indoor Manhattan mapping in the GUI: the occupancy image with scan rays and wall lines
// (coloured by Manhattan direction), and the stitched map growing with the trajectory.
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>

#include "app/sightline/pipeline_presenter.h"
#include "core/common/floor.h"

class QDockWidget;

namespace sightline {

class ImageView;
class SceneView;

// Presenter of the "mapping" pipeline (seed 000). Needs RGB-D frames.
class MappingPresenter : public PipelinePresenter {
  Q_OBJECT

 public:
  explicit MappingPresenter(QObject* parent = nullptr);

  const char* TitleSource() const override;
  Status DeclareOptions(OptionSet* options) const override;
  bool Accepts(SourceKind kind) const override;
  std::unique_ptr<Pipeline> CreateProcessor(const PipelineSource& source) override;
  void Attach(QMainWindow* window) override;
  void Detach() override;
  void Show(const PlaybackResult& result) override;

  // Fits the floor again from the next frames ("Calibrate floor").
  void RecalibrateFloor();
  // Writes the floor calibration in use to a file that mapping.run.floor_file can name.
  Status SaveFloor(const QString& path);

  // The views, for tests.
  const ImageView* occupancy_view() const { return occupancy_view_; }
  const ImageView* map_view() const { return map_view_; }
  // Names of the 3D layers it draws (walls by Manhattan class, the floor grid).
  static std::vector<std::string> SceneLayers();

 private:
  QDockWidget* occupancy_dock_ = nullptr;
  QDockWidget* map_dock_ = nullptr;
  ImageView* occupancy_view_ = nullptr;
  ImageView* map_view_ = nullptr;
  SceneView* scene_ = nullptr;  // The window's 3D view: walls and floor beside the cloud.
  std::string last_status_ = "ok";
  // Shared with the processor on the worker thread: bumped to ask for a new floor fit.
  std::shared_ptr<std::atomic<int>> recalibrations_ = std::make_shared<std::atomic<int>>(0);
  std::optional<FloorPlane> floor_;  // The calibration of the last shown frame.
};

}  // namespace sightline
