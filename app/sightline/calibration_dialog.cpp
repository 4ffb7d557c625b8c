#include "app/sightline/calibration_dialog.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QStandardItemModel>
#include <QTableView>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrent>
#include <opencv2/imgproc.hpp>

#include "core/io/image_loading.h"
#include "core/sensors/driver_registry.h"
#include "widgets/image_view.h"

namespace sightline {
namespace {

QString Qs(const std::string& s) { return QString::fromStdString(s); }

// The views shown in the table: mono views, or the left views of stereo pairs.
const std::vector<BoardView>& ShownViews(const CalibrationOutcome& o) { return o.detections.views; }

const MonoCalibration& FirstCamera(const CalibrationOutcome& o) {
  return o.stereo ? o.stereo->left : *o.mono;
}

}  // namespace

CalibrationDialog::CalibrationDialog(QWidget* parent) : QDialog(parent) {
  setWindowTitle(tr("Calibrate camera"));
  setObjectName("calibration_dialog");
  BuildUi();
  resize(1000, 700);
}

CalibrationDialog::~CalibrationDialog() {
  cancel_->store(true);
  // The worker posts its result to `this`: wait until it is done before the members go.
  QThreadPool::globalInstance()->waitForDone();
}

void CalibrationDialog::BuildUi() {
  mode_combo_ = new QComboBox(this);
  mode_combo_->addItem(tr("Mono (one camera)"));
  mode_combo_->addItem(tr("Stereo (left and right)"));
  source_edit_ = new QLineEdit(this);
  source_edit_->setPlaceholderText(tr("Image folder, stereo folder, recording or camera URI"));
  auto* browse = new QPushButton(tr("Browse..."), this);
  connect(browse, &QPushButton::clicked, this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Calibration images"));
    if (!dir.isEmpty()) source_edit_->setText(dir);
  });
  auto* source_row = new QHBoxLayout;
  source_row->addWidget(source_edit_, 1);
  source_row->addWidget(browse);
  pattern_edit_ = new QLineEdit("*", this);
  pattern_edit_->setToolTip(tr("File name pattern inside a mono image folder, e.g. left*.jpg"));
  columns_spin_ = new QSpinBox(this);
  columns_spin_->setRange(3, 100);
  columns_spin_->setValue(9);
  rows_spin_ = new QSpinBox(this);
  rows_spin_->setRange(3, 100);
  rows_spin_->setValue(6);
  square_spin_ = new QDoubleSpinBox(this);
  square_spin_->setRange(1, 1000);
  square_spin_->setDecimals(2);
  square_spin_->setValue(25);
  square_spin_->setSuffix(tr(" mm"));
  auto* board_row = new QHBoxLayout;
  board_row->addWidget(columns_spin_);
  board_row->addWidget(new QLabel(tr("x"), this));
  board_row->addWidget(rows_spin_);
  board_row->addWidget(new QLabel(tr("inner corners, squares of"), this));
  board_row->addWidget(square_spin_);
  board_row->addStretch(1);

  auto* form = new QFormLayout;
  form->addRow(tr("Mode"), mode_combo_);
  form->addRow(tr("Source"), source_row);
  form->addRow(tr("Image pattern"), pattern_edit_);
  form->addRow(tr("Board"), board_row);

  run_button_ = new QPushButton(tr("&Calibrate"), this);
  save_button_ = new QPushButton(tr("&Save YAML..."), this);
  save_button_->setEnabled(false);
  connect(run_button_, &QPushButton::clicked, this, &CalibrationDialog::StartFromForm);
  connect(save_button_, &QPushButton::clicked, this, &CalibrationDialog::SaveFromButton);
  progress_ = new QProgressBar(this);
  progress_->setRange(0, 1);
  progress_->setValue(0);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(run_button_);
  buttons->addWidget(progress_, 1);
  buttons->addWidget(save_button_);

  status_label_ = new QLabel(tr("Choose a source and the board, then press Calibrate."), this);
  status_label_->setWordWrap(true);
  figures_label_ = new QLabel(this);
  figures_label_->setObjectName("calibration_figures");
  figures_label_->setWordWrap(false);  // Short lines; wrapping labels lose height in layouts.
  figures_label_->setTextInteractionFlags(Qt::TextSelectableByMouse);

  view_errors_ = new QStandardItemModel(0, 4, this);
  view_errors_->setHorizontalHeaderLabels(
      {tr("View"), tr("Error (px)"), tr("Right error (px)"), tr("Status")});
  table_ = new QTableView(this);
  table_->setModel(view_errors_);
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  connect(table_->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
          [this](const QModelIndex& current) { ShowView(current.row()); });

  corner_view_ = new ImageView(this);
  corner_view_->SetTitle(tr("Detected corners"));
  coverage_view_ = new ImageView(this);
  coverage_view_->SetTitle(tr("Coverage (views per cell)"));
  auto* images = new QSplitter(Qt::Horizontal, this);
  images->addWidget(corner_view_);
  images->addWidget(coverage_view_);
  auto* split = new QSplitter(Qt::Vertical, this);
  split->addWidget(images);
  split->addWidget(table_);
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 2);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addLayout(buttons);
  layout->addWidget(status_label_);
  layout->addWidget(figures_label_);
  layout->addWidget(split, 1);
}

