#include "core/ros/bag_source.h"

#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/Image.h>

#include <algorithm>
#include <numeric>
#include <opencv2/imgproc.hpp>

#include "core/io/tum_rgbd_source.h"
#include "core/ros/bag_messages.h"
#include "core/ros/message_check.h"
#include "core/ros/ros_image.h"

namespace sightline {
namespace {

// The messages of one topic in bag order, with their stamps.
struct TopicMessages {
  std::string topic;
  std::vector<rosbag::MessageInstance> messages;
  std::vector<double> stamps;
};

Status AtMessage(const Status& status, const std::string& path, const std::string& topic,
                 int64_t index) {
  return status.WithContext(path + ": " + topic + " message " + std::to_string(index));
}

TopicMessages CollectTopic(const rosbag::Bag& bag, const std::string& topic) {
  TopicMessages out;
  out.topic = topic;
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery(topic))) {
    out.messages.push_back(m);
    out.stamps.push_back(MessageStampS(m));
  }
  return out;
}

// Message indices of `t` in stamp order.
std::vector<size_t> StampOrder(const TopicMessages& t) {
  std::vector<size_t> order(t.stamps.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return t.stamps[a] < t.stamps[b]; });
  return order;
}

std::vector<TimedFile> AsTimed(const TopicMessages& t) {
  std::vector<TimedFile> out;
  for (size_t i = 0; i < t.stamps.size(); ++i) out.push_back({t.stamps[i], t.topic, int(i)});
  return out;
}

StatusOr<cv::Mat> DecodeImage(const TopicMessages& t, size_t index, RosImageRole role,
                              const std::string& path) {
  const rosbag::MessageInstance& m = t.messages[index];
  StatusOr<cv::Mat> image = InvalidArgument("is a " + m.getDataType() + ", not an image");
  if (m.getDataType() == kRosCompressedImageType && role == RosImageRole::kColor) {
    if (auto msg = InstantiateChecked<sensor_msgs::CompressedImage>(m)) {
      image = DecodeRosCompressedImage(*msg);
    }
  } else if (auto msg = InstantiateChecked<sensor_msgs::Image>(m)) {
    image = DecodeRosImage(*msg, role);
  }
  if (!image.ok()) return AtMessage(image.status(), path, t.topic, int64_t(index));
  return image;
}

StatusOr<sensor_msgs::CameraInfo> FirstCameraInfo(const rosbag::Bag& bag, const std::string& path,
                                                  const std::string& topic) {
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery(topic))) {
    if (auto info = InstantiateChecked<sensor_msgs::CameraInfo>(m)) return *info;
    return ParseError(path + ": " + topic + " message 0 is a " + m.getDataType() +
                      ", not a sensor_msgs/CameraInfo");
  }
  return NotFound(path + ": " + topic + " has no messages");
}

StatusOr<PinholeCamera> CameraOf(const rosbag::Bag& bag, const std::string& path,
                                 const std::string& topic) {
  StatusOr<sensor_msgs::CameraInfo> info = FirstCameraInfo(bag, path, topic);
  if (!info.ok()) return info.status();
  StatusOr<PinholeCamera> camera = CameraFromRosInfo(*info);
  if (!camera.ok()) return AtMessage(camera.status(), path, topic, 0);
  return camera;
}

// Left and right cameras; the right CameraInfo's P[3] = -fx * baseline gives the baseline.
StatusOr<StereoRig> StereoOf(const rosbag::Bag& bag, const std::string& path,
                             const BagTopicChoice& choice) {
  StereoRig rig;
  StatusOr<PinholeCamera> left = CameraOf(bag, path, choice.camera_info);
  if (!left.ok()) return left.status();
  StatusOr<PinholeCamera> right = CameraOf(bag, path, choice.right_camera_info);
  if (!right.ok()) return right.status();
  StatusOr<sensor_msgs::CameraInfo> info = FirstCameraInfo(bag, path, choice.right_camera_info);
  if (!info.ok()) return info.status();
  const double baseline = info->P[0] > 0 ? -info->P[3] / info->P[0] : 0;
  if (!(baseline > 0)) {
    return InvalidArgument(path + ": " + choice.right_camera_info + " message 0: P[3] is " +
                           std::to_string(info->P[3]) +
                           ", so the right camera's projection gives no baseline (P[3] = -fx * "
                           "baseline); choose the right camera's CameraInfo with "
                           "io.rosbag.right_camera_info_topic");
  }
  rig.left = *left;
  rig.right = *right;
  rig.right_from_left.translation() = Eigen::Vector3d(-baseline, 0, 0);
  rig.rectified = !left->HasDistortion() && !right->HasDistortion();
  SIGHTLINE_RETURN_IF_ERROR(rig.Validate().WithContext(path));
  return rig;
}

}  // namespace

