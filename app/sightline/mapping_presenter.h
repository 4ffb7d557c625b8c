// Indoor Manhattan mapping in the GUI: the occupancy image with scan rays and wall lines
// (coloured by Manhattan direction), and the stitched map growing with the trajectory.
#pragma once

#include <string>

#include "app/sightline/pipeline_presenter.h"

class QDockWidget;

namespace sightline {

class ImageView;

// Presenter of the "mapping" pipeline (seed 000). Needs RGB-D frames.
class MappingPresenter : public PipelinePresenter {
  Q_OBJECT

 public:
  explicit MappingPresenter(QObject* parent = nullptr);

  QString Title() const override;
  Status DeclareOptions(OptionSet* options) const override;
  bool Accepts(SourceKind kind) const override;
  std::unique_ptr<FrameProcessor> CreateProcessor(const SourceInfo& info) override;
  void Attach(QMainWindow* window) override;
  void Detach() override;
  void Show(const PlaybackResult& result) override;

  // The views, for tests.
  const ImageView* occupancy_view() const { return occupancy_view_; }
  const ImageView* map_view() const { return map_view_; }

 private:
  QDockWidget* occupancy_dock_ = nullptr;
  QDockWidget* map_dock_ = nullptr;
  ImageView* occupancy_view_ = nullptr;
  ImageView* map_view_ = nullptr;
  std::string last_status_ = "ok";
};

}  // namespace sightline
