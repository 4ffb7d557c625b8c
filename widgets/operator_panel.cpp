#include "widgets/operator_panel.h"

#include <QCloseEvent>
#include <QEvent>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QStackedWidget>
#include <QStyle>
#include <QVBoxLayout>
#include <cmath>
#include <limits>

#include "widgets/tap_image_view.h"

namespace sightline {

namespace {

// High contrast: white on black, yellow for attention, a red STOP.
const char kStyle[] =
    "QWidget#OperatorPanel { background: black; }"
    "QLabel { color: white; }"
    "QLabel#banner { color: black; background: #ffdd00; font-weight: bold; padding: 6px; }"
    "QLabel#distance { color: #ffdd00; font-weight: bold; }"
    "QLabel#detail { color: white; }"
    "QLabel#link { color: white; background: #b00020; font-weight: bold; padding: 4px; }"
    "QLabel#link[live=\"true\"] { color: black; background: #00c853; }"
    "QMessageBox { background: black; }"
    "QPushButton { color: black; background: white; font-weight: bold; border: 3px solid white;"
    "  border-radius: 8px; padding: 6px; }"
    "QPushButton#yes { background: #00c853; border-color: #00c853; }"
    "QPushButton#stop { color: white; background: #d50000; border: 4px solid white; }"
    "QPushButton#stop:pressed { background: #8b0000; }";

}  // namespace

OperatorPanel::OperatorPanel(QWidget* parent)
    : QWidget(parent), distance_m_(std::numeric_limits<double>::quiet_NaN()) {
  setObjectName("OperatorPanel");
  setAttribute(Qt::WA_StyledBackground);
  setStyleSheet(kStyle);
  setFocusPolicy(Qt::StrongFocus);  // F11 and Esc when the panel is a window of its own.
  BuildLayout();
  ConnectButtons();
  Retranslate();
  ApplyTouchSizes();
  UpdateControls();
}

void OperatorPanel::BuildLayout() {
  view_ = new TapImageView(this);
  side_ = new QWidget(this);
  banner_ = new QLabel(side_);
  banner_->setObjectName("banner");
  banner_->setAlignment(Qt::AlignCenter);
  banner_->setWordWrap(true);
  link_label_ = new QLabel(side_);
  link_label_->setObjectName("link");
  link_label_->setAlignment(Qt::AlignCenter);
  link_label_->setWordWrap(true);
  link_label_->hide();
  detail_ = new QLabel(side_);
  detail_->setObjectName("detail");
  detail_->setAlignment(Qt::AlignHCenter | Qt::AlignTop);
  detail_->setWordWrap(true);
  distance_ = new QLabel(side_);
  distance_->setObjectName("distance");
  distance_->setAlignment(Qt::AlignCenter);
  stop_ = new QPushButton(side_);
  stop_->setObjectName("stop");
  answers_ = new QStackedWidget(side_);
  empty_page_ = new QWidget(answers_);
  question_page_ = new QWidget(answers_);
  yes_ = new QPushButton(question_page_);
  yes_->setObjectName("yes");
  cancel_ = new QPushButton(question_page_);
  auto* question = new QVBoxLayout(question_page_);
  question->setContentsMargins(0, 0, 0, 0);
  question->addWidget(yes_);
  question->addWidget(cancel_);
  stopped_page_ = new QWidget(answers_);
  start_ = new QPushButton(stopped_page_);
  auto* stopped = new QVBoxLayout(stopped_page_);
  stopped->setContentsMargins(0, 0, 0, 0);
  stopped->addWidget(start_);
  stopped->addStretch(1);
  for (QWidget* page : {empty_page_, question_page_, stopped_page_}) answers_->addWidget(page);

  // Every region has a fixed size (ApplyTouchSizes) and keeps it when hidden: nothing moves when
  // the words change.
  for (QWidget* w : {static_cast<QWidget*>(detail_), static_cast<QWidget*>(distance_)}) {
    QSizePolicy policy = w->sizePolicy();
    policy.setRetainSizeWhenHidden(true);
    w->setSizePolicy(policy);
  }
  auto* side = new QVBoxLayout(side_);
  side->setContentsMargins(0, 0, 0, 0);
  side->addWidget(stop_);
  side->addWidget(link_label_);
  side->addWidget(banner_);
  side->addWidget(detail_);
  side->addWidget(distance_);
  side->addStretch(1);
  side->addWidget(answers_);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(view_, 1);
  layout->addWidget(side_);
}

void OperatorPanel::ConnectButtons() {
  connect(view_, &TapImageView::Tapped, this, [this](QPointF p) {
    if (state_ == OperatorState::kStopped || state_ == OperatorState::kConfirm) return;
    // A tap on a picture that is not the robot's current view would pick the wrong place.
    if (link_ != OperatorLink::kLocal && link_ != OperatorLink::kLive) return Refuse(LinkText());
    emit Tapped(p);
  });
  connect(yes_, &QPushButton::clicked, this, [this] {
    view_->SetOutline({});  // From now on the ring follows the tracked button.
    SetState(OperatorState::kSearching);
    emit Confirmed();
  });
  connect(cancel_, &QPushButton::clicked, this, [this] {
    view_->SetOutline({});
    SetState(OperatorState::kIdle);
    emit Cancelled();
  });
  // pressed, not clicked: STOP acts the moment the finger lands.
  connect(stop_, &QPushButton::pressed, this, [this] {
    state_ = OperatorState::kStopped;
    detail_text_.clear();
    UpdateControls();
    emit StopPressed();
  });
  connect(start_, &QPushButton::clicked, this, [this] {
    state_ = OperatorState::kIdle;
    detail_text_.clear();
    view_->SetOutline({});
    view_->SetRing(std::nullopt);
    UpdateControls();
    emit StartRequested();
  });
}

void OperatorPanel::SetImage(const cv::Mat& image) { view_->SetImage(image); }

void OperatorPanel::ShowCandidate(const QPolygonF& outline_in_image) {
  if (state_ == OperatorState::kStopped) return;
  view_->SetRing(std::nullopt);
  view_->SetOutline(outline_in_image);
  SetState(OperatorState::kConfirm);
}

void OperatorPanel::SetState(OperatorState state, const QString& detail) {
  if (state_ == OperatorState::kStopped) return;  // Only "Start again" leaves STOP.
  if (state == state_ && detail == detail_text_) return;
  state_ = state;
  detail_text_ = detail;
  if (state == OperatorState::kNoButton || state == OperatorState::kIdle ||
      state == OperatorState::kRefused) {
    view_->SetOutline({});
    view_->SetRing(std::nullopt);
  }
  UpdateControls();
}

void OperatorPanel::SetDetailText(const QString& detail) {
  detail_text_ = detail;
  UpdateControls();
}

void OperatorPanel::ReturnToStop(const QString& detail) {
  state_ = OperatorState::kStopped;
  detail_text_ = detail;
  view_->SetOutline({});
  view_->SetRing(std::nullopt);
  UpdateControls();
}

void OperatorPanel::Refuse(const QString& why) {
  if (state_ == OperatorState::kConfirm) return;  // The question stays open.
  SetState(OperatorState::kRefused, why);
}

void OperatorPanel::SetRing(std::optional<QPointF> centre, double radius_px) {
  view_->SetRing(centre, radius_px);
}

void OperatorPanel::SetDistance(double metres) {
  distance_m_ = metres;
  UpdateControls();
}

void OperatorPanel::SetLink(OperatorLink link, const QString& detail) {
  if (link == link_ && detail == link_detail_) return;
  link_ = link;
  link_detail_ = detail;
  UpdateControls();
}

QString OperatorPanel::LinkText() const {
  QString text;
  switch (link_) {
    case OperatorLink::kLocal:
      return {};
    case OperatorLink::kLive:
      text = tr("Robot: live");
      break;
    case OperatorLink::kWaiting:
      text = tr("Waiting for the robot's picture");
      break;
    case OperatorLink::kStale:
      text = tr("Picture stale: no taps");
      break;
    case OperatorLink::kDisconnected:
      text = tr("Disconnected: reconnecting");
      break;
  }
  return link_detail_.isEmpty() ? text : text + "\n" + link_detail_;
}

void OperatorPanel::SetFullScreenMode(bool on) {
  const QScreen* s = screen();
  const QRect area = s ? s->geometry() : QRect();
  if (on) {
    // The window manager makes a full-screen window cover the screen; without one (a kiosk
    // session) the geometry does.
    if (!area.isEmpty()) setGeometry(area);
    showFullScreen();
    return;
  }
  showNormal();
  if (!area.isEmpty() && size() == area.size()) {
    setGeometry(
        QRect(area.topLeft() + QPoint(area.width() / 8, area.height() / 8), area.size() * 3 / 4));
  }
}

int OperatorPanel::MinTouchTargetPx() const {
  // Logical pixels per physical inch. A platform that does not know the screen's size reports
  // nonsense (0, or thousands): then 96 dpi, the common desktop figure.
  double dpi = 0;
  if (const QScreen* s = screen()) dpi = s->physicalDotsPerInch();
  if (!(dpi >= 50 && dpi <= 1000)) dpi = 96;
  return int(std::ceil(kMinTouchTargetMm / 25.4 * dpi));
}

void OperatorPanel::ApplyTouchSizes() {
  const int side = MinTouchTargetPx();
  const int width = 4 * side;
  QFont big = font();
  big.setPixelSize(std::max(18, side * 2 / 5));
  QFont huge = big;
  huge.setPixelSize(std::max(28, side * 3 / 4));
  for (QPushButton* b : {yes_, cancel_, start_}) {
    b->setFixedSize(width, side);
    b->setFont(big);
  }
  stop_->setFixedSize(width, 2 * side);
  stop_->setFont(huge);
  banner_->setFont(big);
  banner_->setFixedSize(width, 3 * big.pixelSize() + 16);  // Two lines and the padding.
  detail_->setFont(big);
  link_label_->setFont(big);
  link_label_->setFixedSize(width, 2 * big.pixelSize() + 12);  // Two lines and the padding.
  detail_->setFixedSize(width, 4 * big.pixelSize() + 8);       // Three lines.
  distance_->setFont(huge);
  distance_->setFixedSize(width, side);
  const int spacing = std::max(6, side / 6);
  question_page_->layout()->setSpacing(spacing);
  answers_->setFixedSize(width, 2 * side + spacing);
  side_->setFixedWidth(width);
}

QString OperatorPanel::BannerText(OperatorState state) const {
  switch (state) {
    case OperatorState::kIdle:
      return tr("Tap a button");
    case OperatorState::kConfirm:
      return tr("Press this button?");
    case OperatorState::kNoButton:
      return tr("No button here - tap again");
    case OperatorState::kSearching:
      return tr("Searching");
    case OperatorState::kTracking:
      return tr("Tracking");
    case OperatorState::kLocating:
      return tr("Locating");
    case OperatorState::kTargetSent:
      return tr("Target sent");
    case OperatorState::kLost:
      return tr("Lost - hold still");
    case OperatorState::kStopped:
      return tr("Stopped");
    case OperatorState::kHolding:
      return tr("Holding: nothing sent");
    case OperatorState::kRefused:
      return tr("Tap not taken");
    case OperatorState::kTrackingOnly:
      return tr("Tracking only");
  }
  return {};
}

void OperatorPanel::UpdateControls() {
  banner_->setText(BannerText(state_));
  link_label_->setVisible(link_ != OperatorLink::kLocal);
  link_label_->setText(LinkText());
  if (link_label_->property("live").toBool() != (link_ == OperatorLink::kLive)) {
    link_label_->setProperty("live", link_ == OperatorLink::kLive);
    link_label_->style()->unpolish(link_label_);  // The style sheet's colour follows.
    link_label_->style()->polish(link_label_);
  }
  // Without a link Yes and Cancel would go nowhere; STOP is kept and sent (never disabled).
  yes_->setEnabled(link_ != OperatorLink::kDisconnected);
  cancel_->setEnabled(link_ != OperatorLink::kDisconnected);
  start_->setEnabled(link_ != OperatorLink::kDisconnected);
  // Hidden texts keep their regions (retainSizeWhenHidden): the layout never moves.
  detail_->setText(detail_text_);
  detail_->setVisible(!detail_text_.isEmpty());
  const bool asking = state_ == OperatorState::kConfirm;
  const bool stopped = state_ == OperatorState::kStopped;
  answers_->setCurrentWidget(asking ? question_page_ : stopped ? stopped_page_ : empty_page_);
  stop_->setVisible(true);  // Always.
  stop_->setEnabled(true);
  view_->SetTapsEnabled(!asking && !stopped);
  const bool show_distance = std::isfinite(distance_m_) && !stopped;
  distance_->setVisible(show_distance);
  if (show_distance) distance_->setText(tr("%1 cm").arg(std::lround(distance_m_ * 100)));
}

void OperatorPanel::Retranslate() {
  yes_->setText(tr("Yes"));
  cancel_->setText(tr("Cancel"));
  stop_->setText(tr("STOP"));
  start_->setText(tr("Start again"));
  UpdateControls();
}

void OperatorPanel::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) Retranslate();
  QWidget::changeEvent(event);
}

