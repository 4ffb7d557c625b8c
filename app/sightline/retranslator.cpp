#include "app/sightline/retranslator.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QProgressBar>
#include <QSet>
#include <QSpinBox>
#include <QTabWidget>
#include <QToolBar>
#include <algorithm>

#include "widgets/image_view.h"
#include "widgets/operator_panel.h"
#include "widgets/text_template.h"

namespace sightline {

namespace {

// Fewer literal characters than this and a text with placeholders matches too much ("%1 cm").
constexpr int kMinPatternLiterals = 4;

// The tool tip Qt derives from an action's text when none was set.
QString DerivedToolTip(QString text) {
  text.remove(QStringLiteral("..."));
  text.replace(QStringLiteral("&&"), QStringLiteral("\x01"));
  text.remove('&');
  text.replace(QChar(1), '&');
  return text.trimmed();
}

}  // namespace

Retranslator::Retranslator(const Lookup& lookup) {
  for (const auto& [old_text, new_text] : lookup) {
    exact_.emplace_back(old_text, new_text);
    QString literal = old_text;
    if (literal.remove(PlaceholderRe()).size() < kMinPatternLiterals) continue;
    if (!old_text.contains(PlaceholderRe())) continue;
    Pattern pattern;
    const QString re = QStringLiteral("^") +
                       PlaceholderPattern(old_text, QStringLiteral("(.*?)"), &pattern.numbers) +
                       QStringLiteral("$");
    pattern.old_text = QRegularExpression(re, QRegularExpression::DotMatchesEverythingOption);
    pattern.new_text = new_text;
    patterns_.push_back(std::move(pattern));
  }
  std::stable_sort(exact_.begin(), exact_.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
}

std::optional<QString> Retranslator::Translate(const QString& text) const {
  const auto it =
      std::lower_bound(exact_.begin(), exact_.end(), text,
                       [](const auto& entry, const QString& t) { return entry.first < t; });
  if (it != exact_.end() && it->first == text) return it->second;
  return FromPattern(text);
}

std::optional<QString> Retranslator::FromPattern(const QString& text) const {
  for (const Pattern& pattern : patterns_) {
    const QRegularExpressionMatch match = pattern.old_text.match(text);
    if (!match.hasMatch()) continue;
    QString result;
    qsizetype last = 0;
    for (const QRegularExpressionMatch& m : PlaceholderRe().globalMatch(pattern.new_text)) {
      result += pattern.new_text.mid(last, m.capturedStart() - last);
      const int number = m.captured(1).toInt();
      const auto at = std::find(pattern.numbers.begin(), pattern.numbers.end(), number);
      QString value = at == pattern.numbers.end()
                          ? m.captured(0)
                          : match.captured(static_cast<int>(at - pattern.numbers.begin()) + 1);
      // A filled-in part that is a message itself ("Statistics: Mobility map").
      const auto inner =
          std::lower_bound(exact_.begin(), exact_.end(), value,
                           [](const auto& entry, const QString& t) { return entry.first < t; });
      if (inner != exact_.end() && inner->first == value) value = inner->second;
      result += value;
      last = m.capturedEnd();
    }
    return result + pattern.new_text.mid(last);
  }
  return std::nullopt;
}

void Retranslator::RetranslateAll() const {
  QSet<QAction*> actions;
  for (QWidget* widget : QApplication::allWidgets()) {
    Retranslate(widget);
    for (QAction* action : widget->actions()) actions.insert(action);
    for (QAction* action : widget->findChildren<QAction*>(Qt::FindDirectChildrenOnly)) {
      actions.insert(action);
    }
  }
  for (QAction* action : actions) Retranslate(action);
}

void Retranslator::Retranslate(QAction* action) const {
  if (action->menu() != nullptr) return;  // A menu's action follows the menu's title.
  const QString old_text = action->text();
  const QString old_tip = action->toolTip();
  const bool derived_tip = old_tip == DerivedToolTip(old_text);
  Apply(old_text, [action](const QString& t) { action->setText(t); });
  if (!derived_tip) Apply(old_tip, [action](const QString& t) { action->setToolTip(t); });
  Apply(action->statusTip(), [action](const QString& t) { action->setStatusTip(t); });
}

void Retranslator::Retranslate(QWidget* w) const {
  if (w->isWindow() || qobject_cast<QDockWidget*>(w) || qobject_cast<QToolBar*>(w)) {
    Apply(w->windowTitle(), [w](const QString& t) { w->setWindowTitle(t); });
  }
  Apply(w->toolTip(), [w](const QString& t) { w->setToolTip(t); });
  Apply(w->statusTip(), [w](const QString& t) { w->setStatusTip(t); });
  if (auto* button = qobject_cast<QAbstractButton*>(w)) {
    Apply(button->text(), [button](const QString& t) { button->setText(t); });
  } else if (auto* label = qobject_cast<QLabel*>(w)) {
    Apply(label->text(), [label](const QString& t) { label->setText(t); });
  } else if (auto* group = qobject_cast<QGroupBox*>(w)) {
    Apply(group->title(), [group](const QString& t) { group->setTitle(t); });
  } else if (auto* line = qobject_cast<QLineEdit*>(w)) {
    Apply(line->placeholderText(), [line](const QString& t) { line->setPlaceholderText(t); });
  } else if (auto* menu = qobject_cast<QMenu*>(w)) {
    Apply(menu->title(), [menu](const QString& t) { menu->setTitle(t); });
  } else if (auto* bar = qobject_cast<QProgressBar*>(w)) {
    Apply(bar->format(), [bar](const QString& t) { bar->setFormat(t); });
  } else if (auto* spin = qobject_cast<QSpinBox*>(w)) {
    Apply(spin->suffix(), [spin](const QString& t) { spin->setSuffix(t); });
    Apply(spin->prefix(), [spin](const QString& t) { spin->setPrefix(t); });
  } else if (auto* dspin = qobject_cast<QDoubleSpinBox*>(w)) {
    Apply(dspin->suffix(), [dspin](const QString& t) { dspin->setSuffix(t); });
    Apply(dspin->prefix(), [dspin](const QString& t) { dspin->setPrefix(t); });
  }
  if (auto* image = qobject_cast<ImageView*>(w)) {
    Apply(image->title(), [image](const QString& t) { image->SetTitle(t); });
    Apply(image->message(), [image](const QString& t) { image->SetMessage(t); });
  }
  if (auto* panel = qobject_cast<OperatorPanel*>(w)) {
    // Its own LanguageChange handler redraws the banner and buttons from the state, the detail
    // line from this text.
    Apply(panel->detail_text(), [panel](const QString& t) { panel->SetDetailText(t); });
  }
  RetranslateItems(w);
}

// Texts held by items rather than by the widget: combo entries, tabs, table headers.
void Retranslator::RetranslateItems(QWidget* w) const {
  if (auto* combo = qobject_cast<QComboBox*>(w)) {
    for (int i = 0; i < combo->count(); ++i) {
      Apply(combo->itemText(i), [combo, i](const QString& t) { combo->setItemText(i, t); });
    }
  } else if (auto* tabs = qobject_cast<QTabWidget*>(w)) {
    for (int i = 0; i < tabs->count(); ++i) {
      Apply(tabs->tabText(i), [tabs, i](const QString& t) { tabs->setTabText(i, t); });
      Apply(tabs->tabToolTip(i), [tabs, i](const QString& t) { tabs->setTabToolTip(i, t); });
    }
  } else if (auto* view = qobject_cast<QAbstractItemView*>(w)) {
    QAbstractItemModel* model = view->model();
    if (model == nullptr) return;
    for (const Qt::Orientation o : {Qt::Horizontal, Qt::Vertical}) {
      const int n = o == Qt::Horizontal ? model->columnCount() : model->rowCount();
      for (int i = 0; i < n && i < 64; ++i) {
        Apply(model->headerData(i, o).toString(),
              [model, i, o](const QString& t) { model->setHeaderData(i, o, t); });
      }
    }
  }
}

}  // namespace sightline