struct BagSource::Impl {
  std::unique_ptr<rosbag::Bag> bag;
  BagSummary summary;
  BagTopicChoice choice;
  TopicMessages primary;                          // Colour, left, mono images or clouds.
  TopicMessages secondary;                        // Depth or right images.
  std::vector<std::pair<size_t, size_t>> frames;  // Message indices of each frame.
  Trajectory odometry;
  Trajectory arm_poses;
};

BagSource::BagSource(std::string path, RosBagOptions options)
    : path_(std::move(path)), options_(std::move(options)), impl_(std::make_unique<Impl>()) {}

BagSource::~BagSource() = default;

const BagSummary& BagSource::summary() const { return impl_->summary; }
const BagTopicChoice& BagSource::choice() const { return impl_->choice; }
const Trajectory* BagSource::odometry() const {
  return impl_->odometry.empty() ? nullptr : &impl_->odometry;
}

const Trajectory* BagSource::arm_poses() const {
  return impl_->arm_poses.empty() ? nullptr : &impl_->arm_poses;
}

void BagSource::Close() {
  RecordedSource::Close();
  impl_ = std::make_unique<Impl>();
}

std::string BagSource::FrameFile(int64_t index) const {
  if (index < 0 || index >= static_cast<int64_t>(impl_->frames.size())) {
    return path_ + " frame " + std::to_string(index);
  }
  return path_ + ": " + impl_->primary.topic + " message " +
         std::to_string(impl_->frames[static_cast<size_t>(index)].first);
}

StatusOr<Frame> BagSource::Load(int64_t index) {
  if (!impl_->bag || index < 0 || index >= static_cast<int64_t>(impl_->frames.size())) {
    return OutOfRange(path_ + ": no frame " + std::to_string(index));
  }
  try {
    return LoadFrame(index);
  } catch (const std::exception& e) {
    return ParseError(FrameFile(index) + ": rosbag cannot read it: " + e.what());
  } catch (...) {
    return ParseError(FrameFile(index) + ": rosbag cannot read it (unknown error)");
  }
}

}  // namespace sightline

