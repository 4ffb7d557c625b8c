#include "core/io/recorded_source.h"

#include <algorithm>
#include <variant>

#include "core/common/timing.h"

namespace sightline {

Status RecordedSource::Grab() {
  if (!open_) return FailedPrecondition("Grab() before a successful Open() of " + info_.path);
  if (next_ >= info_.frame_count) {
    grabbed_ = -1;
    return OutOfRange("end of " + info_.path + " after " + std::to_string(info_.frame_count) +
                      " frames");
  }
  grabbed_ = next_++;
  return Status::Ok();
}

StatusOr<Frame> RecordedSource::Retrieve() {
  if (grabbed_ < 0) return FailedPrecondition("Retrieve() without a successful Grab()");
  StatusOr<Frame> frame = Load(grabbed_);
  if (!frame.ok()) return frame;
  SIGHTLINE_RETURN_IF_ERROR(CheckFrameSize(*frame, grabbed_));
  return frame;
}

std::string RecordedSource::FrameFile(int64_t index) const {
  return info_.path + " frame " + std::to_string(index);
}

Status RecordedSource::CheckFrameSize(const Frame& frame, int64_t index) const {
  if (info_.width <= 0 || info_.height <= 0) return Status::Ok();
  cv::Size size;
  if (const auto* mono = std::get_if<MonoFrame>(&frame)) {
    size = mono->image.size();
  } else if (const auto* stereo = std::get_if<StereoFrame>(&frame)) {
    size = stereo->left.size();  // The readers check that the right image matches.
  } else if (const auto* rgbd = std::get_if<RgbdFrame>(&frame)) {
    size = rgbd->color.empty() ? rgbd->depth_m.size() : rgbd->color.size();
  } else {
    return Status::Ok();  // Point clouds have no image size.
  }
  if (size.width == info_.width && size.height == info_.height) return Status::Ok();
  return ParseError(FrameFile(index) + ": image is " + std::to_string(size.width) + "x" +
                    std::to_string(size.height) + " but the recording's frames are " +
                    std::to_string(info_.width) + "x" + std::to_string(info_.height) +
                    " (the first frame and the calibration): frame " + std::to_string(index) +
                    " changes size mid-sequence");
}

Status RecordedSource::Seek(int64_t index) {
  if (!open_) return FailedPrecondition("Seek() before a successful Open() of " + info_.path);
  if (index < 0 || index > info_.frame_count) {
    return OutOfRange("cannot seek to frame " + std::to_string(index) + " of " + info_.path +
                      ", which has " + std::to_string(info_.frame_count) + " frames");
  }
  next_ = index;
  grabbed_ = -1;
  return Status::Ok();
}

const Trajectory* RecordedSource::ground_truth() const {
  return ground_truth_.has_value() ? &*ground_truth_ : nullptr;
}

void RecordedSource::Close() {
  open_ = false;
  next_ = 0;
  grabbed_ = -1;
}

double RecordedSource::FrameTimeS(int64_t index) const {
  if (index < 0 || index >= static_cast<int64_t>(times_s_.size())) return 0;
  return times_s_[static_cast<size_t>(index)];
}

Status RecordedSource::Commit(SourceInfo info, std::vector<double> times_s,
                              std::optional<Trajectory> ground_truth) {
  if (times_s.empty()) return NotFound(info.path + ": no frames");
  info.frame_count = static_cast<int64_t>(times_s.size());
  info.duration_s = times_s.back() - times_s.front();
  if (info.rate_hz <= 0) info.rate_hz = EstimateRateHz(times_s);
  info.live = false;
  info.seekable = true;
  info.has_ground_truth = ground_truth.has_value() && !ground_truth->empty();
  if (!info.has_ground_truth) ground_truth.reset();
  info_ = std::move(info);
  times_s_ = std::move(times_s);
  ground_truth_ = std::move(ground_truth);
  open_ = true;
  next_ = 0;
  grabbed_ = -1;
  return Status::Ok();
}

FrameStamp RecordedSource::MakeStamp(int64_t index) const {
  FrameStamp stamp;
  stamp.sequence_id = index;
  stamp.sensor_time_s = FrameTimeS(index);
  stamp.host_time_s = HostTimeS();
  return stamp;
}

double RecordedSource::EstimateRateHz(const std::vector<double>& times_s) {
  if (times_s.size() < 2) return 0;
  std::vector<double> intervals;
  intervals.reserve(times_s.size() - 1);
  for (size_t i = 1; i < times_s.size(); ++i) intervals.push_back(times_s[i] - times_s[i - 1]);
  std::nth_element(intervals.begin(), intervals.begin() + intervals.size() / 2, intervals.end());
  const double median = intervals[intervals.size() / 2];
  return median > 0 ? 1.0 / median : 0;
}

}  // namespace sightline
