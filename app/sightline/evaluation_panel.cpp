#include "app/sightline/evaluation_panel.h"

#include <QComboBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QPushButton>
#include <QScrollArea>
#include <QStandardItemModel>
#include <QTabWidget>
#include <QTableView>
#include <QThreadPool>
#include <QVBoxLayout>
#include <cmath>

#include "core/eval/error_report.h"
#include "core/eval/evaluation.h"
#include "core/eval/trajectory_file.h"
#include "core/eval/trajectory_plot.h"
#include "widgets/image_view.h"

namespace sightline {

// A finished evaluation: figures, plots, or the reason there are none.
struct EvaluationOutcome {
  Status status;
  std::vector<std::pair<std::string, double>> figures;
  std::vector<std::string> notes;
  size_t pairs = 0;
  double ground_truth_length_m = 0;
  cv::Mat top_view;
  cv::Mat error_over_time;
};

namespace {

std::shared_ptr<const EvaluationOutcome> RunEvaluation(const std::string& estimate_path,
                                                       const std::string& ground_truth_path,
                                                       const std::string& align) {
  auto outcome = std::make_shared<EvaluationOutcome>();
  StatusOr<Trajectory> estimate = ReadTrajectoryFile(estimate_path);
  if (!estimate.ok()) {
    outcome->status = estimate.status();
    return outcome;
  }
  StatusOr<Trajectory> ground_truth = ReadTrajectoryFile(ground_truth_path);
  if (!ground_truth.ok()) {
    outcome->status = ground_truth.status();
    return outcome;
  }
  EvaluationOptions options;
  options.align = align;
  StatusOr<TrajectoryErrors> errors = EvaluateTrajectory(*estimate, *ground_truth, options);
  if (!errors.ok()) {
    outcome->status = errors.status();
    return outcome;
  }
  outcome->figures = AccuracyFigures(*errors);
  outcome->notes = errors->notes;
  outcome->pairs = errors->pairs;
  outcome->ground_truth_length_m = errors->ground_truth_length_m;
  outcome->top_view = DrawTopView(*errors, PlotPlane::kAuto);
  outcome->error_over_time = DrawAteOverTime(*errors);
  return outcome;
}

}  // namespace

EvaluationPanel::EvaluationPanel(QWidget* parent) : QWidget(parent) {
  estimate_edit_ = new QLineEdit(this);
  estimate_edit_->setPlaceholderText(tr("estimated trajectory (TUM or KITTI file)"));
  ground_truth_edit_ = new QLineEdit(this);
  ground_truth_edit_->setPlaceholderText(tr("ground truth (TUM or KITTI file)"));
  auto with_browse = [this](QLineEdit* edit, const QString& title) {
    auto* row = new QHBoxLayout;
    row->addWidget(edit, 1);
    auto* browse = new QPushButton(tr("Browse..."), this);
    connect(browse, &QPushButton::clicked, this, [this, edit, title] {
      const QString path = Browse(title);
      if (!path.isEmpty()) edit->setText(path);
    });
    row->addWidget(browse);
    return row;
  };
  align_combo_ = new QComboBox(this);
  align_combo_->addItem(tr("SE(3): rotation and translation"), "se3");
  align_combo_->addItem(tr("Sim(3): also scale (monocular)"), "sim3");
  align_combo_->addItem(tr("None"), "none");
  run_button_ = new QPushButton(tr("Evaluate"), this);
  connect(run_button_, &QPushButton::clicked, this, [this] {
    Evaluate(estimate_edit_->text(), ground_truth_edit_->text(),
             align_combo_->currentData().toString());
  });

  auto* form = new QFormLayout;
  form->addRow(tr("Estimate"), with_browse(estimate_edit_, tr("Estimated trajectory")));
  form->addRow(tr("Ground truth"), with_browse(ground_truth_edit_, tr("Ground truth")));
  form->addRow(tr("Alignment"), align_combo_);

  summary_label_ = new QLabel(tr("Choose two trajectory files and press Evaluate."), this);
  summary_label_->setWordWrap(true);
  figures_ = new QStandardItemModel(0, 4, this);
  figures_->setHorizontalHeaderLabels({tr("Figure"), tr("Value"), tr("Unit"), tr("Meaning")});
  table_ = new QTableView(this);
  table_->setModel(figures_);
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);

