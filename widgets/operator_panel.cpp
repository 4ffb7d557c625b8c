#include "widgets/operator_panel.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScreen>
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
  view_ = new TapImageView(this);
  banner_ = new QLabel(this);
  banner_->setObjectName("banner");
  banner_->setAlignment(Qt::AlignCenter);
  detail_ = new QLabel(this);
  detail_->setAlignment(Qt::AlignCenter);
  detail_->setWordWrap(true);
  distance_ = new QLabel(this);
  distance_->setObjectName("distance");
  distance_->setAlignment(Qt::AlignCenter);
  yes_ = new QPushButton(this);
  yes_->setObjectName("yes");
  cancel_ = new QPushButton(this);
  stop_ = new QPushButton(this);
  stop_->setObjectName("stop");
  start_ = new QPushButton(this);

  auto* side = new QVBoxLayout;
  side->addWidget(stop_, 2);
  side->addWidget(banner_);
  side->addWidget(detail_);
  side->addWidget(distance_);
  side->addStretch(1);
  side->addWidget(yes_);
  side->addWidget(cancel_);
  side->addWidget(start_);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(view_, 1);
  layout->addLayout(side);

  connect(view_, &TapImageView::Tapped, this, [this](QPointF p) {
    if (state_ != OperatorState::kStopped && state_ != OperatorState::kConfirm) emit Tapped(p);
  });
  connect(yes_, &QPushButton::clicked, this, [this] {
    view_->SetTapsEnabled(true);
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
    view_->SetOutline({});
    UpdateControls();
    emit StartRequested();
  });
  Retranslate();
  ApplyTouchSizes();
  UpdateControls();
}

void OperatorPanel::SetImage(const cv::Mat& image) { view_->SetImage(image); }

void OperatorPanel::ShowCandidate(const QPolygonF& outline_in_image) {
  if (state_ == OperatorState::kStopped) return;
  view_->SetOutline(outline_in_image);
  SetState(OperatorState::kConfirm);
}

void OperatorPanel::SetState(OperatorState state, const QString& detail) {
  if (state_ == OperatorState::kStopped) return;  // Only "Start again" leaves STOP.
  state_ = state;
  detail_text_ = detail;
  if (state == OperatorState::kNoButton || state == OperatorState::kIdle) view_->SetOutline({});
  UpdateControls();
}

void OperatorPanel::SetDistance(double metres) {
  distance_m_ = metres;
  UpdateControls();
}

void OperatorPanel::SetFullScreenMode(bool on) {
  if (on)
    showFullScreen();
  else
    showNormal();
}

int OperatorPanel::MinTouchTargetPx() const {
  // Logical pixels per physical inch; falls back to the logical DPI when the platform does not
  // know the screen's size.
  double dpi = 0;
  if (const QScreen* s = screen()) dpi = s->physicalDotsPerInch();
  if (!(dpi > 20 && dpi < 2000)) dpi = logicalDpiX();
  return int(std::ceil(kMinTouchTargetMm / 25.4 * dpi));
}

void OperatorPanel::ApplyTouchSizes() {
  const int side = MinTouchTargetPx();
  QFont big = font();
  big.setPixelSize(std::max(18, side / 2));
  for (QPushButton* b : {yes_, cancel_, start_}) {
    b->setMinimumSize(3 * side, side);
    b->setFont(big);
  }
  QFont huge = big;
  huge.setPixelSize(std::max(28, side));
  stop_->setMinimumSize(3 * side, 2 * side);
  stop_->setFont(huge);
  banner_->setFont(big);
  distance_->setFont(huge);
  banner_->setMinimumWidth(3 * side);
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
  }
  return {};
}

void OperatorPanel::UpdateControls() {
  banner_->setText(BannerText(state_));
  detail_->setText(detail_text_);
  detail_->setVisible(!detail_text_.isEmpty());
  const bool asking = state_ == OperatorState::kConfirm;
  yes_->setVisible(asking);
  cancel_->setVisible(asking);
  start_->setVisible(state_ == OperatorState::kStopped);
  stop_->setVisible(true);  // Always.
  stop_->setEnabled(true);
  view_->SetTapsEnabled(!asking && state_ != OperatorState::kStopped);
  const bool show_distance = std::isfinite(distance_m_) && state_ != OperatorState::kStopped;
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

}  // namespace sightline
