// The operator's commands to a running button pipeline (ButtonCommands) and the message keys of
// a tap's refusal.
#include <utility>

#include "core/pipeline/button_result.h"

namespace sightline {

const char* TapRefusalKey(TapRefusal refusal) {
  switch (refusal) {
    case TapRefusal::kNone:
      return "none";
    case TapRefusal::kNoPicture:
      return "no_picture";
    case TapRefusal::kTooOld:
      return "too_old";
    case TapRefusal::kStopped:
      return "stopped";
  }
  return "none";
}

std::optional<TapRefusal> TapRefusalOfKey(const std::string& key) {
  for (TapRefusal r :
       {TapRefusal::kNone, TapRefusal::kNoPicture, TapRefusal::kTooOld, TapRefusal::kStopped}) {
    if (key == TapRefusalKey(r)) return r;
  }
  return std::nullopt;
}

void ButtonCommands::Tap(const ButtonTapRequest& tap) {
  std::lock_guard<std::mutex> lock(mutex_);
  pending_.tap = tap;
}

void ButtonCommands::Confirm() {
  std::lock_guard<std::mutex> lock(mutex_);
  pending_.confirm = true;
}

void ButtonCommands::Cancel() {
  std::lock_guard<std::mutex> lock(mutex_);
  pending_.cancel = true;
}

void ButtonCommands::Stop(const std::string& reason) {
  std::lock_guard<std::mutex> lock(mutex_);
  pending_.stop = true;
  stopped_ = true;
  if (stop_now_) stop_now_(reason);  // At once, not at the next frame.
}

void ButtonCommands::Restart() {
  std::lock_guard<std::mutex> lock(mutex_);
  pending_.restart = true;
  stopped_ = false;
  if (restart_now_) restart_now_();
}

bool ButtonCommands::SetHold(bool hold) {
  std::lock_guard<std::mutex> lock(mutex_);
  held_ = hold;
  if (!hold || !pending_.tap || pending_.tap->ahead) return false;
  pending_.tap.reset();  // A tap on a picture that is no longer live is never applied later.
  return true;
}

bool ButtonCommands::held() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return held_;
}

bool ButtonCommands::stopped() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stopped_;
}

ButtonCommands::Pending ButtonCommands::Take(int64_t index) {
  std::lock_guard<std::mutex> lock(mutex_);
  Pending out = pending_;
  pending_ = Pending();
  if (out.tap && out.tap->ahead && out.tap->frame > index) {  // For a later frame: it waits.
    pending_.tap = out.tap;
    out.tap.reset();
  }
  return out;
}

bool ButtonCommands::tap_pending() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return pending_.tap.has_value();
}

void ButtonCommands::PostAnswer(ButtonTapAnswer answer) {
  std::lock_guard<std::mutex> lock(mutex_);
  answer_ = std::move(answer);
}

std::optional<ButtonTapAnswer> ButtonCommands::TakeAnswer() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<ButtonTapAnswer> out = std::move(answer_);
  answer_.reset();
  return out;
}

void ButtonCommands::SetImmediate(const void* owner, std::function<void(const std::string&)> stop,
                                  std::function<void()> restart) {
  std::lock_guard<std::mutex> lock(mutex_);
  immediate_owner_ = owner;
  stop_now_ = std::move(stop);
  restart_now_ = std::move(restart);
}

void ButtonCommands::ClearImmediate(const void* owner) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (immediate_owner_ != owner) return;  // A newer pipeline object took over.
  immediate_owner_ = nullptr;
  stop_now_ = nullptr;
  restart_now_ = nullptr;
}

}  // namespace sightline