void OperatorPanel::showEvent(QShowEvent* event) {
  ApplyTouchSizes();  // The screen (and its DPI) is known now.
  QWidget::showEvent(event);
}

void OperatorPanel::keyPressEvent(QKeyEvent* event) {
  if (isWindow() && event->key() == Qt::Key_F11) {
    emit FullScreenToggleRequested();
    return;
  }
  if (isWindow() && event->key() == Qt::Key_Escape) {
    AskToLeave();
    return;
  }
  QWidget::keyPressEvent(event);
}

void OperatorPanel::closeEvent(QCloseEvent* event) {
  if (!isWindow()) return QWidget::closeEvent(event);
  event->ignore();  // The owner decides what leaving means (back to the main window, or quit).
  emit LeaveRequested();
}

void OperatorPanel::AskToLeave() {
  if (leave_question_ != nullptr) return;
  leave_question_ =
      new QMessageBox(QMessageBox::Question, tr("Leave"), tr("Leave the operator panel?"),
                      QMessageBox::Yes | QMessageBox::Cancel, this);
  leave_question_->setAttribute(Qt::WA_DeleteOnClose);
  leave_question_->setStyleSheet(kStyle);
  leave_question_->button(QMessageBox::Yes)->setText(tr("Yes"));
  leave_question_->button(QMessageBox::Cancel)->setText(tr("Cancel"));
  for (QAbstractButton* b : leave_question_->buttons()) {
    b->setMinimumSize(3 * MinTouchTargetPx(), MinTouchTargetPx());
  }
  connect(leave_question_, &QMessageBox::finished, this, [this](int result) {
    leave_question_ = nullptr;
    if (result == QMessageBox::Yes) emit LeaveRequested();
  });
  leave_question_->open();  // Window-modal, not blocking: STOP stays in reach underneath.
}

}  // namespace sightline