void CalibrationDialog::SetSource(const QString& path_or_uri) {
  source_edit_->setText(path_or_uri);
}

void CalibrationDialog::Calibrate(bool stereo, const QString& input, const QString& pattern,
                                  int columns, int rows, double square_m) {
  mode_combo_->setCurrentIndex(stereo ? 1 : 0);
  source_edit_->setText(input);
  pattern_edit_->setText(pattern);
  columns_spin_->setValue(columns);
  rows_spin_->setValue(rows);
  square_spin_->setValue(square_m * 1000);
  StartFromForm();
}

void CalibrationDialog::StartFromForm() {
  CalibrationRequest request;
  request.stereo = mode_combo_->currentIndex() == 1;
  request.input = source_edit_->text().trimmed().toStdString();
  request.pattern = pattern_edit_->text().trimmed().isEmpty()
                        ? "*"
                        : pattern_edit_->text().trimmed().toStdString();
  request.settings.board.columns = columns_spin_->value();
  request.settings.board.rows = rows_spin_->value();
  request.settings.board.square_size_m = square_spin_->value() / 1000.0;
  if (request.input.empty()) {
    status_label_->setText(tr("Choose a source first."));
    return;
  }
  run_button_->setEnabled(false);
  save_button_->setEnabled(false);
  progress_->setRange(0, 0);
  status_label_->setText(tr("Detecting the board..."));
  const int generation = ++generation_;
  QPointer<CalibrationDialog> self(this);
  auto cancel = cancel_;
  // Detection and calibration take seconds: never on the GUI thread. Progress and the result
  // come back as queued calls; the destructor waits for the pool.
  (void)QtConcurrent::run([this, self, generation, request, cancel] {
    DetectionCallbacks callbacks;
    callbacks.cancel = cancel.get();
    callbacks.progress = [this, self](int done, int total) {
      QMetaObject::invokeMethod(
          this,
          [self, done, total] {
            if (!self) return;
            self->progress_->setRange(0, total);
            self->progress_->setValue(done);
          },
          Qt::QueuedConnection);
    };
    const SourceOpener open = [](const std::string& uri) { return OpenSource(uri); };
    auto result = std::make_shared<const StatusOr<CalibrationOutcome>>(
        RunCalibration(request, open, callbacks));
    QMetaObject::invokeMethod(
        this,
        [self, generation, result] {
          if (self && generation == self->generation_) self->Show(result);
        },
        Qt::QueuedConnection);
  });
}

void CalibrationDialog::Show(const std::shared_ptr<const StatusOr<CalibrationOutcome>>& result) {
  run_button_->setEnabled(true);
  progress_->setRange(0, 1);
  progress_->setValue(1);
  if (!result->ok()) {
    const QString message = Qs(result->status().ToString());
    status_label_->setText(tr("Calibration failed: %1").arg(message));
    emit Failed(message);
    return;
  }
  outcome_ = std::shared_ptr<const CalibrationOutcome>(result, &result->value());
  const Detections& d = outcome_->detections;
  status_label_->setText(tr("Board found in %1 of %2 %3.")
                             .arg(d.views.size())
                             .arg(d.inputs)
                             .arg(outcome_->stereo ? tr("pairs") : tr("images")));
  figures_label_->setText(FiguresText());
  save_button_->setEnabled(true);
  FillTable();
  ShowCoverage();
  table_->selectRow(0);
  ShowView(0);
  emit Finished();
}

QString CalibrationDialog::FiguresText() const {
  if (!outcome_) return QString();
  const MonoCalibration& first = FirstCamera(*outcome_);
  QString text;
  if (outcome_->stereo) {
    const StereoCalibration& s = *outcome_->stereo;
    text = tr("RMS left %1 px, right %2 px, stereo %3 px; baseline %4 mm; %5 of %6 pairs used.")
               .arg(s.left.rms_px, 0, 'f', 4)
               .arg(s.right.rms_px, 0, 'f', 4)
               .arg(s.rms_px, 0, 'f', 4)
               .arg(1000 * s.BaselineM(), 0, 'f', 2)
               .arg(s.used_pairs())
               .arg(s.pairs.size());
  } else {
    text = tr("RMS %1 px; %2 views used, %3 rejected.")
               .arg(first.rms_px, 0, 'f', 4)
               .arg(first.used.size())
               .arg(first.rejected());
  }
  const PinholeCamera& c = first.camera;
  text += "\n" + tr("fx %1 fy %2 cx %3 cy %4; coverage: %5")
                     .arg(c.fx, 0, 'f', 2)
                     .arg(c.fy, 0, 'f', 2)
                     .arg(c.cx, 0, 'f', 2)
                     .arg(c.cy, 0, 'f', 2)
                     .arg(Qs(first.coverage.Summary()));
  for (const std::string& hint : first.coverage.Hints())
    text += "\n" + tr("Hint: %1").arg(Qs(hint));
  return text;
}

