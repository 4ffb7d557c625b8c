// The operator's button picker panel (tablet style): the live image fills the screen, a tap
// picks a button, the found button is outlined with "Press this button?" Yes / Cancel, the
// tracked button is ringed on every frame, a banner says whether targets go to the arm ("Target
// sent") or not ("Holding: nothing sent" and why), the target's distance in cm, and a STOP
// control that is always visible and always works. Fixed regions (banner, detail, distance,
// question buttons) that never move with the text; touch targets of at least 15 mm on the
// screen's physical DPI; high contrast, short words, all text through tr(). Without a metric
// scale (no arm) it says "Tracking only" and never "Target sent". As a window of its
// own (operator mode, full screen) F11 asks for a normal window and back, Esc asks before
// leaving.
#pragma once

#include <QPointF>
#include <QPolygonF>
#include <QWidget>
#include <opencv2/core.hpp>
#include <optional>

class QLabel;
class QMessageBox;
class QPushButton;
class QStackedWidget;

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
  kTargetSent,    // Targets go to the arm.
  kLost,          // "Lost - hold still"
  kStopped,       // After STOP until "Start again"
  kHolding,       // "Holding: nothing sent"; the detail says why (paused, button lost, ...).
  kRefused,       // "Tap not taken"; the detail says why (the picture is paused, ...).
  kTrackingOnly,  // "Tracking only": no metric scale (no arm motion), nothing is ever sent.
};

// Where the panel's picture comes from and whether it is current: the GUI's own pipeline, or a
// sightline-node on another machine whose link can stall or break.
enum class OperatorLink {
  kLocal,         // The GUI's own pipeline (no link line shown).
  kLive,          // A remote node's picture arrives.
  kWaiting,       // Connected; no picture from the node yet. Taps refused.
  kStale,         // No picture for a while: the view is old, taps refused.
  kDisconnected,  // The master or the node is gone: taps, Yes and Cancel off; STOP still works.
};

// A view of the button pipeline: it emits what the operator asks for and shows what the
// pipeline reports; it never decides about the arm itself.
//
//   panel->SetImage(frame);
//   connect(panel, &OperatorPanel::Tapped, controller, &Controller::DetectAt);
//   panel->ShowCandidate(outline);               // -> Confirmed() or Cancelled()
//   panel->SetState(OperatorState::kHolding, tr("Paused"));
//   panel->SetRing(centre, radius);              // The tracked button, every frame.
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
  // Shows the state in the banner; `detail` (e.g. the reason for holding) below it.
  // Ignored while stopped: only "Start again" leaves STOP.
  void SetState(OperatorState state, const QString& detail = {});
  // The detail line as it is, and the same line in the GUI's new language after a language
  // switch (the state stays).
  const QString& detail_text() const { return detail_text_; }
  void SetDetailText(const QString& detail);
  // Back to STOP without emitting StopPressed, saying why (e.g. "Start again" did not reach the
  // robot, which therefore stays stopped).
  void ReturnToStop(const QString& detail);
  // The operator's tap was not taken: says why, and the operator may tap again.
  void Refuse(const QString& why);
  // The tracked button's centre and radius in image pixels; nullopt hides the ring.
  void SetRing(std::optional<QPointF> centre, double radius_px = 0);
  // Distance to the target in metres; NaN hides it.
  void SetDistance(double metres);
  // The link's state in a line above the banner (hidden for kLocal); `detail` after it (e.g. the
  // picture's age). Taps on a picture that is not live are refused with words.
  void SetLink(OperatorLink link, const QString& detail = {});
  OperatorLink link() const { return link_; }
  // Full screen for the tablet (true) or a normal window (false).
  void SetFullScreenMode(bool on);

  OperatorState state() const { return state_; }
  // Smallest touch target side in logical pixels: 15 mm at the screen's physical DPI (96 dpi
  // when the platform does not know the screen's size).
  int MinTouchTargetPx() const;
  static constexpr double kMinTouchTargetMm = 15.0;

  // Children, for tests and keyboard shortcuts.
  TapImageView* image_view() const { return view_; }
  QPushButton* stop_button() const { return stop_; }
  QPushButton* start_button() const { return start_; }
  QPushButton* yes_button() const { return yes_; }
  QPushButton* cancel_button() const { return cancel_; }
  QLabel* banner() const { return banner_; }
  QLabel* detail_label() const { return detail_; }
  QLabel* distance_label() const { return distance_; }
  QLabel* link_label() const { return link_label_; }
  // The open "Leave the operator panel?" question, or null.
  QMessageBox* leave_question() const { return leave_question_; }

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
  // F11 while the panel is a window of its own: full screen <-> normal window.
  void FullScreenToggleRequested();
  // The operator confirmed leaving the panel (Esc, then Yes) or closed its window.
  void LeaveRequested();

 protected:
  void changeEvent(QEvent* event) override;
  void showEvent(QShowEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void closeEvent(QCloseEvent* event) override;

 private:
  void BuildLayout();
  void ConnectButtons();
  void Retranslate();
  void ApplyTouchSizes();
  void UpdateControls();
  void AskToLeave();
  QString BannerText(OperatorState state) const;
  QString LinkText() const;

  TapImageView* view_ = nullptr;
  QWidget* side_ = nullptr;
  QLabel* banner_ = nullptr;
  QLabel* link_label_ = nullptr;
  QLabel* detail_ = nullptr;
  QLabel* distance_ = nullptr;
  QStackedWidget* answers_ = nullptr;  // Empty, Yes / Cancel, or Start again: one fixed region.
  QWidget* question_page_ = nullptr;
  QWidget* stopped_page_ = nullptr;
  QWidget* empty_page_ = nullptr;
  QPushButton* yes_ = nullptr;
  QPushButton* cancel_ = nullptr;
  QPushButton* stop_ = nullptr;
  QPushButton* start_ = nullptr;
  QMessageBox* leave_question_ = nullptr;
  OperatorState state_ = OperatorState::kIdle;
  QString detail_text_;
  OperatorLink link_ = OperatorLink::kLocal;
  QString link_detail_;
  double distance_m_;
};

}  // namespace sightline
