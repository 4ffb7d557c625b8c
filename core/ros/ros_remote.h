// Watching a sightline-node from another process (the GUI): connects to a given ROS master,
// subscribes to the node's topics and hands immutable, timestamped copies of what arrives to a
// callback; sends the operator's commands to the node's button topics. STOP is latched: kept
// and delivered to every node that subscribes to button_stop (also one that starts or comes
// back after a master restart) until SendStart lifts it. ROS-free header (pimpl):
// the GUI includes it without ROS's headers and links ROS only through sightline_ros_remote.
//
//   RosRemote remote([](std::shared_ptr<const RemoteUpdate> u) { /* any thread: queue it */ });
//   Status s = remote.Connect({"http://robot:11311", "/"});
//   ...
//   remote.SendStop("operator");
//   remote.Disconnect();
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline {

// Where the node runs.
struct RosRemoteOptions {
  // The master's XML-RPC URI, "http://HOST:PORT" (e.g. http://robot:11311).
  std::string master_uri;
  // The node's namespace ("/" or "" for the root, "/robot1"): its topics are NAMESPACE/map ...
  std::string ros_namespace = "/";
  // The operator's image from button_image/compressed (JPEG: a tablet on Wi-Fi) when true, the
  // raw button_image otherwise.
  bool compressed_image = true;

  // Empty when valid; otherwise a message naming the bad field and value.
  bool IsValid(std::string* error) const;
};

// The node's latched map (nav_msgs/OccupancyGrid): row 0 is the lowest y, cells 0..100 or -1.
struct RemoteMap {
  int width = 0, height = 0;
  double resolution_m = 0;                           // Cell edge, metres.
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  // World position of cell (0, 0).
  std::vector<int8_t> cells;                         // width * height, row-major.
  std::string frame_id;
};

// One odometry message (nav_msgs/Odometry): the child frame's pose in the parent frame.
struct RemotePose {
  Eigen::Isometry3d parent_from_child = Eigen::Isometry3d::Identity();
  std::string parent_frame, child_frame;
};

// A PointCloud2 (its x y z float fields) from one topic.
struct RemoteCloud {
  std::string topic;
  std::vector<Eigen::Vector3f> points;
  std::string frame_id;
};

// The wall lines of the `walls` MarkerArray: pairs of end points in `frame_id`.
struct RemoteWalls {
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> segments;
  std::string frame_id;
};

// The node's button target (geometry_msgs/PoseStamped).
struct RemoteTarget {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  std::string frame_id;
};

// The button pipeline's gate on the node's diagnostics (status "sightline/button/gate"): keys
// as core/ros/ros_publish.h's ButtonGateStatus writes them.
struct RemoteGate {
  std::string state;    // PickerStateKey: "idle", "confirm", "tracking", ..., "stopped".
  std::string reason;   // GateReasonKey: "send", "not_confirmed", "stale", ...
  std::string message;  // The gate's own words ("target sent" or why not), English.
  bool stopped = false, held = false, tracking_only = false, target_published = false;
  // On the frame that answered a tap: "found", "no_button", "no_picture", "too_old", "stopped"
  // (TapAnswerKey), and the stamp of the picture that tap was made on; "" and 0 otherwise.
  std::string tap;
  double tap_stamp_s = 0;
  // With "found": the outline of the button the node found (image pixels); empty when the node
  // sent none or its text was not an outline (then `bad_candidate` says why).
  std::vector<cv::Point> candidate;
  std::string bad_candidate;
  // The tracked button on this frame (centre and radius, image pixels), when the node tracks it.
  std::optional<cv::Point3d> ring;
};

// One thing that arrived, or a change of the connection. Immutable once handed out.
struct RemoteUpdate {
  enum class Kind {
    kConnection,
    kMap,
    kOdometry,
    kCloud,
    kWalls,
    kTarget,
    kButtonImage,  // `image`: the frame the operator taps on; stamp_s names it in a tap.
    kGate,         // `gate`.
    kStopState,    // `stopped`: the node's latched `stop` (true once it has taken STOP).
  };
  Kind kind = Kind::kConnection;
  double stamp_s = 0;    // The message's header stamp (sensor time), seconds.
  double receive_s = 0;  // Host time when it arrived (steady clock), seconds.
  // kConnection: whether the master answers now, and the URI.
  bool connected = false;
  std::string master_uri;
  RemoteMap map;
  RemotePose pose;
  RemoteCloud cloud;
  RemoteWalls walls;
  RemoteTarget target;
  cv::Mat image;  // kButtonImage: CV_8UC3 BGR or CV_8UC1, its own buffer.
  RemoteGate gate;
  bool stopped = false;
};

// The connection to one master at a time. Thread-safe; the callback runs on ROS's spinner or the
// watch thread, never while Connect/Disconnect hold their lock: it must not block (queue the
// update for the GUI thread). Only one RosRemote may be connected per process (roscpp has one
// master per process).
class RosRemote {
 public:
  using Callback = std::function<void(std::shared_ptr<const RemoteUpdate>)>;
  explicit RosRemote(Callback on_update);
  ~RosRemote();
  RosRemote(const RosRemote&) = delete;
  RosRemote& operator=(const RosRemote&) = delete;

  // Validates `options`, points roscpp at the master (ros::init once per process, then
  // ros::master::init) and starts the watch (every 1 s): subscribes while the master answers,
  // reports kConnection changes and subscribes anew when it comes back. Fails only on invalid
  // options; an absent master is reported as disconnected and waited for.
  Status Connect(const RosRemoteOptions& options);
  // Drops the subscriptions and stops the watch. Safe to call twice.
  void Disconnect();
  // Whether the master answered at the last check.
  bool connected() const;
  // The options of the current connection.
  RosRemoteOptions options() const;
  // Messages refused because their bytes do not hold what their type declares (never handed to
  // the callback), and the last one's topic and reason.
  int64_t refused_messages() const;
  std::string last_refused() const;

  // The operator's tap at pixel (x, y) of the image stamped `image_stamp_s` (button_tap).
  Status SendTap(double x, double y, double image_stamp_s);
  // The operator's Yes to the candidate (button_confirm).
  Status SendConfirm();
  // Forgets the candidate or target (button_cancel).
  Status SendCancel();
  // STOP with a reason (button_stop, latched). Never dropped: published at once on the open
  // publisher (its connections to the node outlive a master that went away) and kept, so that a
  // node that subscribes later (reconnecting, restarted) receives it, until SendStart. Ok when a
  // node subscribes now; kUnavailable (saying it is kept) otherwise, the STOP still pending.
  Status SendStop(const std::string& reason);
  // Lifts STOP (button_start) and forgets the latched STOP; kUnavailable, the STOP kept, when no
  // node subscribes to button_start (or no master answers).
  Status SendStart();
  // Whether a node (sightline-node's button pipeline) subscribes to button_tap now: false when
  // the node is gone even though the master answers.
  bool node_listening() const;
  // Whether a STOP is kept for nodes (since SendStop, until SendStart).
  bool stop_latched() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sightline
