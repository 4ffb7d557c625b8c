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
    const std::string id = "camera_rgb_optical_frame";
    if (!f.color.empty()) {
      SIGHTLINE_RETURN_IF_ERROR(bag_->WriteImage("/camera/rgb/image_color", t, f.color, id));
    }
    SIGHTLINE_RETURN_IF_ERROR(bag_->WriteImage("/camera/depth/image", t, f.depth_m, id));
    return bag_->WriteCameraInfo("/camera/rgb/camera_info", t, info_.rgbd->color, id);
  }
  Status WriteFrame(const StereoFrame& f, double t) {
    const StereoRig& rig = *info_.stereo;
    SIGHTLINE_RETURN_IF_ERROR(bag_->WriteImage("/stereo/left/image_raw", t, f.left, "stereo_left"));
    SIGHTLINE_RETURN_IF_ERROR(
        bag_->WriteImage("/stereo/right/image_raw", t, f.right, "stereo_right"));
    SIGHTLINE_RETURN_IF_ERROR(
        bag_->WriteCameraInfo("/stereo/left/camera_info", t, rig.left, "stereo_left"));
    return bag_->WriteCameraInfo("/stereo/right/camera_info", t, rig.right, "stereo_right",
                                 rig.BaselineM());
  }
  Status WriteFrame(const MonoFrame& f, double t) {
    SIGHTLINE_RETURN_IF_ERROR(bag_->WriteImage("/mono/image_raw", t, f.image, "mono_camera"));
    return bag_->WriteCameraInfo("/mono/camera_info", t, *info_.camera, "mono_camera");
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
