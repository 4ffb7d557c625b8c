// The lab engineer's trajectory evaluation: pick an estimate and a ground truth, see ATE, RPE,
// KITTI segment, length and end-point errors as a table and as plots.
#pragma once

#include <QString>
#include <QWidget>
#include <memory>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QStandardItemModel;
class QTableView;

namespace sightline {

class ImageView;
struct EvaluationOutcome;

// Evaluates in a background thread; the GUI thread only shows the finished result.
//
//   auto* panel = new EvaluationPanel(this);
//   panel->Evaluate("estimate.txt", "groundtruth.txt", "se3");  // Or through its own buttons.
class EvaluationPanel : public QWidget {
  Q_OBJECT

 public:
  explicit EvaluationPanel(QWidget* parent = nullptr);
  ~EvaluationPanel() override;

  // Starts an evaluation of two trajectory files (TUM or KITTI, detected) with an alignment
  // ("se3", "sim3" or "none"). Finished or Failed follows.
  void Evaluate(const QString& estimate_path, const QString& ground_truth_path,
                const QString& align);

  // Empties the figures, the summary and the plots (another source was opened).
  void Clear();
  // The value shown for a figure key such as "ate_rmse_m"; NaN when absent.
  double Figure(const QString& key) const;
  // The plots currently shown (empty before the first evaluation).
  const ImageView* top_view() const { return top_view_; }
  const ImageView* error_view() const { return error_view_; }

 signals:
  void Finished();
  void Failed(const QString& message);

 private:
  void Show(const std::shared_ptr<const EvaluationOutcome>& outcome);
  QString Browse(const QString& title);

  QLineEdit* estimate_edit_ = nullptr;
  QLineEdit* ground_truth_edit_ = nullptr;
  QComboBox* align_combo_ = nullptr;
  QPushButton* run_button_ = nullptr;
  QLabel* summary_label_ = nullptr;
  QStandardItemModel* figures_ = nullptr;
  QTableView* table_ = nullptr;
  ImageView* top_view_ = nullptr;
  ImageView* error_view_ = nullptr;
  int generation_ = 0;
};

}  // namespace sightline
