// RosRemote: one process-wide roscpp (initialised once, pointed at a master with
// ros::master::init), per connection a NodeHandle with its own callback queue and spinner, and a
// watch thread that checks the master every second and subscribes anew when it comes back. STOP
// goes out on a latched publisher and is kept here, so every (re)advertised publisher carries it.
#include "core/ros/ros_remote.h"

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/callback_queue.h>
#include <ros/init.h>
#include <ros/master.h>
#include <ros/names.h>
#include <ros/node_handle.h>
#include <ros/spinner.h>
#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Empty.h>
#include <std_msgs/String.h>
#include <visualization_msgs/MarkerArray.h>

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <thread>

#include "core/common/timing.h"
#include "core/ros/checked_subscribe.h"
#include "core/ros/ros_image.h"

// roscpp 1.15 exports ros::master::init (libroscpp.so; init.cpp calls it with the remappings)
// without declaring it in a public header. It re-reads `__master` (else ROS_MASTER_URI).
namespace ros::master {
void init(const M_string& remappings);
}  // namespace ros::master

namespace sightline {

namespace {

double SecondsOf(const ros::Time& t) { return t.sec + 1e-9 * t.nsec; }

// An outline written as "x,y x,y ..." (core/ros/ros_publish.h's OutlineText): 3 to 4096
// points, each within +-1e6 pixels.
StatusOr<std::vector<cv::Point>> ParseOutline(const std::string& text) {
  constexpr size_t kMaxPoints = 4096;
  std::vector<cv::Point> points;
  const char* s = text.c_str();
  while (*s != '\0') {
    if (*s == ' ') {
      ++s;
      continue;
    }
    if (points.size() >= kMaxPoints) {
      return InvalidArgument("gate key 'candidate': more than " + std::to_string(kMaxPoints) +
                             " points");
    }
    char* end = nullptr;
    const long x = std::strtol(s, &end, 10);
    if (end == s || *end != ',') {
      return InvalidArgument("gate key 'candidate': point " + std::to_string(points.size() + 1) +
                             " is not 'x,y'");
    }
    s = end + 1;
    const long y = std::strtol(s, &end, 10);
    if (end == s || (*end != ' ' && *end != '\0') || std::labs(x) > 1000000 ||
        std::labs(y) > 1000000) {
      return InvalidArgument("gate key 'candidate': point " + std::to_string(points.size() + 1) +
                             " is not 'x,y' within +-1e6 pixels");
    }
    points.emplace_back(int(x), int(y));
    s = end;
  }
  if (points.size() < 3) {
    return InvalidArgument("gate key 'candidate': " + std::to_string(points.size()) +
                           " points, an outline needs 3");
  }
  return points;
}

// A ring written as "x,y,r" (finite, r > 0); nullopt for anything else.
std::optional<cv::Point3d> ParseRing(const std::string& text) {
  double v[3];
  const char* s = text.c_str();
  for (int i = 0; i < 3; ++i) {
    char* end = nullptr;
    v[i] = std::strtod(s, &end);
    if (end == s || !std::isfinite(v[i]) || *end != (i < 2 ? ',' : '\0')) return std::nullopt;
    s = end + 1;
  }
  if (!(v[2] > 0)) return std::nullopt;
  return cv::Point3d(v[0], v[1], v[2]);
}

// A stamp written as decimal seconds; 0 for text that is not one whole finite number.
double ParseStamp(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  return (end != text.c_str() && *end == '\0' && std::isfinite(v)) ? v : 0;
}

Eigen::Isometry3d PoseOf(const geometry_msgs::Pose& p) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  Eigen::Quaterniond q(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z);
  if (q.norm() > 1e-9) pose.linear() = q.normalized().toRotationMatrix();
  return pose;
}

std::shared_ptr<RemoteUpdate> NewUpdate(RemoteUpdate::Kind kind, const ros::Time& stamp) {
  auto update = std::make_shared<RemoteUpdate>();
  update->kind = kind;
  update->stamp_s = SecondsOf(stamp);
  update->receive_s = HostTimeS();
  return update;
}

// The float32 x y z of a PointCloud2 (either byte order as the message says; NaNs dropped).
std::vector<Eigen::Vector3f> CloudPoints(const sensor_msgs::PointCloud2& msg) {
  int offset[3] = {-1, -1, -1};
  for (const auto& field : msg.fields) {
    const int axis = field.name == "x" ? 0 : field.name == "y" ? 1 : field.name == "z" ? 2 : -1;
    if (axis >= 0 && field.datatype == sensor_msgs::PointField::FLOAT32) {
      offset[axis] = static_cast<int>(field.offset);
    }
  }
  std::vector<Eigen::Vector3f> points;
  if (offset[0] < 0 || offset[1] < 0 || offset[2] < 0 || msg.is_bigendian) return points;
  const size_t count = static_cast<size_t>(msg.width) * msg.height;
  if (msg.point_step < 12 || msg.data.size() < count * msg.point_step) return points;
  points.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    const uint8_t* p = msg.data.data() + i * msg.point_step;
    float v[3];
    for (int a = 0; a < 3; ++a) std::memcpy(&v[a], p + offset[a], sizeof(float));
    if (std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2])) {
      points.emplace_back(v[0], v[1], v[2]);
    }
  }
  return points;
}

