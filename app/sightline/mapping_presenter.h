// Indoor Manhattan mapping in the GUI: the occupancy image with scan rays and wall lines
// (coloured by Manhattan direction), and the stitched map growing with the trajectory.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/sightline/pipeline_presenter.h"
#include "core/common/floor.h"
#include "core/pipeline/mapping_result.h"

class QDockWidget;
class QLabel;

namespace sightline {

class ImageView;
class SceneView;

// Presenter of the "mapping" pipeline (seed 000): draws the results of the registry's
// MappingPipeline (core/pipeline/mapping_pipeline.h), the object `sightline-cli run mapping`
// runs. Needs RGB-D frames.
class MappingPresenter : public PipelinePresenter {
  Q_OBJECT

 public:
  explicit MappingPresenter(QObject* parent = nullptr);

  const char* TitleSource() const override;
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
  // Names of the 3D layers it draws (walls by Manhattan class, the floor grid, the stitched map
  // as a textured plane on the floor and the path over it).
  static std::vector<std::string> SceneLayers();

 private:
  MappingPresenter(std::shared_ptr<MappingRequests> requests, QObject* parent);
  // The stitched map and path in the 3D view when the frame carries a new map; every frame, their
  // place seen from the frame's camera.
  void ShowStitchedMap(const MappingFrameResult& mapping);

  QDockWidget* occupancy_dock_ = nullptr;
  QDockWidget* map_dock_ = nullptr;
  ImageView* occupancy_view_ = nullptr;
  ImageView* map_view_ = nullptr;
  QLabel* figures_ = nullptr;   // The frame's statistics with their units.
  SceneView* scene_ = nullptr;  // The window's 3D view: walls and floor beside the cloud.
  std::string last_status_ = "ok";
  // Shared with the pipeline on the worker thread ("Calibrate floor").
  std::shared_ptr<MappingRequests> requests_;
  std::optional<FloorPlane> floor_;  // The calibration of the last shown frame.
};

}  // namespace sightline
