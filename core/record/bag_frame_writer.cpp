#include "core/record/bag_frame_writer.h"

#include <cmath>
#include <filesystem>
#include <variant>

#include "core/common/text_file.h"

#ifdef SIGHTLINE_HAVE_ROS
#include "core/ros/bag_writer.h"
#endif

namespace sightline {

#ifdef SIGHTLINE_HAVE_ROS
namespace {

class BagFrameWriter : public FrameWriter {
 public:
  BagFrameWriter(std::string path, SourceInfo info, std::unique_ptr<BagWriter> bag)
      : path_(std::move(path)), info_(std::move(info)), bag_(std::move(bag)) {}
  ~BagFrameWriter() override { (void)bag_->Close(); }

  Status Write(const Frame& frame, int64_t index) override {
    const double t = StampOf(frame).sensor_time_s;
    if (index == 0 && t < 1.0) {
      offset_s_ = std::ceil(1.0 - t);
      notes_.push_back("bag stamps are the sensor times + " + std::to_string(int(offset_s_)) +
                       " s (a bag holds no time 0)");
    }
    const double stamp = t + offset_s_;
    Status written = std::visit([&](const auto& f) { return WriteFrame(f, stamp); }, frame);
    if (!written.ok())
      return Unavailable(path_ + ": frame " + std::to_string(index) + ": " + written.message());
    bytes_ = static_cast<int64_t>(std::filesystem::file_size(path_, ec_));
    return Status::Ok();
  }
  Status Finish() override {
    const Status closed = bag_->Close();
    if (!closed.ok()) return Unavailable(path_ + ": " + closed.message());
    bytes_ = static_cast<int64_t>(std::filesystem::file_size(path_, ec_));
    return Status::Ok();
  }
  const std::string& folder() const override { return path_; }
  const char* format() const override { return "ROS bag"; }

 private:
  Status WriteFrame(const RgbdFrame& f, double t) {
    return bag_->WriteRgbdFrame(t, f.color, f.depth_m, info_.rgbd->color);
  }
  Status WriteFrame(const StereoFrame& f, double t) {
    return bag_->WriteStereoFrame(t, f.left, f.right, *info_.stereo);
  }
  Status WriteFrame(const MonoFrame& f, double t) {
    return bag_->WriteMonoFrame(t, f.image, *info_.camera);
  }
  Status WriteFrame(const CloudFrame&, double) {
    return InvalidArgument("point clouds are not recorded");
  }

  std::string path_;
  SourceInfo info_;
  std::unique_ptr<BagWriter> bag_;
  double offset_s_ = 0;
  std::error_code ec_;
};

// The calibration a kind of frame needs in the bag's camera_info.
Status CheckCalibration(const SourceInfo& info) {
  const bool ok = (info.kind == SourceKind::kRgbd && info.rgbd) ||
                  (info.kind == SourceKind::kStereo && info.stereo) ||
                  (info.kind == SourceKind::kMono && info.camera);
  if (ok) return Status::Ok();
  return InvalidArgument(info.path + ": a " + SourceKindName(info.kind) +
                         " source without calibration cannot be recorded as a ROS bag "
                         "(its camera_info would be empty)");
}

}  // namespace

StatusOr<std::unique_ptr<FrameWriter>> CreateBagFrameWriter(const std::string& dir,
                                                            const SourceInfo& info) {
  if (info.kind == SourceKind::kCloud) {
    return InvalidArgument(
        "point-cloud sources cannot be recorded yet (RGB-D, stereo and mono can)");
  }
  SIGHTLINE_RETURN_IF_ERROR(CheckCalibration(info));
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return Unavailable("cannot create " + dir + ": " + ec.message());
  const std::string path = JoinPath(dir, kRecordingBagName);
  StatusOr<std::unique_ptr<BagWriter>> bag = BagWriter::Create(path, "lz4");
  if (!bag.ok()) return bag.status();
  return std::unique_ptr<FrameWriter>(new BagFrameWriter(path, info, std::move(*bag)));
}

#else

StatusOr<std::unique_ptr<FrameWriter>> CreateBagFrameWriter(const std::string& dir,
                                                            const SourceInfo& info) {
  return Unavailable("cannot record " + JoinPath(dir, kRecordingBagName) +
                     ": this Sightline was built without ROS (SIGHTLINE_WITH_ROS=OFF)");
}

#endif

}  // namespace sightline
