#include "app/node/node_button.h"

#include <geometry_msgs/PointStamped.h>
#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/Image.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Empty.h>
#include <std_msgs/String.h>

#include <cmath>
#include <cstdio>
#include <deque>
#include <mutex>

namespace sightline::node {

class SeenStamps {
 public:
  void Add(double stamp_s, int64_t frame) {
    std::lock_guard<std::mutex> lock(mutex_);
    seen_.emplace_back(stamp_s, frame);
    while (seen_.size() > 256) seen_.pop_front();
  }
  // The frame shown at `stamp_s` (to a microsecond), or -1.
  int64_t Find(double stamp_s) const {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& [stamp, frame] : seen_) {
      if (std::abs(stamp - stamp_s) < 1e-6) return frame;
    }
    return -1;
  }

 private:
  mutable std::mutex mutex_;
  std::deque<std::pair<double, int64_t>> seen_;
};

namespace {

class ButtonPublisher : public ResultPublisher {
 public:
  ButtonPublisher(const StatisticTable& table, ros::NodeHandle& nh, const RosFrames& frames,
                  std::shared_ptr<ButtonCommands> commands)
      : slam_(MakeSlamPublisher("button", table, nh, frames)),
        commands_(std::move(commands)),
        camera_frame_(frames.camera) {
    target_ = nh.advertise<geometry_msgs::PoseStamped>("button_target", 10);
    stop_ = nh.advertise<std_msgs::Bool>("stop", 1, /*latch=*/true);
    gate_ = nh.advertise<diagnostic_msgs::DiagnosticArray>("diagnostics", 10);
    // The image the operator taps on, stamped with its frame's time (a tap carries that stamp).
    image_ = nh.advertise<sensor_msgs::Image>("button_image", 2);
    jpeg_ = nh.advertise<sensor_msgs::CompressedImage>("button_image/compressed", 2);
    subs_.push_back(nh.subscribe("button_tap", 10, &ButtonPublisher::OnTap, this));
    subs_.push_back(nh.subscribe("button_confirm", 10, &ButtonPublisher::OnConfirm, this));
    subs_.push_back(nh.subscribe("button_cancel", 10, &ButtonPublisher::OnCancel, this));
    subs_.push_back(nh.subscribe("button_stop", 10, &ButtonPublisher::OnStop, this));
    subs_.push_back(nh.subscribe("button_start", 10, &ButtonPublisher::OnStart, this));
  }

  void Publish(const PipelineResult& base) override {
    slam_->Publish(base);
    const auto* result = dynamic_cast<const ButtonFrameResult*>(&base);
    if (result == nullptr) return;
    seen_.Add(result->stamp.sensor_time_s, result->stamp.sequence_id);
    PublishImage(*result);
    diagnostic_msgs::DiagnosticArray gate;
    gate.header.stamp = RosTimeFromSeconds(result->stamp.sensor_time_s);
    gate.status.push_back(ButtonGateStatus(*result));
    gate_.publish(gate);
    PublishStopped(result->stopped, /*from_frame=*/true);
    // Only what the gate let out (confirmed, not stopped, fresh, certain, inside the workspace).
    if (result->picker.target) target_.publish(ButtonTargetMessage(*result->picker.target));
    if (result->tap_answered) {
      std::fprintf(stderr, "sightline-node: tap on frame %lld: %s\n",
                   static_cast<long long>(result->picker.frame_id),
                   result->tap_status.ok() ? "button found; confirm on button_confirm"
                                           : result->tap_status.ToString().c_str());
    }
  }

 private:
  // Encoded only for subscribers (a remote operator panel); the stamp is the frame's.
  void PublishImage(const ButtonFrameResult& result) {
    if (!result.slam || result.slam->image.empty()) return;
    const double t = result.stamp.sensor_time_s;
    if (image_.getNumSubscribers() > 0) {
      if (auto msg = EncodeRosImage(result.slam->image, t, camera_frame_); msg.ok()) {
        image_.publish(*msg);
      }
    }
    if (jpeg_.getNumSubscribers() > 0) {
      if (auto msg = EncodeRosJpeg(result.slam->image, t, camera_frame_, 85); msg.ok()) {
        jpeg_.publish(*msg);
      }
    }
  }
  void OnTap(const geometry_msgs::PointStamped::ConstPtr& msg) {
    ButtonTapRequest tap;
    tap.x = msg->point.x;
    tap.y = msg->point.y;
    tap.stamp_s = RosSecondsOf(msg->header.stamp);
    tap.frame = seen_.Find(tap.stamp_s);  // -1: no such image; the pipeline refuses the tap.
    commands_->Tap(tap);
  }
  void OnConfirm(const std_msgs::Empty::ConstPtr&) { commands_->Confirm(); }
  void OnCancel(const std_msgs::Empty::ConstPtr&) { commands_->Cancel(); }
  void OnStop(const std_msgs::String::ConstPtr& msg) {
    commands_->Stop(msg->data.empty() ? "operator" : msg->data);
    std::fprintf(stderr, "sightline-node: STOP on button_stop (%s)\n",
                 msg->data.empty() ? "operator" : msg->data.c_str());
    // Acknowledged at once on `stop`, not at the next frame (there may be none: a stalled
    // camera, a recording that ended).
    PublishStopped(true, /*from_frame=*/false);
  }
  void OnStart(const std_msgs::Empty::ConstPtr&) {
    commands_->Restart();
    std::lock_guard<std::mutex> lock(stop_mutex_);
    stop_taken_ = false;
  }
  // The latched `stop` when it changes. A STOP taken on the topic stands until a frame reports
  // it (a frame already in the pipeline when STOP came must not say "not stopped") or START.
  void PublishStopped(bool stopped, bool from_frame) {
    std::lock_guard<std::mutex> lock(stop_mutex_);
    if (!from_frame) stop_taken_ = true;
    if (from_frame && stopped) stop_taken_ = false;
    const bool now = stopped || stop_taken_;
    if (stop_sent_ && now == last_stopped_) return;
    std_msgs::Bool msg;
    msg.data = now;
    stop_.publish(msg);
    stop_sent_ = true;
    last_stopped_ = now;
  }
  static double RosSecondsOf(const ros::Time& t) { return t.sec + 1e-9 * t.nsec; }

  std::unique_ptr<ResultPublisher> slam_;
  std::shared_ptr<ButtonCommands> commands_;
  SeenStamps seen_;
  ros::Publisher target_, stop_, gate_, image_, jpeg_;
  std::string camera_frame_;
  std::vector<ros::Subscriber> subs_;
  std::mutex stop_mutex_;  // The loop and the topic callbacks publish `stop`.
  bool stop_sent_ = false, last_stopped_ = false, stop_taken_ = false;
};

}  // namespace

std::unique_ptr<ResultPublisher> MakeButtonPublisher(const StatisticTable& table,
                                                     ros::NodeHandle& nh, const RosFrames& frames,
                                                     std::shared_ptr<ButtonCommands> commands) {
  return std::make_unique<ButtonPublisher>(table, nh, frames, std::move(commands));
}

}  // namespace sightline::node
