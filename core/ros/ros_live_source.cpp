// The live ROS source: subscriptions on a private callback queue served by its own spinner
// thread; synced frames wait in a bounded queue for the pipeline's Grab.
#include "core/ros/ros_live_source.h"

#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <tf2_msgs/TFMessage.h>

#include <condition_variable>
#include <cstdio>
#include <deque>
#include <mutex>
#include <optional>

#include "core/common/timing.h"
#include "core/ros/bag_messages.h"
#include "core/ros/checked_subscribe.h"
#include "core/ros/ros_image.h"
#include "core/ros/tf_buffer.h"
#include "core/sensors/timestamp_pairer.h"

namespace sightline {

struct RosLiveSource::Impl {
  using ImagePtr = sensor_msgs::ImageConstPtr;
  struct Item {
    ImagePtr a, b;  // image / left, and depth / right (null for mono).
    double host_s = 0;
  };

  explicit Impl(RosLiveOptions o)
      : options(std::move(o)),
        pairer(options.exact ? 1e-9 : options.slop_s, 2 * static_cast<size_t>(options.queue)),
        tf(options.tf_gap_s) {}

  void OnTf(const tf2_msgs::TFMessageConstPtr& msg, bool is_static) {
    for (const geometry_msgs::TransformStamped& t : msg->transforms) {
      StatusOr<Eigen::Isometry3d> pose =
          IsometryFromRos(t.transform.translation, t.transform.rotation);
      if (pose.ok())
        tf.Add(t.header.frame_id, t.child_frame_id, RosSeconds(t.header.stamp), *pose, is_static);
    }
    std::lock_guard<std::mutex> lock(mutex);
    ready_cv.notify_all();
  }
  // Appends parent_from_child at `stamp_s` to `out` once tf names `trigger`, waiting up to
  // tf_wait for a transform that covers the stamp.
  void PoseAt(const std::string& trigger, const std::string& parent, const std::string& child,
              double stamp_s, Trajectory* out) {
    if (!tf.HasFrame(trigger)) return;
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(options.tf_wait_s));
    std::unique_lock<std::mutex> lock(mutex);
    while (true) {
      StatusOr<Eigen::Isometry3d> pose = tf.Lookup(parent, child, stamp_s);
      if (pose.ok()) {
        out->Add(stamp_s, *pose);
        return;
      }
      if (!ros::ok() || ready_cv.wait_until(lock, deadline) == std::cv_status::timeout) {
        if (tf.Lookup(parent, child, stamp_s).ok()) continue;
        ++stats.tf_missing;
        return;
      }
    }
  }

  void OnImage(int stream, const ImagePtr& msg) {
    std::lock_guard<std::mutex> lock(mutex);
    if (options.kind() == SourceKind::kMono) {
      Push({msg, nullptr, HostTimeS()});
    } else if (auto pair = pairer.Add(stream, RosSeconds(msg->header.stamp), msg)) {
      Push({pair->first, pair->second, HostTimeS()});
    }
    stats.unpaired = static_cast<int64_t>(pairer.unpaired());
    ready_cv.notify_all();
  }
  void Push(Item item) {
    ready.push_back(std::move(item));
    while (static_cast<int>(ready.size()) > options.queue) {
      ready.pop_front();
      ++stats.queue_overflows;
    }
  }
  void OnInfo(int stream, const sensor_msgs::CameraInfoConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex);
    (stream == 0 ? info_a : info_b) = msg;
    ready_cv.notify_all();
  }
  void Subscribe();
  Status FillInfo();

  RosLiveOptions options;
  SourceInfo info;
  ros::CallbackQueue queue;
  std::unique_ptr<ros::NodeHandle> nh;
  std::unique_ptr<ros::AsyncSpinner> spinner;
  std::vector<ros::Subscriber> subs;
  std::mutex mutex;
  std::condition_variable ready_cv;
  TimestampPairer<ImagePtr> pairer;
  std::deque<Item> ready;
  std::optional<Item> current;
  sensor_msgs::CameraInfoConstPtr info_a, info_b;
  RosLiveStats stats;
  TfBuffer tf;
  Trajectory odometry, arm_poses;  // Driving thread only.
  int64_t position = 0;
  bool reported = false;
};

