#include "app/sightline/statistics_presenter.h"

#include <QDockWidget>
#include <QHeaderView>
#include <QMainWindow>
#include <QStandardItemModel>
#include <QTableView>

namespace sightline {

StatisticsPresenter::StatisticsPresenter(PipelineInfo info, QObject* parent)
    : PipelinePresenter(std::move(info), parent),
      title_(this->info().title.empty() ? this->info().name : this->info().title) {
  if (this->info().create) {
    if (std::unique_ptr<Pipeline> pipeline = this->info().create()) {
      statistics_ = pipeline->Statistics();
    }
  }
}

void StatisticsPresenter::Attach(QMainWindow* window) {
  if (dock_ == nullptr) {
    model_ = new QStandardItemModel(0, 4, this);
    model_->setHorizontalHeaderLabels({tr("Statistic"), tr("Value"), tr("Unit"), tr("Meaning")});
    view_ = new QTableView(window);
    view_->setModel(model_);
    view_->verticalHeader()->hide();
    view_->horizontalHeader()->setStretchLastSection(true);
    view_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    dock_ = new QDockWidget(tr("Statistics: %1").arg(Title()), window);
    dock_->setObjectName(QString::fromStdString("statistics_dock_" + info().name));
    dock_->setWidget(view_);
  }
  window->addDockWidget(Qt::RightDockWidgetArea, dock_);
  dock_->show();
}

void StatisticsPresenter::Detach() {
  if (dock_ != nullptr) dock_->hide();
}

void StatisticsPresenter::Show(const PlaybackResult& result) {
  if (model_ == nullptr || !result.pipeline) return;
  model_->removeRows(0, model_->rowCount());
  for (const auto& [key, value] : result.pipeline->stats) {
    const StatisticInfo* stat = FindStatistic(statistics_, key);
    model_->appendRow(
        {new QStandardItem(QString::fromStdString(key)),
         new QStandardItem(QString::number(value, 'g', 6)),
         new QStandardItem(stat ? QString::fromStdString(stat->unit) : QString()),
         new QStandardItem(stat ? QString::fromStdString(stat->description) : QString())});
  }
  if (!result.pipeline->status.ok()) {
    model_->appendRow({new QStandardItem(tr("status")),
                       new QStandardItem(QString::fromStdString(result.pipeline->status.message())),
                       new QStandardItem(), new QStandardItem()});
  }
}

}  // namespace sightline
