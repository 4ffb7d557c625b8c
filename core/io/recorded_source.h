// Shared bookkeeping of file-backed recordings (dataset readers): frame index, Grab/Seek/Position,
// info() and ground truth. Readers fill the state in Open() and decode one frame in Load().
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/io/source.h"

namespace sightline {

// A recording on disk whose frames are addressed by index. Subclasses implement Open(), which
// ends with Commit(), and Load(index). Grab() only moves the index; Retrieve() decodes.
//
//   class MyReader : public RecordedSource {
//    public:
//     Status Open() override { ...; return Commit(std::move(info), std::move(times), gt); }
//    protected:
//     StatusOr<Frame> Load(int64_t index) override { ... }
//   };
class RecordedSource : public Source {
 public:
  // Source interface. Grab() is FailedPrecondition before a successful Open(), OutOfRange at
  // the end; Seek(frame_count) is allowed (the next Grab() is then OutOfRange).
  const SourceInfo& info() const override { return info_; }
  Status Grab() override;
  StatusOr<Frame> Retrieve() override;
  int64_t Position() const override { return next_; }
  Status Seek(int64_t index) override;
  const Trajectory* ground_truth() const override;
  // Forgets the position; Open() again to reuse.
  void Close() override;

  // Dataset timestamp of frame `index` in seconds (0 when out of range).
  double FrameTimeS(int64_t index) const;

 protected:
  // Decodes frame `index`, 0 <= index < frame_count. Called by Retrieve(), which then checks
  // that the frame's images have info().width x info().height pixels (the size of the first
  // frame and of the calibration): a frame of another size is a ParseError naming FrameFile().
  virtual StatusOr<Frame> Load(int64_t index) = 0;
  // The file frame `index` is read from (the left or colour image), for messages.
  virtual std::string FrameFile(int64_t index) const;

  // Publishes what Open() found and rewinds to frame 0. `times_s` has one entry per frame.
  // Fills frame_count, duration_s, rate_hz (when 0: estimated from the times), seekable and
  // has_ground_truth.
  Status Commit(SourceInfo info, std::vector<double> times_s,
                std::optional<Trajectory> ground_truth);

  // The stamp of frame `index`, with the host time of now.
  FrameStamp MakeStamp(int64_t index) const;

  // Frames per second from the median interval between timestamps; 0 for fewer than 2 frames.
  static double EstimateRateHz(const std::vector<double>& times_s);

 private:
  // ParseError naming the frame's file when its images are not info().width x info().height.
  Status CheckFrameSize(const Frame& frame, int64_t index) const;

  SourceInfo info_;
  std::vector<double> times_s_;
  std::optional<Trajectory> ground_truth_;
  bool open_ = false;
  int64_t next_ = 0;      // Index the next Grab() acquires.
  int64_t grabbed_ = -1;  // Index acquired by the last successful Grab(), -1 = none.
};

}  // namespace sightline