// ros::init once per process: no SIGINT handler (the GUI owns its signals), an anonymous name (a
// desktop may watch with two GUIs), no rosout (its publisher would wait for a master).
void InitRosOnce(const std::string& master_uri) {
  static std::once_flag once;
  std::call_once(once, [&] {
    if (ros::isInitialized()) return;
    ros::M_string remappings{{"__master", master_uri}};
    ros::init(remappings, "sightline_gui",
              ros::init_options::NoSigintHandler | ros::init_options::AnonymousName |
                  ros::init_options::NoRosout);
  });
  // Registering waits for the master; a master that goes away during it gives up after this.
  ros::master::setRetryTimeout(ros::WallDuration(3.0));
  ros::master::init(ros::M_string{{"__master", master_uri}});
}

}  // namespace

bool RosRemoteOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  const std::string prefix = "http://";
  if (master_uri.rfind(prefix, 0) != 0) {
    return fail("master URI '" + master_uri +
                "' must start with http:// (e.g. http://robot:11311)");
  }
  std::string rest = master_uri.substr(prefix.size());
  if (!rest.empty() && rest.back() == '/') rest.pop_back();
  const size_t colon = rest.rfind(':');
  if (colon == std::string::npos || colon == 0) {
    return fail("master URI '" + master_uri + "' needs a host and a port (http://HOST:PORT)");
  }
  const std::string host = rest.substr(0, colon), port = rest.substr(colon + 1);
  for (char c : host) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_')) {
      return fail("master URI '" + master_uri + "' has an invalid host '" + host + "'");
    }
  }
  const bool digits = !port.empty() && port.size() <= 5 &&
                      port.find_first_not_of("0123456789") == std::string::npos;
  if (!digits || std::stoi(port) < 1 || std::stoi(port) > 65535) {
    return fail("master URI '" + master_uri + "' has an invalid port '" + port + "' (1..65535)");
  }
  std::string why;
  if (!ros_namespace.empty() && !ros::names::validate(ros_namespace, why)) {
    return fail("ROS namespace '" + ros_namespace + "' is invalid: " + why);
  }
  return true;
}

struct RosRemote::Impl {
  explicit Impl(Callback cb) : on_update(std::move(cb)) {}

  Callback on_update;
  mutable std::mutex refused_mutex;  // Guards `refused` and `last_refused` (spinner thread).
  int64_t refused = 0;
  std::string last_refused;
  mutable std::mutex mutex;  // Guards everything below but `connected`.
  std::condition_variable wake;
  RosRemoteOptions options;
  bool running = false;
  std::thread watch;
  std::atomic<bool> connected{false};
  ros::CallbackQueue queue;
  std::unique_ptr<ros::NodeHandle> nh;
  std::unique_ptr<ros::AsyncSpinner> spinner;
  std::vector<ros::Subscriber> subs;
  ros::Publisher tap, confirm, cancel, stop, start;
  // The STOP kept for nodes (latched on `stop`, published anew on every advertise) until
  // SendStart; empty reason with `stop_latched` false: none.
  bool stop_latched = false;
  std::string stop_reason;

  void Emit(std::shared_ptr<RemoteUpdate> update) {
    if (on_update) on_update(std::move(update));
  }