void CalibrationDialog::FillTable() {
  view_errors_->removeRows(0, view_errors_->rowCount());
  const bool stereo = outcome_->stereo.has_value();
  const size_t count = ShownViews(*outcome_).size();
  for (size_t i = 0; i < count; ++i) {
    QString name, left, right;
    bool rejected = false;
    if (stereo) {
      const PairError& p = outcome_->stereo->pairs[i];
      name = Qs(p.name);
      left = QString::number(p.left_rms_px, 'f', 4);
      right = QString::number(p.right_rms_px, 'f', 4);
      rejected = p.rejected;
    } else {
      const ViewError& v = outcome_->mono->views[i];
      name = Qs(v.name);
      left = QString::number(v.rms_px, 'f', 4);
      rejected = v.rejected;
    }
    view_errors_->appendRow({new QStandardItem(name), new QStandardItem(left),
                             new QStandardItem(right),
                             new QStandardItem(rejected ? tr("rejected") : tr("used"))});
  }
  table_->resizeColumnsToContents();
}

void CalibrationDialog::ShowView(int row) {
  if (!outcome_ || row < 0 || row >= static_cast<int>(ShownViews(*outcome_).size())) return;
  const BoardView& view = ShownViews(*outcome_)[row];
  cv::Mat image;
  if (!view.path.empty()) {
    auto loaded = LoadImage8(view.path);
    if (loaded.ok()) image = *loaded;
  }
  if (image.empty()) image = cv::Mat(view.image_size, CV_8UC1, cv::Scalar(64));
  const bool rejected = view_errors_->item(row, 3)->text() == tr("rejected");
  const QColor colour = rejected ? QColor(Qt::red) : QColor(Qt::green);
  ImageOverlay overlay;
  for (size_t i = 0; i < view.corners.size(); ++i) {
    const QPointF p(view.corners[i].x, view.corners[i].y);
    overlay.points.push_back({p, colour, 3.0});
    if (i > 0) {
      const QPointF q(view.corners[i - 1].x, view.corners[i - 1].y);
      overlay.lines.push_back({QLineF(q, p), QColor(Qt::yellow), 1.0});
    }
  }
  corner_view_->SetImage(image);
  corner_view_->SetOverlay(std::move(overlay));
  corner_view_->SetTitle(
      tr("Detected corners: %1 (%2 px)").arg(Qs(view.name), view_errors_->item(row, 1)->text()));
}

void CalibrationDialog::ShowCoverage() {
  const Coverage& c = FirstCamera(*outcome_).coverage;
  const cv::Size size = ShownViews(*outcome_).front().image_size;
  cv::Mat canvas(size, CV_8UC3, cv::Scalar(40, 40, 40));
  ImageOverlay overlay;
  const double cw = static_cast<double>(size.width) / c.grid_columns;
  const double ch = static_cast<double>(size.height) / c.grid_rows;
  for (int row = 0; row < c.grid_rows; ++row) {
    for (int col = 0; col < c.grid_columns; ++col) {
      const int n = c.CellViews(col, row);
      const cv::Rect cell(static_cast<int>(col * cw), static_cast<int>(row * ch),
                          static_cast<int>(cw) + 1, static_cast<int>(ch) + 1);
      // Dark red: no view; green, brighter with more views (saturating at 4).
      const double level = std::min(n, 4) / 4.0;
      const cv::Scalar colour =
          n == 0 ? cv::Scalar(30, 30, 110) : cv::Scalar(40, 90 + 160 * level, 40);
      cv::rectangle(canvas, cell, colour, cv::FILLED);
      cv::rectangle(canvas, cell, cv::Scalar(90, 90, 90), 1);
      overlay.texts.push_back({QPointF(col * cw + cw * 0.4, row * ch + ch * 0.6),
                               QString::number(n), QColor(Qt::white)});
    }
  }
  coverage_view_->SetImage(canvas);
  coverage_view_->SetOverlay(std::move(overlay));
}

bool CalibrationDialog::SaveTo(const QString& path, QString* error) {
  if (!outcome_) {
    if (error) *error = tr("Nothing to save: calibrate first.");
    return false;
  }
  Status saved = SaveCalibration(*outcome_, path.toStdString());
  if (!saved.ok()) {
    if (error) *error = Qs(saved.ToString());
    return false;
  }
  status_label_->setText(tr("Saved %1").arg(path));
  return true;
}

void CalibrationDialog::SaveFromButton() {
  const QString path = QFileDialog::getSaveFileName(this, tr("Save calibration"), "camera.yaml",
                                                    tr("OpenCV YAML (*.yaml *.yml)"));
  if (path.isEmpty()) return;
  QString error;
  if (!SaveTo(path, &error)) status_label_->setText(tr("Saving failed: %1").arg(error));
}

void OpenCalibrationDialog(QWidget* parent, const QString& current_source) {
  auto* dialog = new CalibrationDialog(parent);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  dialog->SetSource(current_source);
  dialog->show();
}

}  // namespace sightline
