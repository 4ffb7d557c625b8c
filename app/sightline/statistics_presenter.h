// The views of a pipeline that draws no pictures of its own (e.g. `inspect`): the window's
// image and 3D views show the frames as always, and a dock lists the pipeline's named
// statistics of the current frame with their units and meanings.
#pragma once

#include <memory>

#include "app/sightline/pipeline_presenter.h"

class QDockWidget;
class QStandardItemModel;
class QTableView;

namespace sightline {

// A presenter made from a registry entry alone.
class StatisticsPresenter : public PipelinePresenter {
  Q_OBJECT

 public:
  explicit StatisticsPresenter(PipelineInfo info, QObject* parent = nullptr);

  const char* TitleSource() const override { return title_.c_str(); }
  void Attach(QMainWindow* window) override;
  void Detach() override;
  void Show(const PlaybackResult& result) override;

  // For tests: the table's rows (statistic key, value, unit, meaning).
  const QStandardItemModel* table() const { return model_; }

 private:
  std::string title_;
  StatisticTable statistics_;  // The pipeline's table, read once.
  QDockWidget* dock_ = nullptr;
  QTableView* view_ = nullptr;
  QStandardItemModel* model_ = nullptr;
};

}  // namespace sightline
