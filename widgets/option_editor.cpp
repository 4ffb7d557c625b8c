#include "widgets/option_editor.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>
#include <algorithm>
#include <climits>
#include <cmath>

namespace sightline {
namespace {

// Decimals needed to write x exactly, at most 6.
int DecimalsOf(double x) {
  for (int d = 0; d < 6; ++d) {
    const double scaled = x * std::pow(10.0, d);
    if (std::abs(scaled - std::round(scaled)) < 1e-6 * std::max(1.0, std::abs(scaled))) return d;
  }
  return 6;
}

QString UnitSuffix(const OptionSpec& spec) {
  return spec.unit.empty() ? QString() : QStringLiteral(" ") + QString::fromStdString(spec.unit);
}

}  // namespace

int DecimalsFor(const OptionSpec& spec) {
  int decimals = std::max(1, DecimalsOf(spec.step));
  if (const double* d = std::get_if<double>(&spec.default_value)) {
    decimals = std::max(decimals, DecimalsOf(*d));
  }
  return std::min(decimals, 6);
}

QString OptionDescription(const OptionSpec& spec) {
  if (spec.description.empty()) return QString();
  return QCoreApplication::translate("sightline::OptionText", spec.description.c_str());
}

QString OptionTooltip(const OptionSpec& spec) {
  QString tip = OptionDescription(spec);
  const QString unit = UnitSuffix(spec);
  if (spec.type == OptionType::kInt || spec.type == OptionType::kDouble) {
    tip += QLatin1Char('\n') +
           OptionEditor::tr("Range: %1 … %2%3").arg(spec.min).arg(spec.max).arg(unit);
  } else if (spec.type == OptionType::kChoice) {
    QStringList choices;
    for (const std::string& c : spec.choices) choices << QString::fromStdString(c);
    tip +=
        QLatin1Char('\n') + OptionEditor::tr("Choices: %1").arg(choices.join(QStringLiteral(", ")));
  }
  tip += QLatin1Char('\n') +
         OptionEditor::tr("Default: %1%2")
             .arg(QString::fromStdString(FormatOptionValue(spec.default_value)), unit);
  return tip.trimmed();
}

OptionEditor::OptionEditor(const OptionSpec& spec, QWidget* parent) : QWidget(parent), spec_(spec) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  input_ = CreateInput();
  layout->addWidget(input_, 1);

  reset_button_ = new QToolButton(this);
  reset_button_->setIcon(style()->standardIcon(QStyle::SP_DialogResetButton));
  reset_button_->setAutoRaise(true);
  UpdateToolTips();
  connect(reset_button_, &QToolButton::clicked, this, [this] { emit ResetRequested(spec_.key); });
  layout->addWidget(reset_button_);
  SetValue(spec_.default_value);
}

void OptionEditor::UpdateToolTips() {
  input_->setToolTip(OptionTooltip(spec_));
  reset_button_->setToolTip(
      tr("Reset to default (%1)")
          .arg(QString::fromStdString(FormatOptionValue(spec_.default_value))));
}

void OptionEditor::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) UpdateToolTips();
  QWidget::changeEvent(event);
}

QWidget* OptionEditor::CreateInput() {
  switch (spec_.type) {
    case OptionType::kBool: {
      auto* box = new QCheckBox(this);
      connect(box, &QCheckBox::toggled, this,
              [this](bool on) { emit ValueEdited(spec_.key, OptionValue(on)); });
      return box;
    }
    case OptionType::kInt: {
      auto* box = new QSpinBox(this);
      // QSpinBox holds an int; options wider than that are clamped to what it can show.
      box->setRange(static_cast<int>(std::max(spec_.min, static_cast<double>(INT_MIN))),
                    static_cast<int>(std::min(spec_.max, static_cast<double>(INT_MAX))));
      box->setSingleStep(std::max(1, static_cast<int>(spec_.step)));
      box->setSuffix(UnitSuffix(spec_));
      box->setKeyboardTracking(false);  // One edit per Enter / focus change, not per keystroke.
      connect(box, &QSpinBox::valueChanged, this,
              [this](int v) { emit ValueEdited(spec_.key, OptionValue(static_cast<int64_t>(v))); });
      return box;
    }
    case OptionType::kDouble: {
      auto* box = new QDoubleSpinBox(this);
      box->setDecimals(DecimalsFor(spec_));
      box->setRange(spec_.min, spec_.max);
      box->setSingleStep(spec_.step > 0 ? spec_.step : 0.1);
      box->setSuffix(UnitSuffix(spec_));
      box->setKeyboardTracking(false);
      connect(box, &QDoubleSpinBox::valueChanged, this,
              [this](double v) { emit ValueEdited(spec_.key, OptionValue(v)); });
      return box;
    }
    case OptionType::kChoice: {
      auto* box = new QComboBox(this);
      for (const std::string& choice : spec_.choices) box->addItem(QString::fromStdString(choice));
      connect(box, &QComboBox::currentTextChanged, this, [this](const QString& text) {
        emit ValueEdited(spec_.key, OptionValue(text.toStdString()));
      });
      return box;
    }
    case OptionType::kString:
    default: {
      auto* edit = new QLineEdit(this);
      connect(edit, &QLineEdit::editingFinished, this, [this, edit] {
        emit ValueEdited(spec_.key, OptionValue(edit->text().toStdString()));
      });
      return edit;
    }
  }
}

void OptionEditor::SetValue(const OptionValue& value) {
  const QSignalBlocker blocker(input_);
  if (auto* box = qobject_cast<QCheckBox*>(input_)) {
    if (const bool* v = std::get_if<bool>(&value)) box->setChecked(*v);
  } else if (auto* box = qobject_cast<QSpinBox*>(input_)) {
    if (const int64_t* v = std::get_if<int64_t>(&value)) box->setValue(static_cast<int>(*v));
  } else if (auto* box = qobject_cast<QDoubleSpinBox*>(input_)) {
    if (const double* v = std::get_if<double>(&value)) box->setValue(*v);
  } else if (auto* box = qobject_cast<QComboBox*>(input_)) {
    if (const std::string* v = std::get_if<std::string>(&value)) {
      box->setCurrentText(QString::fromStdString(*v));
    }
  } else if (auto* edit = qobject_cast<QLineEdit*>(input_)) {
    if (const std::string* v = std::get_if<std::string>(&value)) {
      edit->setText(QString::fromStdString(*v));
    }
  }
  modified_ = !(value == spec_.default_value);
  reset_button_->setEnabled(modified_);
}

}  // namespace sightline
