// A tuning panel generated from an OptionSet: one group box per key prefix, one row per option,
// profile load/save and reset. Every accepted edit is announced with the complete option set.
#pragma once

#include <QString>
#include <QWidget>
#include <map>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/options/option_set.h"

class QGroupBox;
class QLabel;
class QLineEdit;

namespace sightline {

class OptionEditor;

// Shows and edits a copy of an OptionSet. Values are validated by OptionSet::Set before
// OptionsChanged is emitted, so receivers can hand the set to a worker as it is.
//
//   auto* panel = new ParameterPanel(this);
//   panel->SetOptions(options);
//   connect(panel, &ParameterPanel::OptionsChanged, controller, &Controller::ApplyOptions);
class ParameterPanel : public QWidget {
  Q_OBJECT

 public:
  // Creates an empty panel; call SetOptions to fill it.
  explicit ParameterPanel(QWidget* parent = nullptr);
  ~ParameterPanel() override;

  // Shows `options` (specs and current values). Rebuilds the rows only when the keys or types
  // changed. Does not emit OptionsChanged.
  void SetOptions(const OptionSet& options);
  // The options as currently edited.
  const OptionSet& options() const { return options_; }

  // Loads a YAML profile into the set (all or nothing); on success emits OptionsChanged.
  // Errors are returned and shown in the message area.
  Status LoadProfile(const QString& path);
  // Writes the current values as a YAML profile, without the options under the prefix set by
  // SetProfileExclusion; errors are returned and shown.
  Status SaveProfile(const QString& path);
  // Options whose keys start with `prefix` (e.g. the window's own "view.") stay out of saved
  // profiles, so a profile holds what `sightline-cli run --profile` reads.
  void SetProfileExclusion(const std::string& prefix) { profile_exclusion_ = prefix; }
  // Restores every default and emits OptionsChanged.
  void ResetAll();
  // Shows only options whose key contains `text` (case-insensitive); empty shows all.
  void SetFilter(const QString& text);

  // The input widget of an option's row (for focus and tests); nullptr for unknown keys.
  QWidget* InputFor(const std::string& key) const;
  // The editor of an option's row (input and reset button); nullptr for unknown keys.
  OptionEditor* EditorFor(const std::string& key) const;
  // The text in the message area ("" when none).
  QString message() const;

 signals:
  // Emitted after every accepted change, with the whole set.
  void OptionsChanged(const sightline::OptionSet& options);

 private:
  struct Row {
    OptionEditor* editor = nullptr;
    QLabel* label = nullptr;
    QGroupBox* group = nullptr;
  };

  std::string profile_exclusion_;

  void changeEvent(QEvent* event) override;  // Retranslates the rows' tool tips.
  void Rebuild();
  void RefreshValues();
  void RefreshRow(const std::string& key);
  void OnValueEdited(const std::string& key, const OptionValue& value);
  void OnResetRequested(const std::string& key);
  void OnLoadClicked();
  void OnSaveClicked();
  void ShowMessage(const QString& text, bool error);
  // Shows a core error in the user's language (widgets/core_message.h), again after a switch.
  void ShowStatus(const Status& status);

  OptionSet options_;
  std::map<std::string, Row> rows_;
  std::vector<QGroupBox*> groups_;
  QWidget* content_ = nullptr;
  QLineEdit* filter_ = nullptr;
  QLabel* message_ = nullptr;
  std::string message_status_;  // The core's English text of the error shown, if one is.
  QString last_dir_;
};

}  // namespace sightline