  void OnMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    auto u = NewUpdate(RemoteUpdate::Kind::kMap, msg->header.stamp);
    u->map.width = static_cast<int>(msg->info.width);
    u->map.height = static_cast<int>(msg->info.height);
    u->map.resolution_m = msg->info.resolution;
    u->map.origin = Eigen::Vector2d(msg->info.origin.position.x, msg->info.origin.position.y);
    u->map.cells = msg->data;
    u->map.frame_id = msg->header.frame_id;
    if (u->map.cells.size() != static_cast<size_t>(u->map.width) * u->map.height) return;
    Emit(std::move(u));
  }
  void OnOdometry(const nav_msgs::Odometry::ConstPtr& msg) {
    auto u = NewUpdate(RemoteUpdate::Kind::kOdometry, msg->header.stamp);
    u->pose.parent_from_child = PoseOf(msg->pose.pose);
    u->pose.parent_frame = msg->header.frame_id;
    u->pose.child_frame = msg->child_frame_id;
    Emit(std::move(u));
  }
  void OnCloud(const std::string& topic, const sensor_msgs::PointCloud2::ConstPtr& msg) {
    auto u = NewUpdate(RemoteUpdate::Kind::kCloud, msg->header.stamp);
    u->cloud.topic = topic;
    u->cloud.points = CloudPoints(*msg);
    u->cloud.frame_id = msg->header.frame_id;
    Emit(std::move(u));
  }
  void OnWalls(const visualization_msgs::MarkerArray::ConstPtr& msg) {
    for (const auto& marker : msg->markers) {
      if (marker.action != visualization_msgs::Marker::ADD ||
          marker.type != visualization_msgs::Marker::LINE_LIST) {
        continue;
      }
      auto u = NewUpdate(RemoteUpdate::Kind::kWalls, marker.header.stamp);
      u->walls.frame_id = marker.header.frame_id;
      const Eigen::Isometry3d frame_from_marker = PoseOf(marker.pose);
      for (size_t i = 0; i + 1 < marker.points.size(); i += 2) {
        const auto& a = marker.points[i];
        const auto& b = marker.points[i + 1];
        u->walls.segments.emplace_back(frame_from_marker * Eigen::Vector3d(a.x, a.y, a.z),
                                       frame_from_marker * Eigen::Vector3d(b.x, b.y, b.z));
      }
      Emit(std::move(u));
    }
  }
  void OnTarget(const geometry_msgs::PoseStamped::ConstPtr& msg) {
    auto u = NewUpdate(RemoteUpdate::Kind::kTarget, msg->header.stamp);
    u->target.pose = PoseOf(msg->pose);
    u->target.frame_id = msg->header.frame_id;
    Emit(std::move(u));
  }

  void OnImage(const cv::Mat& image, const ros::Time& stamp) {
    if (image.empty()) return;
    auto u = NewUpdate(RemoteUpdate::Kind::kButtonImage, stamp);
    u->image = image;
    Emit(std::move(u));
  }
  void OnDiagnostics(const diagnostic_msgs::DiagnosticArray::ConstPtr& msg) {
    for (const auto& status : msg->status) {
      if (status.name != "sightline/button/gate") continue;
      auto u = NewUpdate(RemoteUpdate::Kind::kGate, msg->header.stamp);
      u->gate.message = status.message;
      for (const auto& kv : status.values) {
        const bool yes = kv.value == "true";
        if (kv.key == "state") u->gate.state = kv.value;
        if (kv.key == "reason") u->gate.reason = kv.value;
        if (kv.key == "stopped") u->gate.stopped = yes;
        if (kv.key == "held") u->gate.held = yes;
        if (kv.key == "tracking_only") u->gate.tracking_only = yes;
        if (kv.key == "target_published") u->gate.target_published = yes;
        if (kv.key == "tap") u->gate.tap = kv.value;
        if (kv.key == "tap_stamp") u->gate.tap_stamp_s = ParseStamp(kv.value);
        if (kv.key == "ring") u->gate.ring = ParseRing(kv.value);
        if (kv.key == "candidate") {
          StatusOr<std::vector<cv::Point>> outline = ParseOutline(kv.value);
          if (outline.ok()) {
            u->gate.candidate = std::move(*outline);
          } else {
            u->gate.bad_candidate = outline.status().message();
          }
        }
      }
      Emit(std::move(u));
    }
  }
  void OnStopState(const std_msgs::Bool::ConstPtr& msg) {
    auto u = NewUpdate(RemoteUpdate::Kind::kStopState, ros::Time());
    u->stopped = msg->data;
    Emit(std::move(u));
  }

  // The latched STOP publisher (mutex held); a kept STOP goes out on it at once, so that the
  // node, subscribing now or later, receives it.
  void AdvertiseStop() {
    stop = nh->advertise<std_msgs::String>("button_stop", 10, /*latch=*/true);
    if (stop_latched) PublishStop();
  }
  void PublishStop() {
    std_msgs::String msg;
    msg.data = stop_reason;
    stop.publish(msg);
  }

  // (Re)subscribes and advertises on the master that answers now (mutex held). roscpp registers
  // with the master blocking until it answers: only called right after a successful check.
  void Subscribe() {
    Unsubscribe();
    nh = std::make_unique<ros::NodeHandle>(options.ros_namespace.empty() ? "/"
                                                                         : options.ros_namespace);
    nh->setCallbackQueue(&queue);
    // Every topic through the message check: a node (or anyone on the network) that sends a map
    // claiming billions of cells is refused and counted, not decoded.
    const auto refused_on = [this](const std::string& topic) {
      return [this, topic = nh->resolveName(topic)](const std::string& why) {
        std::lock_guard<std::mutex> lock(refused_mutex);
        ++refused;
        last_refused = topic + ": " + why;
      };
    };
    subs.push_back(SubscribeChecked<nav_msgs::OccupancyGrid>(
        *nh, "map", 2, [this](const nav_msgs::OccupancyGrid::ConstPtr& m) { OnMap(m); },
        refused_on("map")));
    subs.push_back(SubscribeChecked<nav_msgs::Odometry>(
        *nh, "odom", 50, [this](const nav_msgs::Odometry::ConstPtr& m) { OnOdometry(m); },
        refused_on("odom")));
    for (const std::string topic : {"map_points", "mobility_cloud"}) {
      const std::string resolved = nh->resolveName(topic);
      subs.push_back(SubscribeChecked<sensor_msgs::PointCloud2>(
          *nh, topic, 2,
          [this, resolved](const sensor_msgs::PointCloud2::ConstPtr& msg) {
            OnCloud(resolved, msg);
          },
          refused_on(topic)));
    }
    subs.push_back(SubscribeChecked<visualization_msgs::MarkerArray>(
        *nh, "walls", 10,
        [this](const visualization_msgs::MarkerArray::ConstPtr& m) { OnWalls(m); },
        refused_on("walls")));
    subs.push_back(SubscribeChecked<geometry_msgs::PoseStamped>(
        *nh, "button_target", 10,
        [this](const geometry_msgs::PoseStamped::ConstPtr& m) { OnTarget(m); },
        refused_on("button_target")));
    // The operator's picture: latest wins (queue 1), decoded on the spinner thread.
    if (options.compressed_image) {
      subs.push_back(SubscribeChecked<sensor_msgs::CompressedImage>(
          *nh, "button_image/compressed", 1,
          [this](const sensor_msgs::CompressedImage::ConstPtr& m) {
            if (auto image = DecodeRosCompressedImage(*m); image.ok()) {
              OnImage(*image, m->header.stamp);
            }
          },
          refused_on("button_image/compressed")));
    } else {
      subs.push_back(SubscribeChecked<sensor_msgs::Image>(
          *nh, "button_image", 1,
          [this](const sensor_msgs::Image::ConstPtr& m) {
            if (auto image = DecodeRosImage(*m, RosImageRole::kColor); image.ok()) {
              OnImage(*image, m->header.stamp);
            }
          },
          refused_on("button_image")));
    }
    subs.push_back(SubscribeChecked<diagnostic_msgs::DiagnosticArray>(
        *nh, "diagnostics", 20,
        [this](const diagnostic_msgs::DiagnosticArray::ConstPtr& m) { OnDiagnostics(m); },
        refused_on("diagnostics")));
    subs.push_back(SubscribeChecked<std_msgs::Bool>(
        *nh, "stop", 5, [this](const std_msgs::Bool::ConstPtr& m) { OnStopState(m); },
        refused_on("stop")));
    tap = nh->advertise<geometry_msgs::PointStamped>("button_tap", 10);
    confirm = nh->advertise<std_msgs::Empty>("button_confirm", 10);
    cancel = nh->advertise<std_msgs::Empty>("button_cancel", 10);
    start = nh->advertise<std_msgs::Empty>("button_start", 10);
    AdvertiseStop();
    if (!spinner) {
      spinner = std::make_unique<ros::AsyncSpinner>(1, &queue);
      spinner->start();
    }
  }
  void Unsubscribe() {
    subs.clear();
    tap = confirm = cancel = stop = start = ros::Publisher();
    nh.reset();
  }

  void Watch() {
    std::unique_lock<std::mutex> lock(mutex);
    while (running) {
      lock.unlock();
      const bool up = ros::master::check();
      lock.lock();
      if (!running) break;
      if (up != connected.load()) {
        if (up) Subscribe();
        connected.store(up);
        auto u = std::make_shared<RemoteUpdate>();
        u->kind = RemoteUpdate::Kind::kConnection;
        u->receive_s = HostTimeS();
        u->connected = up;
        u->master_uri = options.master_uri;
        lock.unlock();
        Emit(std::move(u));
        lock.lock();
      }
      wake.wait_for(lock, std::chrono::seconds(1), [this] { return !running; });
    }
  }

  Status Send(const ros::Publisher& pub, const char* topic,
              const std::function<void(const ros::Publisher&)>& publish) {
    std::lock_guard<std::mutex> lock(mutex);
    if (!connected.load() || !pub) {
      return Status(StatusCode::kUnavailable,
                    std::string("not connected to a ROS master: ") + topic + " not sent");
    }
    if (pub.getNumSubscribers() == 0) {
      return Status(StatusCode::kUnavailable, "no node subscribes to " + pub.getTopic() +
                                                  " (is sightline-node running "
                                                  "the button pipeline?)");
    }
    publish(pub);
    return Status::Ok();
  }
};

