#include "widgets/log_panel.h"

#include <QDateTime>
#include <QHBoxLayout>
#include <QListView>
#include <QScrollBar>
#include <QStandardItemModel>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>

namespace sightline {
namespace {

constexpr int kSeverityRole = Qt::UserRole + 1;

}  // namespace

LogPanel::LogPanel(QWidget* parent, int max_lines)
    : QWidget(parent), max_lines_(std::max(1, max_lines)) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  model_ = new QStandardItemModel(this);
  view_ = new QListView(this);
  view_->setModel(model_);
  view_->setUniformItemSizes(true);  // Constant-time layout however many lines there are.
  view_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  view_->setSelectionMode(QAbstractItemView::ExtendedSelection);
  view_->setWordWrap(false);
  layout->addWidget(view_, 1);

  auto* tools = new QVBoxLayout();
  auto* clear = new QToolButton(this);
  clear->setIcon(style()->standardIcon(QStyle::SP_DialogDiscardButton));
  clear->setToolTip(tr("Clear messages"));
  clear->setAutoRaise(true);
  connect(clear, &QToolButton::clicked, this, &LogPanel::Clear);
  tools->addWidget(clear);
  tools->addStretch(1);
  layout->addLayout(tools);
}

LogPanel::~LogPanel() = default;

void LogPanel::AddMessage(Severity severity, const QString& text) {
  const QScrollBar* bar = view_->verticalScrollBar();
  const bool at_bottom = bar->value() >= bar->maximum() - 2;

  auto* item =
      new QStandardItem(QDateTime::currentDateTime().toString(QStringLiteral("hh:mm:ss.zzz")) +
                        QStringLiteral("  ") + text);
  item->setData(static_cast<int>(severity), kSeverityRole);
  item->setToolTip(text);
  switch (severity) {
    case Severity::kInfo:
      item->setIcon(style()->standardIcon(QStyle::SP_MessageBoxInformation));
      break;
    case Severity::kWarning:
      item->setIcon(style()->standardIcon(QStyle::SP_MessageBoxWarning));
      item->setForeground(QColor(200, 120, 0));
      break;
    case Severity::kError:
      item->setIcon(style()->standardIcon(QStyle::SP_MessageBoxCritical));
      item->setForeground(QColor(210, 40, 40));
      break;
  }
  model_->appendRow(item);
  if (model_->rowCount() > max_lines_) model_->removeRows(0, model_->rowCount() - max_lines_);
  if (at_bottom) view_->scrollToBottom();
}

void LogPanel::Clear() { model_->clear(); }

int LogPanel::count() const { return model_->rowCount(); }

QString LogPanel::MessageText(int row) const {
  const QStandardItem* item = model_->item(row);
  return item ? item->text() : QString();
}

LogPanel::Severity LogPanel::MessageSeverity(int row) const {
  const QStandardItem* item = model_->item(row);
  return item ? static_cast<Severity>(item->data(kSeverityRole).toInt()) : Severity::kInfo;
}

}  // namespace sightline