namespace sightline {

Status BagSource::Open() {
  Close();
  try {
    Status opened = OpenBag();
    if (!opened.ok()) impl_ = std::make_unique<Impl>();
    return opened;
  } catch (const std::exception& e) {
    impl_ = std::make_unique<Impl>();
    return ParseError(path_ + ": rosbag cannot read it: " + e.what());
  } catch (...) {
    impl_ = std::make_unique<Impl>();
    return ParseError(path_ + ": rosbag cannot read it (unknown error)");
  }
}

Status BagSource::OpenBag() {
  BagFileLayout layout;
  StatusOr<std::unique_ptr<rosbag::Bag>> bag = OpenBagForReading(path_, &layout);
  if (!bag.ok()) return bag.status();
  impl_->bag = std::move(*bag);
  StatusOr<BagSummary> summary = SummarizeBag(*impl_->bag, path_, layout);
  if (!summary.ok()) return summary.status();
  impl_->summary = std::move(*summary);
  StatusOr<BagTopicChoice> choice = ChooseBagTopics(impl_->summary, options_);
  if (!choice.ok()) return choice.status();
  impl_->choice = std::move(*choice);

  SourceInfo info;
  info.format = "ROS bag";
  info.path = path_;
  info.kind = impl_->choice.kind;
  info.notes.push_back(impl_->choice.Describe());
  for (const std::string& note : impl_->choice.notes) info.notes.push_back(note);
  PairFrames(&info);
  if (impl_->frames.empty()) {
    return NotFound(path_ + ": " + impl_->choice.Describe() + " gives no frame");
  }
  SIGHTLINE_RETURN_IF_ERROR(ReadCalibration(&info));
  std::optional<Trajectory> ground_truth;
  SIGHTLINE_RETURN_IF_ERROR(ReadPoses(&info, &ground_truth));
  info.notes.push_back("bag compression: " + impl_->summary.layout.CompressionText());

  std::vector<double> times;
  for (const auto& [first, second] : impl_->frames) times.push_back(impl_->primary.stamps[first]);
  return Commit(std::move(info), std::move(times), std::move(ground_truth));
}

void BagSource::PairFrames(SourceInfo* info) {
  const BagTopicChoice& c = impl_->choice;
  const rosbag::Bag& bag = *impl_->bag;
  impl_->primary = CollectTopic(bag, c.kind == SourceKind::kCloud ? c.cloud : c.image);
  if (c.kind == SourceKind::kMono || c.kind == SourceKind::kCloud) {
    for (size_t i : StampOrder(impl_->primary)) impl_->frames.push_back({i, 0});
    return;
  }
  impl_->secondary = CollectTopic(bag, c.kind == SourceKind::kRgbd ? c.depth : c.right_image);
  const double tolerance_s = options_.pair_tolerance_ms / 1000.0;
  for (const TumAssociation& pair :
       AssociateByTime(AsTimed(impl_->primary), AsTimed(impl_->secondary), tolerance_s)) {
    impl_->frames.push_back({size_t(pair.rgb.line), size_t(pair.depth.line)});
  }
  const char* what = c.kind == SourceKind::kRgbd ? "colour/depth" : "left/right";
  std::string note = std::string(what) + " paired by nearest stamp (at most " +
                     std::to_string(int(options_.pair_tolerance_ms + 0.5)) + " ms apart)";
  const size_t total = impl_->primary.messages.size();
  if (impl_->frames.size() < total) {
    note += "; " + std::to_string(total - impl_->frames.size()) + " of " + std::to_string(total) +
            " images have no partner and are skipped";
  }
  info->notes.push_back(note);
}

Status BagSource::ReadCalibration(SourceInfo* info) {
  const BagTopicChoice& c = impl_->choice;
  if (c.kind == SourceKind::kStereo) {
    StatusOr<StereoRig> rig = StereoOf(*impl_->bag, path_, c);
    if (!rig.ok()) return rig.status();
    info->stereo = *rig;
    info->camera = rig->left;
    info->notes.push_back("cameras from " + c.camera_info + " and " + c.right_camera_info);
  } else if (c.kind != SourceKind::kCloud) {
    StatusOr<PinholeCamera> camera = CameraOf(*impl_->bag, path_, c.camera_info);
    if (!camera.ok()) return camera.status();
    info->camera = *camera;
    info->notes.push_back("camera from " + c.camera_info);
  }
  // The first frame gives the size and proves the images decode.
  StatusOr<Frame> first = LoadFrame(0);
  if (!first.ok()) return first.status();
  if (const auto* cloud = std::get_if<CloudFrame>(&*first)) {
    info->width = cloud->cloud->width;
    info->height = cloud->cloud->height;
    return Status::Ok();
  }
  const cv::Size size = std::visit(
      [](const auto& f) -> cv::Size {
        using T = std::decay_t<decltype(f)>;
        if constexpr (std::is_same_v<T, RgbdFrame>) return f.color.size();
        if constexpr (std::is_same_v<T, StereoFrame>) return f.left.size();
        if constexpr (std::is_same_v<T, MonoFrame>) return f.image.size();
        return cv::Size();
      },
      *first);
  info->width = size.width;
  info->height = size.height;
  PinholeCamera& camera = *info->camera;
  if (camera.width != size.width || camera.height != size.height) {
    return InvalidArgument(path_ + ": " + c.camera_info + " describes a " +
                           std::to_string(camera.width) + "x" + std::to_string(camera.height) +
                           " camera but " + c.image + " has " + std::to_string(size.width) + "x" +
                           std::to_string(size.height) + " images");
  }
  if (c.kind == SourceKind::kRgbd) {
    RgbdCalibration rgbd;
    rgbd.color = camera;
    rgbd.depth_scale = 1000;  // Depth arrives in metres; the scale applies to 16UC1 only.
    info->rgbd = rgbd;
  }
  return Status::Ok();
}

Status BagSource::ReadPoses(SourceInfo* info, std::optional<Trajectory>* ground_truth) {
  const BagTopicChoice& c = impl_->choice;
  if (!c.odometry.empty()) {
    StatusOr<Trajectory> odometry = ReadBagOdometry(*impl_->bag, path_, c.odometry);
    if (!odometry.ok()) return odometry.status();
    impl_->odometry = std::move(*odometry);
    info->notes.push_back("odometry: " + c.odometry + " (" +
                          std::to_string(impl_->odometry.size()) + " poses)");
  }
  SIGHTLINE_RETURN_IF_ERROR(ReadTfPoses(info));
  const std::string frame = FirstFrameId(*impl_->bag, impl_->primary.topic);
  StatusOr<std::optional<Trajectory>> tf =
      ReadBagTfGroundTruth(*impl_->bag, impl_->summary, options_, frame, &info->notes);
  if (!tf.ok()) return tf.status();
  *ground_truth = std::move(*tf);
  if (!*ground_truth && !c.odometry.empty() &&
      c.odometry.find("ground_truth") != std::string::npos && !impl_->odometry.empty()) {
    *ground_truth = impl_->odometry;
    info->notes.push_back("ground truth: " + c.odometry + " (its name says ground_truth)");
  }
  return Status::Ok();
}

Status BagSource::ReadTfPoses(SourceInfo* info) {
  TfBuffer tf(options_.tf_max_gap_s);
  SIGHTLINE_RETURN_IF_ERROR(ReadBagTfBuffer(*impl_->bag, impl_->summary, &tf));
  std::vector<double> stamps;
  for (const auto& [first, second] : impl_->frames) stamps.push_back(impl_->primary.stamps[first]);
  struct Wanted {
    const std::string& parent;
    const char* parent_key;
    const std::string& child;
    const char* child_key;
    Trajectory* out;
    const char* what;
  };
  std::vector<Wanted> wanted;
  // Odometry from tf when no Odometry topic gives it and tf knows the odometry's frame.
  if (impl_->choice.odometry.empty() && tf.HasFrame(options_.odom_frame)) {
    wanted.push_back({options_.odom_frame, "io.rosbag.odom_frame", options_.base_frame,
                      "io.rosbag.base_frame", &impl_->odometry, "odometry"});
  }
  if (tf.HasFrame(options_.end_effector_frame)) {
    wanted.push_back({options_.arm_base_frame, "io.rosbag.arm_base_frame",
                      options_.end_effector_frame, "io.rosbag.end_effector_frame",
                      &impl_->arm_poses, "arm poses"});
  }
  for (const Wanted& w : wanted) {
    std::string first_gap;
    StatusOr<Trajectory> poses = TfPosesAtStamps(tf, path_, w.parent, w.parent_key, w.child,
                                                 w.child_key, stamps, &first_gap);
    if (!poses.ok()) return poses.status();
    if (poses->empty()) return OutOfRange(path_ + ": " + w.what + " at no frame: " + first_gap);
    *w.out = std::move(*poses);
    std::string note = std::string(w.what) + ": tf " + TfFrameName(w.parent) + " -> " +
                       TfFrameName(w.child) + " at " + std::to_string(w.out->size()) + " of " +
                       std::to_string(stamps.size()) + " frames";
    if (!first_gap.empty()) note += " (first without: " + first_gap + ")";
    info->notes.push_back(note);
  }
  return Status::Ok();
}

StatusOr<Frame> BagSource::LoadFrame(int64_t index) {
  const auto [first, second] = impl_->frames[static_cast<size_t>(index)];
  const SourceKind kind = impl_->choice.kind;
  if (kind == SourceKind::kCloud) {
    const rosbag::MessageInstance& m = impl_->primary.messages[first];
    auto msg = InstantiateChecked<sensor_msgs::PointCloud2>(m);
    if (!msg) return ParseError(FrameFile(index) + " is not a sensor_msgs/PointCloud2");
    StatusOr<PointCloud> cloud = CloudFromRos(*msg);
    if (!cloud.ok()) return cloud.status().WithContext(FrameFile(index));
    CloudFrame frame;
    frame.stamp = MakeStamp(index);
    frame.cloud = std::make_shared<const PointCloud>(std::move(*cloud));
    return Frame(std::move(frame));
  }
  StatusOr<cv::Mat> image = DecodeImage(impl_->primary, first, RosImageRole::kColor, path_);
  if (!image.ok()) return image.status();
  if (kind == SourceKind::kMono) return Frame(MonoFrame{MakeStamp(index), std::move(*image)});
  const RosImageRole role = kind == SourceKind::kRgbd ? RosImageRole::kDepth : RosImageRole::kColor;
  StatusOr<cv::Mat> other = DecodeImage(impl_->secondary, second, role, path_);
  if (!other.ok()) return other.status();
  return FrameFromRosImages(
      kind, MakeStamp(index), std::move(*image), std::move(*other),
      impl_->primary.topic + " message " + std::to_string(first),
      path_ + ": " + impl_->secondary.topic + " message " + std::to_string(second));
}

StatusOr<BagSummary> ReadBagSummary(const std::string& path) {
  try {
    BagFileLayout layout;
    StatusOr<std::unique_ptr<rosbag::Bag>> bag = OpenBagForReading(path, &layout);
    if (!bag.ok()) return bag.status();
    return SummarizeBag(**bag, path, layout);
  } catch (const std::exception& e) {
    return ParseError(path + ": rosbag cannot read it: " + e.what());
  } catch (...) {
    return ParseError(path + ": rosbag cannot read it (unknown error)");
  }
}

}  // namespace sightline