RosRemote::RosRemote(Callback on_update) : impl_(std::make_unique<Impl>(std::move(on_update))) {}

RosRemote::~RosRemote() { Disconnect(); }

Status RosRemote::Connect(const RosRemoteOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) return Status(StatusCode::kInvalidArgument, error);
  Disconnect();
  InitRosOnce(options.master_uri);
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->options = options;
  impl_->running = true;
  impl_->connected.store(false);
  impl_->watch = std::thread([this] { impl_->Watch(); });
  return Status::Ok();
}

void RosRemote::Disconnect() {
  std::thread watch;
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    if (!impl_->running) return;
    impl_->running = false;
    watch = std::move(impl_->watch);
  }
  impl_->wake.notify_all();
  if (watch.joinable()) watch.join();
  std::lock_guard<std::mutex> lock(impl_->mutex);
  if (impl_->spinner) impl_->spinner->stop();
  impl_->spinner.reset();
  impl_->Unsubscribe();
  impl_->queue.clear();
  impl_->connected.store(false);
}

bool RosRemote::connected() const { return impl_->connected.load(); }

int64_t RosRemote::refused_messages() const {
  std::lock_guard<std::mutex> lock(impl_->refused_mutex);
  return impl_->refused;
}

std::string RosRemote::last_refused() const {
  std::lock_guard<std::mutex> lock(impl_->refused_mutex);
  return impl_->last_refused;
}

