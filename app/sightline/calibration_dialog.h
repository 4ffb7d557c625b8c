// The calibration dialog (Tools > Calibrate camera): mono or stereo chessboard calibration of
// an image folder, a recording or a live camera, run in a worker thread; shows the detected
// corners of the selected view, the coverage grid, per-view errors, RMS and baseline, and saves
// the OpenCV YAML the readers accept.
#pragma once

#include <QDialog>
#include <QString>
#include <atomic>
#include <memory>

#include "core/calib/calibration_job.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QStandardItemModel;
class QTableView;

namespace sightline {

class ImageView;

// Calibrates in the global thread pool; the GUI thread only shows the finished result.
//
//   auto* dialog = new CalibrationDialog(this);
//   dialog->SetSource("v4l2://0");   // Or the user types a folder.
//   dialog->show();
class CalibrationDialog : public QDialog {
  Q_OBJECT

 public:
  explicit CalibrationDialog(QWidget* parent = nullptr);
  ~CalibrationDialog() override;

  // Fills the source field (the main window's current dataset or camera).
  void SetSource(const QString& path_or_uri);
  // Sets the form and starts a calibration, as the Calibrate button does. Finished or Failed
  // follows.
  void Calibrate(bool stereo, const QString& input, const QString& pattern, int columns, int rows,
                 double square_m);
  // Writes the last result; false with *error set when there is none or writing fails.
  bool SaveTo(const QString& path, QString* error);

  // The last successful result, or nullptr.
  const CalibrationOutcome* outcome() const { return outcome_.get(); }
  // The figures line shown under the table ("RMS ... px, baseline ... mm").
  QString FiguresText() const;
  const QStandardItemModel* view_errors() const { return view_errors_; }
  const ImageView* corner_view() const { return corner_view_; }
  const ImageView* coverage_view() const { return coverage_view_; }

 signals:
  void Finished();
  void Failed(const QString& message);

 private:
  void BuildUi();
  void StartFromForm();
  void Show(const std::shared_ptr<const StatusOr<CalibrationOutcome>>& result);
  void FillTable();
  void ShowView(int row);
  void ShowCoverage();
  void SaveFromButton();

  QComboBox* mode_combo_ = nullptr;
  QLineEdit* source_edit_ = nullptr;
  QLineEdit* pattern_edit_ = nullptr;
  QSpinBox* columns_spin_ = nullptr;
  QSpinBox* rows_spin_ = nullptr;
  QDoubleSpinBox* square_spin_ = nullptr;
  QPushButton* run_button_ = nullptr;
  QPushButton* save_button_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QLabel* status_label_ = nullptr;
  QLabel* figures_label_ = nullptr;
  QStandardItemModel* view_errors_ = nullptr;
  QTableView* table_ = nullptr;
  ImageView* corner_view_ = nullptr;
  ImageView* coverage_view_ = nullptr;

  std::shared_ptr<const CalibrationOutcome> outcome_;
  std::shared_ptr<std::atomic<bool>> cancel_ = std::make_shared<std::atomic<bool>>(false);
  int generation_ = 0;
};

// Opens a non-modal calibration dialog (deleted on close) with `current_source` filled in.
void OpenCalibrationDialog(QWidget* parent, const QString& current_source);

}  // namespace sightline
