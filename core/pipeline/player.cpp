#include "core/pipeline/player.h"

#include <chrono>

#include "core/common/timing.h"

namespace sightline {

Player::Player(std::unique_ptr<Source> source) : source_(std::move(source)) {}

void Player::Play() {
  std::lock_guard<std::mutex> lock(mutex_);
  playing_ = true;
  ResetClockLocked();
  wake_.notify_all();
}

void Player::Pause() {
  std::lock_guard<std::mutex> lock(mutex_);
  playing_ = false;
  steps_pending_ = 0;
  wake_.notify_all();
}

void Player::Step() {
  std::lock_guard<std::mutex> lock(mutex_);
  playing_ = false;
  ++steps_pending_;
  wake_.notify_all();
}

void Player::Seek(int64_t index) {
  std::lock_guard<std::mutex> lock(mutex_);
  seek_to_ = index;
  ResetClockLocked();
  wake_.notify_all();
}

void Player::SetSpeed(double factor) {
  std::lock_guard<std::mutex> lock(mutex_);
  speed_ = factor < 0 ? 0 : factor;
  ResetClockLocked();
  wake_.notify_all();
}

void Player::SetLoop(bool loop) {
  std::lock_guard<std::mutex> lock(mutex_);
  loop_ = loop;
}

void Player::Stop() {
  std::lock_guard<std::mutex> lock(mutex_);
  stopped_ = true;
  wake_.notify_all();
}

bool Player::playing() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return playing_;
}

int64_t Player::position() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return seek_to_ >= 0 ? seek_to_ : position_;
}

void Player::ResetClockLocked() { clock_valid_ = false; }

StatusOr<Frame> Player::Next() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    wake_.wait(lock, [&] { return stopped_ || playing_ || steps_pending_ > 0 || seek_to_ >= 0; });
    if (stopped_) return Cancelled("playback stopped");

    bool forced = false;  // A seek or step delivers one frame regardless of pacing.
    if (seek_to_ >= 0) {
      const int64_t target = seek_to_;
      seek_to_ = -1;
      lock.unlock();
      const Status sought = source_->Seek(target);
      lock.lock();
      if (!sought.ok()) return sought;
      forced = !playing_;
    } else if (!playing_) {
      --steps_pending_;
      forced = true;
    }

    // Only this thread touches the source: decode without holding the lock so that control
    // calls from the GUI never wait for file I/O.
    const bool loop = loop_;
    lock.unlock();
    Status grabbed = source_->Grab();
    bool wrapped = false;
    if (grabbed.code() == StatusCode::kOutOfRange && loop && info().seekable) {
      grabbed = source_->Seek(0);
      if (grabbed.ok()) grabbed = source_->Grab();
      wrapped = true;
    }
    StatusOr<Frame> frame = grabbed.ok() ? source_->Retrieve() : StatusOr<Frame>(grabbed);
    lock.lock();
    position_ = source_->Position();
    if (wrapped) ResetClockLocked();
    if (!grabbed.ok()) {
      if (grabbed.code() == StatusCode::kOutOfRange) playing_ = false;
      return grabbed;
    }
    if (!frame.ok()) return frame;

    if (!forced && speed_ > 0 && !info().live) {
      const double t = StampOf(*frame).sensor_time_s;
      if (!clock_valid_) {
        clock_valid_ = true;
        sensor_anchor_ = t;
        host_anchor_ = HostTimeS();
      }
      const double due_host = host_anchor_ + (t - sensor_anchor_) / speed_;
      const auto due = std::chrono::steady_clock::time_point(
          std::chrono::duration_cast<std::chrono::steady_clock::duration>(
              std::chrono::duration<double>(due_host)));
      // Wait until due, unless a control call changes the plan.
      const bool interrupted = wake_.wait_until(
          lock, due, [&] { return stopped_ || !playing_ || seek_to_ >= 0 || !clock_valid_; });
      if (interrupted && stopped_) return Cancelled("playback stopped");
      // A pause, seek or speed change while waiting: the frame is still delivered; pacing
      // restarts from the next one.
    }
    return frame;
  }
}

}  // namespace sightline
