// Playback control over a Source: at recorded rate or as fast as possible, pause, step, seek, loop.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>

#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/io/source.h"

namespace sightline {

// Paces a Source. Control calls may come from any thread (the GUI); Next() is called by one
// reading thread, which it blocks until a frame is due. Waiting is on a condition variable, so
// control calls take effect at once.
//
//   Player player(std::move(source));
//   player.Play();
//   while (true) {
//     StatusOr<Frame> frame = player.Next();   // Waits while paused.
//     if (!frame.ok()) break;                  // kCancelled after Stop(), kOutOfRange at end.
//     Show(*frame);
//   }
class Player {
 public:
  explicit Player(std::unique_ptr<Source> source);

  const SourceInfo& info() const { return source_->info(); }
  const Trajectory* ground_truth() const { return source_->ground_truth(); }

  // Starts or resumes playback.
  void Play();
  // Stops delivering frames until Play() or Step().
  void Pause();
  // Delivers exactly one frame, then pauses.
  void Step();
  // Moves to frame `index`; the next Next() delivers it (also while paused).
  void Seek(int64_t index);
  // Playback speed relative to the recording; 0 plays as fast as possible.
  void SetSpeed(double factor);
  // At the end, start again from the first frame.
  void SetLoop(bool loop);
  // Ends playback: a waiting Next() returns kCancelled.
  void Stop();

  bool playing() const;
  int64_t position() const;  // Index of the next frame.

  // Blocks until a frame is due, then grabs and decodes it.
  StatusOr<Frame> Next();

 private:
  // Resets the pacing reference so that the next frame is due now.
  void ResetClockLocked();

  std::unique_ptr<Source> source_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool playing_ = false;
  bool stopped_ = false;
  bool loop_ = false;
  int steps_pending_ = 0;
  int64_t seek_to_ = -1;
  int64_t position_ = 0;  // source_->Position() after the last Next().
  double speed_ = 1.0;
  // Pacing: frame with sensor time t is due at host_anchor_ + (t - sensor_anchor_) / speed_.
  bool clock_valid_ = false;
  double sensor_anchor_ = 0;
  double host_anchor_ = 0;
};

}  // namespace sightline