void RosLiveSource::Impl::Subscribe() {
  const bool stereo = options.kind() == SourceKind::kStereo;
  const uint32_t depth = static_cast<uint32_t>(2 * options.queue);
  const std::string a = stereo ? options.left : options.image;
  const std::string b = stereo ? options.right : options.depth;
  auto refused = [this](const std::string& topic) {
    return [this, topic](const std::string& why) {
      std::lock_guard<std::mutex> lock(mutex);
      ++stats.refused;
      stats.last_refused = nh->resolveName(topic) + ": " + why;
    };
  };
  subs.push_back(SubscribeChecked<sensor_msgs::Image>(
      *nh, a, depth, [this](const ImagePtr& m) { OnImage(0, m); }, refused(a)));
  if (!b.empty()) {
    subs.push_back(SubscribeChecked<sensor_msgs::Image>(
        *nh, b, depth, [this](const ImagePtr& m) { OnImage(1, m); }, refused(b)));
  }
  const std::string info_a_topic = stereo ? options.left_info : options.info;
  subs.push_back(SubscribeChecked<sensor_msgs::CameraInfo>(
      *nh, info_a_topic, 1, [this](const sensor_msgs::CameraInfoConstPtr& m) { OnInfo(0, m); },
      refused(info_a_topic)));
  if (stereo) {
    subs.push_back(SubscribeChecked<sensor_msgs::CameraInfo>(
        *nh, options.right_info, 1,
        [this](const sensor_msgs::CameraInfoConstPtr& m) { OnInfo(1, m); },
        refused(options.right_info)));
  }
  subs.push_back(SubscribeChecked<tf2_msgs::TFMessage>(
      *nh, "/tf", 100, [this](const tf2_msgs::TFMessageConstPtr& m) { OnTf(m, false); },
      refused("/tf")));
  subs.push_back(SubscribeChecked<tf2_msgs::TFMessage>(
      *nh, "/tf_static", 100, [this](const tf2_msgs::TFMessageConstPtr& m) { OnTf(m, true); },
      refused("/tf_static")));
}

Status RosLiveSource::Impl::FillInfo() {
  const SourceKind kind = options.kind();
  info.kind = kind;
  info.live = true;
  info.frame_count = -1;
  info.format = "ROS topics";
  // Each frame's arm pose is looked up on tf at its stamp (Retrieve): a channel for pipelines
  // that take the arm's poses frame by frame.
  info.arm_pose_channel = "tf " + options.arm_base_frame + " -> " + options.end_effector_frame +
                          " (ros:// arm_base_frame, end_effector_frame)";
  StatusOr<PinholeCamera> a = CameraFromRosInfo(*info_a);
  if (!a.ok())
    return a.status().WithContext(kind == SourceKind::kStereo ? options.left_info : options.info);
  info.camera = *a;
  info.width = a->width;
  info.height = a->height;
  if (kind == SourceKind::kRgbd) {
    RgbdCalibration rgbd;
    rgbd.color = *a;
    rgbd.depth_scale = 1;  // Frames carry metres.
    info.rgbd = rgbd;
  }
  if (kind == SourceKind::kStereo) {
    StatusOr<PinholeCamera> b = CameraFromRosInfo(*info_b);
    if (!b.ok()) return b.status().WithContext(options.right_info);
    StereoRig rig;
    rig.left = *a;
    rig.right = *b;
    // Rectified pair: the right projection's P[3] = -fx * baseline.
    const double fx = info_b->P[0];
    if (!(fx > 0) || !(info_b->P[3] < 0)) {
      return InvalidArgument(options.right_info +
                             ": P[3] must hold -fx * baseline of a rectified pair, got " +
                             std::to_string(info_b->P[3]));
    }
    rig.right_from_left.translation() = Eigen::Vector3d(info_b->P[3] / fx, 0, 0);
    rig.rectified = true;
    info.stereo = rig;
    info.notes.push_back("left/right are taken as rectified images (image_rect topics)");
  }
  info.notes.push_back(std::string(options.exact ? "exact" : "approximate") +
                       " time sync; at most " + std::to_string(options.queue) +
                       " frames wait, older ones are dropped and counted");
  return Status::Ok();
}

RosLiveSource::RosLiveSource(RosLiveOptions options)
    : impl_(std::make_unique<Impl>(std::move(options))) {
  const RosLiveOptions& o = impl_->options;
  impl_->info.path = "ros://" + (o.kind() == SourceKind::kStereo
                                     ? o.left + "," + o.right
                                     : o.image + (o.depth.empty() ? "" : "," + o.depth));
}

RosLiveSource::~RosLiveSource() { Close(); }

