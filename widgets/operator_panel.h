// The operator's button picker panel (tablet style): the live image fills the screen, a tap
// picks a button, the found button is outlined with "Press this button?" Yes / Cancel, a
// banner shows the state (Searching / Tracking / Locating / Target sent / Lost - hold still),
// the target's distance in cm, and a STOP control that is always visible and always works.
// Large touch targets (>= 9 mm on the screen's physical DPI), high contrast, short words, all
// text through tr().
#pragma once

#include <QPointF>
#include <QPolygonF>
#include <QWidget>
#include <opencv2/core.hpp>

class QLabel;
class QPushButton;

namespace sightline {

class TapImageView;

// What the panel shows in its banner.
enum class OperatorState {
  kIdle,      // "Tap a button"
  kConfirm,   // "Press this button?" with Yes / Cancel
  kNoButton,  // "No button here - tap again"
  kSearching,
  kTracking,
  kLocating,
  kTargetSent,
  kLost,     // "Lost - hold still"
  kStopped,  // After STOP until "Start again"
};

// A view of the button pipeline: it emits what the operator asks for and shows what the
// pipeline reports; it never decides about the arm itself.
//
//   panel->SetImage(frame);
//   connect(panel, &OperatorPanel::Tapped, controller, &Controller::DetectAt);
//   panel->ShowCandidate(outline);               // -> Confirmed() or Cancelled()
//   panel->SetState(OperatorState::kTracking);
//   panel->SetDistance(0.234);                   // "23 cm"
//   connect(panel, &OperatorPanel::StopPressed, server, ...);  // Emitted on press, at once.
class OperatorPanel : public QWidget {
  Q_OBJECT

 public:
  explicit OperatorPanel(QWidget* parent = nullptr);

  // The live image (BGR, BGRA or grey, 8-bit).
  void SetImage(const cv::Mat& image);
  // The button found at the tap, outlined in image pixels; asks "Press this button?".
  void ShowCandidate(const QPolygonF& outline_in_image);
  // Shows the state in the banner; `detail` (e.g. the safety gate's reason) below it.
  // Ignored while stopped, except kIdle after StartRequested.
  void SetState(OperatorState state, const QString& detail = {});
  // Distance to the target in metres; NaN hides it.
  void SetDistance(double metres);
  // Full screen for the tablet (true) or a normal window (false).
  void SetFullScreenMode(bool on);

  OperatorState state() const { return state_; }
  // Smallest touch target side in logical pixels: 9 mm at the screen's physical DPI.
  int MinTouchTargetPx() const;
  static constexpr double kMinTouchTargetMm = 9.0;

  // Children, for tests and keyboard shortcuts.
  TapImageView* image_view() const { return view_; }
  QPushButton* stop_button() const { return stop_; }
  QPushButton* start_button() const { return start_; }
  QPushButton* yes_button() const { return yes_; }
  QPushButton* cancel_button() const { return cancel_; }
  QLabel* banner() const { return banner_; }
  QLabel* detail_label() const { return detail_; }
  QLabel* distance_label() const { return distance_; }

 signals:
  // The operator tapped the image at this pixel (not while a question or STOP is shown).
  void Tapped(QPointF image_px);
  // "Yes": press the outlined button.
  void Confirmed();
  // "Cancel": pick again.
  void Cancelled();
  // STOP, emitted on press (not release) so it is never late.
  void StopPressed();
  // "Start again" after STOP.
  void StartRequested();

 protected:
  void changeEvent(QEvent* event) override;
  void showEvent(QShowEvent* event) override;

 private:
  void Retranslate();
  void ApplyTouchSizes();
  void UpdateControls();
  QString BannerText(OperatorState state) const;

  TapImageView* view_ = nullptr;
  QLabel* banner_ = nullptr;
  QLabel* detail_ = nullptr;
  QLabel* distance_ = nullptr;
  QPushButton* yes_ = nullptr;
  QPushButton* cancel_ = nullptr;
  QPushButton* stop_ = nullptr;
  QPushButton* start_ = nullptr;
  OperatorState state_ = OperatorState::kIdle;
  QString detail_text_;
  double distance_m_;
};

}  // namespace sightline