  top_view_ = new ImageView(this);
  error_view_ = new ImageView(this);
  auto* tabs = new QTabWidget(this);
  tabs->addTab(table_, tr("Figures"));
  tabs->addTab(top_view_, tr("Top view"));
  tabs->addTab(error_view_, tr("Error over time"));

  // In a scroll area: the panel shares the window's right column with the log and the operator
  // panel, and must not make the window taller than a laptop's screen.
  auto* content = new QWidget(this);
  auto* layout = new QVBoxLayout(content);
  layout->addLayout(form);
  layout->addWidget(run_button_);
  layout->addWidget(summary_label_);
  layout->addWidget(tabs, 1);
  content->setMinimumHeight(content->minimumSizeHint().height());
  auto* scroll = new QScrollArea(this);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setWidget(content);
  scroll->setMinimumHeight(fontMetrics().height() * 4);
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(0, 0, 0, 0);
  outer->addWidget(scroll);
}

EvaluationPanel::~EvaluationPanel() { QThreadPool::globalInstance()->waitForDone(); }

QString EvaluationPanel::Browse(const QString& title) {
  return QFileDialog::getOpenFileName(this, title, QString(),
                                      tr("Trajectories (*.txt *.csv);;All files (*)"));
}

void EvaluationPanel::Evaluate(const QString& estimate_path, const QString& ground_truth_path,
                               const QString& align) {
  estimate_edit_->setText(estimate_path);
  ground_truth_edit_->setText(ground_truth_path);
  run_button_->setEnabled(false);
  summary_label_->setText(tr("Evaluating..."));
  const int generation = ++generation_;
  QPointer<EvaluationPanel> self(this);
  const std::string estimate = estimate_path.toStdString();
  const std::string ground_truth = ground_truth_path.toStdString();
  const std::string mode = align.toStdString();
  // Reading and evaluating long trajectories takes a moment: never on the GUI thread. The
  // destructor waits for the pool, so `this` outlives the task.
  QThreadPool::globalInstance()->start([this, self, generation, estimate, ground_truth, mode] {
    auto outcome = RunEvaluation(estimate, ground_truth, mode);
    QMetaObject::invokeMethod(
        this,
        [self, generation, outcome] {
          if (self && generation == self->generation_) self->Show(outcome);
        },
        Qt::QueuedConnection);
  });
}

void EvaluationPanel::Clear() {
  ++generation_;  // An evaluation still running belongs to the previous source.
  run_button_->setEnabled(true);
  figures_->removeRows(0, figures_->rowCount());
  summary_label_->setText(tr("Choose two trajectory files and press Evaluate."));
  top_view_->Clear();
  error_view_->Clear();
}

void EvaluationPanel::Show(const std::shared_ptr<const EvaluationOutcome>& outcome) {
  run_button_->setEnabled(true);
  figures_->removeRows(0, figures_->rowCount());
  if (!outcome->status.ok()) {
    const QString message = QString::fromStdString(outcome->status.ToString());
    summary_label_->setText(tr("Evaluation failed: %1").arg(message));
    top_view_->Clear();
    error_view_->Clear();
    emit Failed(message);
    return;
  }
  for (const auto& [key, value] : outcome->figures) {
    const AccuracyFigureInfo info = DescribeAccuracyFigure(key);
    figures_->appendRow({new QStandardItem(QString::fromStdString(key)),
                         new QStandardItem(QString::number(value, 'g', 6)),
                         new QStandardItem(QString::fromStdString(info.unit)),
                         new QStandardItem(QString::fromStdString(info.meaning))});
  }
  QString summary = tr("%1 associated poses, ground-truth path %2 m.")
                        .arg(outcome->pairs)
                        .arg(outcome->ground_truth_length_m, 0, 'f', 2);
  for (const std::string& note : outcome->notes) summary += "\n" + QString::fromStdString(note);
  summary_label_->setText(summary);
  top_view_->SetImage(outcome->top_view);
  error_view_->SetImage(outcome->error_over_time);
  emit Finished();
}

double EvaluationPanel::Figure(const QString& key) const {
  for (int row = 0; row < figures_->rowCount(); ++row) {
    if (figures_->item(row, 0)->text() == key) return figures_->item(row, 1)->text().toDouble();
  }
  return std::nan("");
}

}  // namespace sightline