Status RosLiveSource::Open() {
  if (!ros::isInitialized()) {
    return FailedPrecondition("ros:// sources need a running ROS node (use sightline-node)");
  }
  impl_->nh = std::make_unique<ros::NodeHandle>();
  impl_->nh->setCallbackQueue(&impl_->queue);
  impl_->Subscribe();
  impl_->spinner = std::make_unique<ros::AsyncSpinner>(1, &impl_->queue);
  impl_->spinner->start();
  const bool stereo = impl_->options.kind() == SourceKind::kStereo;
  // Live-device guard by the host clock: the camera info must come within `wait`.
  std::unique_lock<std::mutex> lock(impl_->mutex);
  const bool got =
      impl_->ready_cv.wait_for(lock, std::chrono::duration<double>(impl_->options.wait_s),
                               [&] { return impl_->info_a && (!stereo || impl_->info_b); });
  if (!got) {
    return Unavailable("no CameraInfo on " +
                       (stereo ? impl_->options.left_info + " and " + impl_->options.right_info
                               : impl_->options.info) +
                       " within " + std::to_string(impl_->options.wait_s) +
                       " s (is the camera running? set info=TOPIC)" +
                       (impl_->stats.refused > 0
                            ? "; " + std::to_string(impl_->stats.refused) +
                                  " messages refused, the last: " + impl_->stats.last_refused
                            : std::string()));
  }
  return impl_->FillInfo();
}

const SourceInfo& RosLiveSource::info() const { return impl_->info; }

Status RosLiveSource::Grab() {
  std::unique_lock<std::mutex> lock(impl_->mutex);
  while (impl_->ready.empty()) {
    // Ctrl-C, SIGTERM or rosnode kill: the run stops as cancelled (its files are written).
    if (!ros::ok()) return Cancelled("ROS shut down while waiting for frames on live topics");
    impl_->ready_cv.wait_for(lock, std::chrono::milliseconds(100));
  }
  impl_->current = std::move(impl_->ready.front());
  impl_->ready.pop_front();
  return Status::Ok();
}

StatusOr<Frame> RosLiveSource::Retrieve() {
  if (!impl_->current) return FailedPrecondition("Retrieve before a successful Grab");
  const Impl::Item item = *impl_->current;
  FrameStamp stamp;
  stamp.sequence_id = impl_->position++;
  stamp.sensor_time_s = RosSeconds(item.a->header.stamp);
  stamp.host_time_s = item.host_s;
  const SourceKind kind = impl_->options.kind();
  const RosLiveOptions& tf_frames = impl_->options;
  impl_->PoseAt(tf_frames.odom_frame, tf_frames.odom_frame, tf_frames.base_frame,
                stamp.sensor_time_s, &impl_->odometry);
  impl_->PoseAt(tf_frames.end_effector_frame, tf_frames.arm_base_frame,
                tf_frames.end_effector_frame, stamp.sensor_time_s, &impl_->arm_poses);
  StatusOr<cv::Mat> a = DecodeRosImage(*item.a, RosImageRole::kColor);
  StatusOr<cv::Mat> b =
      item.b ? DecodeRosImage(
                   *item.b, kind == SourceKind::kRgbd ? RosImageRole::kDepth : RosImageRole::kColor)
             : StatusOr<cv::Mat>(cv::Mat());
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    ++impl_->stats.frames;
    if (!a.ok() || !b.ok()) ++impl_->stats.decode_errors;
  }
  if (!a.ok()) return a.status();
  if (!b.ok()) return b.status();
  const RosLiveOptions& o = impl_->options;
  const bool rgbd = kind == SourceKind::kRgbd;
  return FrameFromRosImages(kind, stamp, std::move(*a), std::move(*b), rgbd ? o.image : o.left,
                            "ros:// " + (rgbd ? o.depth : o.right));
}

int64_t RosLiveSource::Position() const { return impl_->position; }

void RosLiveSource::Close() {
  if (impl_->spinner) impl_->spinner->stop();
  impl_->spinner.reset();
  impl_->subs.clear();
  impl_->nh.reset();
  if (impl_->stats.frames > 0 && !impl_->reported) {
    impl_->reported = true;
    const RosLiveStats s = Stats();
    std::fprintf(stderr,
                 "ros:// source: %lld frames, dropped %lld unpaired and %lld while the pipeline "
                 "lagged, %lld undecodable\n",
                 static_cast<long long>(s.frames), static_cast<long long>(s.unpaired),
                 static_cast<long long>(s.queue_overflows),
                 static_cast<long long>(s.decode_errors));
  }
}

const Trajectory* RosLiveSource::odometry() const {
  return impl_->odometry.empty() ? nullptr : &impl_->odometry;
}

const Trajectory* RosLiveSource::arm_poses() const {
  return impl_->arm_poses.empty() ? nullptr : &impl_->arm_poses;
}

RosLiveStats RosLiveSource::Stats() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->stats;
}

StatusOr<std::unique_ptr<Source>> OpenRosLiveSource(const std::string& uri) {
  StatusOr<RosLiveOptions> options = ParseRosLiveUri(uri);
  if (!options.ok()) return options.status();
  auto source = std::make_unique<RosLiveSource>(*options);
  SIGHTLINE_RETURN_IF_ERROR(source->Open());
  return std::unique_ptr<Source>(std::move(source));
}

}  // namespace sightline
