#include "widgets/log_panel.h"

#include <QDateTime>
#include <QHBoxLayout>
#include <QLabel>
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
  view_->setTextElideMode(Qt::ElideRight);
  view_->setToolTip(tr("Click a line to read it in full."));
  detail_ = new QLabel(this);
  detail_->setObjectName("log_detail");
  detail_->setWordWrap(true);
  detail_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  detail_->setFrameShape(QFrame::StyledPanel);
  detail_->hide();
  connect(view_, &QListView::clicked, this, [this](const QModelIndex& index) {
    ShowDetail(index.row() == detail_row_ ? -1 : index.row());
  });
  auto* column = new QVBoxLayout();
  column->addWidget(view_, 1);
  column->addWidget(detail_);
  layout->addLayout(column, 1);

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
  if (model_->rowCount() > max_lines_) {
    const int dropped = model_->rowCount() - max_lines_;
    model_->removeRows(0, dropped);
    if (detail_row_ >= 0) detail_row_ = detail_row_ >= dropped ? detail_row_ - dropped : -1;
    if (detail_row_ < 0) detail_->hide();
  }
  if (at_bottom) view_->scrollToBottom();
}

void LogPanel::Clear() {
  model_->clear();
  ShowDetail(-1);
}

void LogPanel::ShowDetail(int row) {
  detail_row_ = row;
  const QStandardItem* item = row >= 0 ? model_->item(row) : nullptr;
  detail_->setText(item ? item->text() : QString());
  detail_->setVisible(item != nullptr);
}

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
