// A bounded list of timestamped messages (info, warning, error) for the main window.
#pragma once

#include <QString>
#include <QWidget>

class QLabel;
class QListView;
class QStandardItemModel;

namespace sightline {

// Shows the latest messages, oldest dropped beyond max_lines. GUI thread only: workers report
// through queued signals (or QMetaObject::invokeMethod) to AddMessage.
//
//   log->AddMessage(LogPanel::Severity::kWarning, tr("Dropped 3 frames (queue full)"));
class LogPanel : public QWidget {
  Q_OBJECT

 public:
  // How serious a message is; sets its icon and colour.
  enum class Severity { kInfo, kWarning, kError };

  // Creates an empty panel keeping at most `max_lines` messages.
  explicit LogPanel(QWidget* parent = nullptr, int max_lines = 2000);
  ~LogPanel() override;

  // Appends "hh:mm:ss.zzz  text"; keeps the view at the bottom if it was there.
  void AddMessage(Severity severity, const QString& text);
  // Removes every message.
  void Clear();

  // Number of messages held.
  int count() const;
  // The text of message `row` (0 = oldest held), including its timestamp.
  QString MessageText(int row) const;
  // The severity of message `row`.
  Severity MessageSeverity(int row) const;
  // Most messages kept.
  int max_lines() const { return max_lines_; }
  // A click on a line shows the whole message, wrapped and selectable, under the list (long
  // lines are cut at the panel's edge); a second click on it, or Clear, hides it again.
  QLabel* detail() const { return detail_; }

 private:
  void ShowDetail(int row);

  QListView* view_ = nullptr;
  QLabel* detail_ = nullptr;
  int detail_row_ = -1;
  QStandardItemModel* model_ = nullptr;
  int max_lines_;
};

}  // namespace sightline