RosRemoteOptions RosRemote::options() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->options;
}

Status RosRemote::SendTap(double x, double y, double image_stamp_s) {
  return impl_->Send(impl_->tap, "button_tap", [&](const ros::Publisher& pub) {
    geometry_msgs::PointStamped msg;
    msg.header.stamp = RosTimeFromSeconds(image_stamp_s);
    msg.point.x = x;
    msg.point.y = y;
    pub.publish(msg);
  });
}

Status RosRemote::SendConfirm() {
  return impl_->Send(impl_->confirm, "button_confirm",
                     [](const ros::Publisher& pub) { pub.publish(std_msgs::Empty()); });
}

Status RosRemote::SendCancel() {
  return impl_->Send(impl_->cancel, "button_cancel",
                     [](const ros::Publisher& pub) { pub.publish(std_msgs::Empty()); });
}

Status RosRemote::SendStop(const std::string& reason) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->stop_latched = true;
  impl_->stop_reason = reason;
  // Whatever the master says: a publisher that exists still reaches the nodes it is connected
  // to, and keeps the STOP for those that subscribe later.
  if (!impl_->stop) {
    return Status(StatusCode::kUnavailable,
                  "not connected to a ROS master: STOP kept, sent on button_stop when it answers");
  }
  impl_->PublishStop();
  if (impl_->stop.getNumSubscribers() == 0) {
    return Status(StatusCode::kUnavailable, "no node subscribes to " + impl_->stop.getTopic() +
                                                " yet: STOP kept (latched) for it");
  }
  return Status::Ok();
}

Status RosRemote::SendStart() {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  // STOP stays until a node really hears START: a START that reaches nobody lifts nothing.
  if (!impl_->connected.load() || !impl_->start) {
    return Status(StatusCode::kUnavailable,
                  "not connected to a ROS master: button_start not sent, STOP kept");
  }
  if (impl_->start.getNumSubscribers() == 0) {
    return Status(StatusCode::kUnavailable, "no node subscribes to " + impl_->start.getTopic() +
                                                ": button_start not sent, STOP kept");
  }
  impl_->start.publish(std_msgs::Empty());
  impl_->stop_latched = false;
  impl_->stop_reason.clear();
  // A fresh publisher holds no STOP for nodes that subscribe from now on.
  impl_->stop.shutdown();
  impl_->AdvertiseStop();
  return Status::Ok();
}

bool RosRemote::node_listening() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->tap && impl_->tap.getNumSubscribers() > 0;
}

bool RosRemote::stop_latched() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->stop_latched;
}

}  // namespace sightline
