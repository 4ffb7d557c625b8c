// Recording any source's frames to disk through a bounded queue and a writer thread.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/common/bounded_queue.h"
#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/io/source.h"
#include "core/options/option_table.h"
#include "core/record/frame_writers.h"

namespace sightline {

// How a Recorder buffers and stores frames; keys `record.*`.
struct RecorderOptions {
  int queue_capacity = 64;         // Frames buffered between the producer and the disk.
  bool block_when_full = false;    // Wait for the disk instead of dropping (recorded sources).
  int png_compression = 1;         // zlib level 0 (fast, large) to 9 (slow, small).
  bool sync = true;                // fsync every image and index line (a pulled plug loses at most
                                   // the frame being written).
  bool overwrite = false;          // Record into a folder that already holds files: its sensor
                                   // folder (e.g. DIR/mono) is removed first, other files stay.
  std::string format = "folders";  // "folders" (DIR/<sensor>/) or "bag" (DIR/recording.bag).

  bool IsValid(std::string* error) const;
  static OptionTable<RecorderOptions> Describe();
};

// Counters of a recording; a snapshot (see Recorder::stats()).
struct RecorderStats {
  uint64_t frames_offered = 0;       // Frames given to Push().
  uint64_t frames_written = 0;       // Frames completely on disk and listed in the index.
  uint64_t frames_dropped = 0;       // Offered but not written: queue full, out of order, or after
                                     // a write error. offered = written + dropped + queued.
  uint64_t frames_out_of_order = 0;  // Of the dropped: sensor time not after the previous one.
  int64_t bytes_written = 0;         // Images and index lines.
  double elapsed_s = 0;              // Since Start().
  double write_mb_per_s = 0;         // bytes_written / elapsed_s / 1e6.
  bool failed = false;               // A write failed; the recording stopped (see status()).
};

// One frame that reached the disk, for acknowledgements.
struct WrittenFrame {
  int64_t index = 0;  // Position in the recording, from 0.
  FrameStamp stamp;   // As the source delivered it.
};

// Records frames of one source into DIR/<sensor>/ (frame_writers.h) on its own thread. Push()
// never waits for the disk unless block_when_full: a full queue drops the oldest frame and
// counts it. A write error (disk full, file size limit, folder removed) stops the recording
// with a Status naming the file; what was written stays a valid recording.
//
//   auto recorder = Recorder::Start("/data/rec1", source.info(), RecorderOptions());
//   if (!recorder.ok()) return recorder.status();
//   while (source.Grab().ok()) (*recorder)->Push(*source.Retrieve());
//   Status s = (*recorder)->Stop();   // drains the queue; the first write error, if any
//   RecorderStats st = (*recorder)->stats();
class Recorder {
 public:
  // Creates the folders and calibration, starts the writer thread. `on_written`, if set, is
  // called on the writer thread after each frame is durable. `dir` must be new or empty (or a
  // file there is an error): a folder that already holds files is FailedPrecondition naming it,
  // so that an earlier recording is never truncated or left with orphan images, unless
  // options.overwrite, which replaces DIR/<sensor>/ as a whole.
  static StatusOr<std::unique_ptr<Recorder>> Start(
      const std::string& dir, const SourceInfo& info, const RecorderOptions& options,
      std::function<void(const WrittenFrame&)> on_written = nullptr);
  ~Recorder();
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  // Queues a frame for writing (any thread). False when it was not accepted: the recorder is
  // stopped or failed (the frame is counted as dropped).
  bool Push(Frame frame);
  // Writes what is queued, stops the thread and closes the files. Returns the first write
  // error or Ok. Idempotent.
  Status Stop();
  // The first write error so far, or Ok (any thread).
  Status status() const;
  RecorderStats stats() const;
  // The sensor folder, e.g. "DIR/rgbd", and its format name.
  const std::string& folder() const { return writer_->folder(); }
  const char* format() const { return writer_->format(); }
  const std::vector<std::string>& notes() const { return writer_->notes(); }

 private:
  Recorder() = default;
  void WriterLoop();

  RecorderOptions options_;
  std::unique_ptr<FrameWriter> writer_;
  std::unique_ptr<BoundedQueue<Frame>> queue_;
  std::function<void(const WrittenFrame&)> on_written_;
  std::thread thread_;
  double start_s_ = 0;

  mutable std::mutex mutex_;  // Guards everything below.
  Status status_;
  RecorderStats stats_;
  uint64_t rejected_ = 0;       // Push() after stop or failure.
  uint64_t lost_on_error_ = 0;  // Queued frames discarded after a write error.
  double last_time_s_ = 0;
  bool have_time_ = false;
  double stop_s_ = 0;
};

}  // namespace sightline
