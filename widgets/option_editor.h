// One row of the parameter panel: the input widget that fits an OptionSpec (spin box with unit,
// check box, combo box or line edit) and a reset-to-default button.
#pragma once

#include <QWidget>
#include <string>

#include "core/options/option_spec.h"

class QToolButton;

namespace sightline {

// Edits one option. It never changes an OptionSet itself: it reports edits, and its owner
// validates them and writes the accepted value back with SetValue.
class OptionEditor : public QWidget {
  Q_OBJECT

 public:
  // Builds the input for `spec`: range, step, decimals and unit suffix come from the spec.
  explicit OptionEditor(const OptionSpec& spec, QWidget* parent = nullptr);

  // The spec this row edits.
  const OptionSpec& spec() const { return spec_; }
  // Shows `value` without emitting ValueEdited.
  void SetValue(const OptionValue& value);
  // True when the shown value differs from the spec's default.
  bool modified() const { return modified_; }
  // The input widget (QSpinBox, QDoubleSpinBox, QCheckBox, QComboBox or QLineEdit).
  QWidget* input() const { return input_; }

 signals:
  // The user changed the value (already within the input's range).
  void ValueEdited(const std::string& key, const sightline::OptionValue& value);
  // The user asked for the default value.
  void ResetRequested(const std::string& key);

 private:
  void changeEvent(QEvent* event) override;  // Retranslates the tool tips.
  QWidget* CreateInput();
  void UpdateToolTips();

  OptionSpec spec_;
  QWidget* input_ = nullptr;
  QToolButton* reset_button_ = nullptr;
  bool modified_ = false;
};

// Decimals a spin box needs to show `spec`'s step and default exactly (1 to 6).
int DecimalsFor(const OptionSpec& spec);

// The spec's description in the user's language: the core's English text translated under the
// context "sightline::OptionText" (listed in app/sightline/option_texts.cpp); as it is when no
// translation has it.
QString OptionDescription(const OptionSpec& spec);

// "Description\nRange: 0.01 … 5 m\nDefault: 0.05 m" for tooltips.
QString OptionTooltip(const OptionSpec& spec);

}  // namespace sightline
