#include "app/sightline/mobility_views.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

#include "core/mobility/mobility_map.h"
#include "widgets/image_view.h"

namespace sightline {

MobilityTimingPanel::MobilityTimingPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  auto* row = new QHBoxLayout();
  row->addWidget(new QLabel(tr("3D colour:"), this));
  color_choice_ = new QComboBox(this);
  color_choice_->addItems({tr("Score (rule)"), tr("Score (GPR)"), tr("Segment")});
  row->addWidget(color_choice_);
  row->addStretch(1);
  layout->addLayout(row);
  summary_ = new QLabel(this);
  summary_->setWordWrap(true);
  layout->addWidget(summary_);
  table_ = new QTableWidget(0, 3, this);
  table_->setHorizontalHeaderLabels({tr("Stage"), tr("Time (ms)"), tr("Points")});
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  table_->verticalHeader()->setVisible(false);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  layout->addWidget(table_, 1);
}

void MobilityTimingPanel::Show(const MobilityFrameResult& frame) {
  const MobilityResult& result = *frame.mobility;
  table_->setRowCount(static_cast<int>(result.stages.size()) + 1);
  int row = 0;
  double total_ms = 0;
  for (const StageReport& s : result.stages) {
    const double ms = frame.Stat("mobility/" + s.name + "_ms").value_or(0);
    const double points = frame.Stat("mobility/" + s.name + "_points").value_or(0);
    total_ms += ms;
    table_->setItem(row, 0, new QTableWidgetItem(QString::fromStdString(s.name)));
    table_->setItem(row, 1, new QTableWidgetItem(QString::number(ms, 'f', 2)));
    table_->setItem(row, 2, new QTableWidgetItem(QString::number(points, 'f', 0)));
    ++row;
  }
  table_->setItem(row, 0, new QTableWidgetItem(tr("Total")));
  table_->setItem(row, 1, new QTableWidgetItem(QString::number(total_ms, 'f', 2)));
  table_->setItem(row, 2, new QTableWidgetItem(QString()));
  QString text = tr("%1 mode, %2 segments")
                     .arg(QString::fromStdString(result.mode))
                     .arg(frame.Stat("mobility/segments").value_or(0));
  if (const auto height = frame.Stat("mobility/ground_height_m")) {
    text += tr(", camera %1 m above the ground").arg(*height, 0, 'f', 3);
  }
  if (!result.status.ok()) text += "\n" + QString::fromStdString(result.status.message());
  summary_->setText(text);
}

MobilityImagePanel::MobilityImagePanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* tabs = new QTabWidget(this);
  projection_ = new ImageView(tabs);
  top_ = new ImageView(tabs);
  surface_ = new ImageView(tabs);
  tabs->addTab(projection_, tr("Projection"));
  tabs->addTab(top_, tr("Top view"));
  tabs->addTab(surface_, tr("GPR surface"));
  layout->addWidget(tabs);
}

void MobilityImagePanel::Show(const MobilityResult& result) {
  // The score colours, as core's ScoreColorBgr draws them.
  const auto colour = [](float score) {
    const cv::Vec3b bgr = ScoreColorBgr(score);
    return QColor(bgr[2], bgr[1], bgr[0]);
  };
  const std::vector<ImageView::Key> keys = {{colour(0.f), tr("score 0: not passable")},
                                            {colour(0.5f), tr("score 0.5")},
                                            {colour(1.f), tr("score 1: passable")},
                                            {colour(NAN), tr("not scored")}};
  for (ImageView* view : {projection_, top_}) view->SetKeys(keys);
  if (!result.projection.empty()) projection_->SetImage(result.projection);
  if (result.ground.found) top_->SetImage(RenderTopView(result.map));
}

void MobilityImagePanel::SetScoreSurface(const cv::Mat& image) { surface_->SetImage(image); }

}  // namespace sightline
