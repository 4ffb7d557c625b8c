// The ROS node dock: RosRemote's updates, queued to the GUI thread, become the map image and the
// 3D view's ros_node/* layers.
#include "app/sightline/ros_node_view.h"

#include <QDockWidget>
#include <QLabel>
#include <QMetaObject>
#include <QPointer>
#include <mutex>
#include <opencv2/core.hpp>

#include "core/common/frame.h"
#include "widgets/image_view.h"
#include "widgets/scene_view.h"

#ifdef SIGHTLINE_HAVE_ROS
#include "core/ros/ros_remote.h"
#endif

namespace sightline {

namespace {

constexpr char kTrajectoryLayer[] = "ros_node/trajectory";
constexpr char kWallsLayer[] = "ros_node/walls";
constexpr char kTargetLayer[] = "ros_node/target";
constexpr char kCloudLayerPrefix[] = "ros_node/cloud";

}  // namespace

#ifdef SIGHTLINE_HAVE_ROS

// The map as a map_server image: 0 occupied, 254 free, 205 unknown, row 0 the largest y.
static cv::Mat MapImage(const RemoteMap& map) {
  cv::Mat gray(map.height, map.width, CV_8UC1);
  for (int row = 0; row < map.height; ++row) {
    const int8_t* cells = map.cells.data() + static_cast<size_t>(map.height - 1 - row) * map.width;
    uint8_t* out = gray.ptr<uint8_t>(row);
    for (int col = 0; col < map.width; ++col) {
      const int v = cells[col];
      out[col] = v < 0 ? 205 : static_cast<uint8_t>(254 - (254 * std::min(v, 100)) / 100);
    }
  }
  return gray;
}

// The newest picture not yet shown: a slow GUI skips pictures instead of queueing them.
struct LatestImage {
  std::mutex mutex;
  std::shared_ptr<const RemoteUpdate> update;
};

struct RosNodeView::Remote {
  std::unique_ptr<RosRemote> remote;
};

#else

struct RosNodeView::Remote {};

#endif

RosNodeView::RosNodeView(SceneView* scene, QWidget* parent)
    : QObject(parent), remote_(std::make_unique<Remote>()), scene_(scene) {
  dock_ = new QDockWidget(tr("ROS node"), parent);
  dock_->setObjectName("ros_node_dock");
  map_view_ = new ImageView(dock_);
  map_view_->setObjectName("ros_map_view");
  map_view_->SetMessage(tr("Not connected: File > Connect to ROS master..."));
  dock_->setWidget(map_view_);
  status_label_ = new QLabel(parent);
  status_label_->setObjectName("ros_status");
  status_label_->hide();
}

// The widgets may be gone already (the window deletes its children in any order): only the
// connection is closed here.
RosNodeView::~RosNodeView() {
#ifdef SIGHTLINE_HAVE_ROS
  if (remote_->remote != nullptr) remote_->remote->Disconnect();
#endif
}

bool RosNodeView::active() const {
#ifdef SIGHTLINE_HAVE_ROS
  return remote_->remote != nullptr;
#else
  return false;
#endif
}

Status RosNodeView::Connect(const QString& master_uri, const QString& ros_namespace) {
#ifdef SIGHTLINE_HAVE_ROS
  RosRemoteOptions options;
  options.master_uri = master_uri.trimmed().toStdString();
  options.ros_namespace =
      ros_namespace.trimmed().isEmpty() ? "/" : ros_namespace.trimmed().toStdString();
  std::string error;
  if (!options.IsValid(&error)) {
    status_label_->setText(tr("ROS: %1").arg(QString::fromStdString(error)));
    status_label_->show();
    return Status(StatusCode::kInvalidArgument, error);
  }
  Disconnect();
  QPointer<RosNodeView> self(this);
  auto latest = std::make_shared<LatestImage>();
  // Any thread: the update is handed to the GUI thread as a queued call.
  auto remote =
      std::make_unique<RosRemote>([self, latest](std::shared_ptr<const RemoteUpdate> update) {
        if (self.isNull()) return;
        if (update->kind == RemoteUpdate::Kind::kButtonImage) {
          std::lock_guard<std::mutex> lock(latest->mutex);
          // A call on its way to the GUI thread takes this one instead of the older one.
          const bool posted = latest->update != nullptr;
          latest->update = std::move(update);
          if (posted) return;
          QMetaObject::invokeMethod(
              self.data(),
              [self, latest] {
                std::shared_ptr<const RemoteUpdate> newest;
                {
                  std::lock_guard<std::mutex> lock(latest->mutex);
                  newest = std::move(latest->update);
                  latest->update = nullptr;
                }
                if (!self.isNull() && newest != nullptr) self->Apply(newest);
              },
              Qt::QueuedConnection);
          return;
        }
        QMetaObject::invokeMethod(
            self.data(),
            [self, update] {
              if (!self.isNull()) self->Apply(update);
            },
            Qt::QueuedConnection);
      });
  const Status connected = remote->Connect(options);
  if (!connected.ok()) return connected;
  if (stop_kept_) (void)remote->SendStop(stop_reason_);  // Kept for the node at the new master.
  remote_->remote = std::move(remote);
  uri_ = QString::fromStdString(options.master_uri);
  connected_ = false;
  maps_shown_ = 0;
  trajectory_ = Trajectory();
  map_view_->Clear();
  map_view_->SetMessage(tr("Waiting for the map from %1 ...").arg(uri_));
  ShowStatus();
  return Status::Ok();
#else
  const std::string message = "this build has no ROS (configured with SIGHTLINE_WITH_ROS=OFF)";
  status_label_->setText(tr("ROS: not available in this build"));
  status_label_->show();
  return Status(StatusCode::kUnavailable, message);
#endif
}

void RosNodeView::Disconnect() {
#ifdef SIGHTLINE_HAVE_ROS
  if (remote_->remote == nullptr) return;
  remote_->remote->Disconnect();
  remote_->remote.reset();
#endif
  const bool was_connected = connected_;
  connected_ = false;
  if (was_connected) emit ConnectionChanged(false, uri_);
  if (scene_ != nullptr) {
    scene_->RemoveLayer(kTrajectoryLayer);
    scene_->RemoveLayer(kWallsLayer);
    scene_->RemoveLayer(kTargetLayer);
    scene_->RemoveLayer(std::string(kCloudLayerPrefix) + "/map_points");
    scene_->RemoveLayer(std::string(kCloudLayerPrefix) + "/mobility_cloud");
  }
  map_view_->SetMessage(tr("Not connected: File > Connect to ROS master..."));
  status_label_->hide();
}

#ifdef SIGHTLINE_HAVE_ROS
namespace {
const Status kNotConnected(StatusCode::kUnavailable,
                           "not connected to a ROS master (File > Connect to ROS master...)");
}  // namespace

Status RosNodeView::SendTap(double x, double y, double image_stamp_s) {
  return remote_->remote ? remote_->remote->SendTap(x, y, image_stamp_s) : kNotConnected;
}
Status RosNodeView::SendConfirm() {
  return remote_->remote ? remote_->remote->SendConfirm() : kNotConnected;
}
Status RosNodeView::SendCancel() {
  return remote_->remote ? remote_->remote->SendCancel() : kNotConnected;
}
Status RosNodeView::SendStop(const std::string& reason) {
  stop_kept_ = true;
  stop_reason_ = reason;
  return remote_->remote ? remote_->remote->SendStop(reason) : kNotConnected;
}
Status RosNodeView::SendStart() {
  const Status sent = remote_->remote ? remote_->remote->SendStart() : kNotConnected;
  if (sent.ok()) {  // Otherwise the STOP stays kept: no node heard START.
    stop_kept_ = false;
    stop_reason_.clear();
  }
  return sent;
}
bool RosNodeView::node_listening() const {
  return remote_->remote != nullptr && remote_->remote->node_listening();
}
#else
bool RosNodeView::node_listening() const { return false; }
Status RosNodeView::SendTap(double, double, double) {
  return Status(StatusCode::kUnavailable, "this build has no ROS");
}
Status RosNodeView::SendConfirm() { return SendTap(0, 0, 0); }
Status RosNodeView::SendCancel() { return SendTap(0, 0, 0); }
Status RosNodeView::SendStop(const std::string&) { return SendTap(0, 0, 0); }
Status RosNodeView::SendStart() { return SendTap(0, 0, 0); }
#endif

void RosNodeView::ShowStatus() {
  status_label_->setText(connected_ ? tr("ROS: connected to %1").arg(uri_)
                                    : tr("ROS: disconnected — reconnecting to %1").arg(uri_));
  status_label_->show();
}

void RosNodeView::Apply(const std::shared_ptr<const RemoteUpdate>& update) {
#ifdef SIGHTLINE_HAVE_ROS
  if (remote_->remote == nullptr) return;  // Arrived after Disconnect.
  switch (update->kind) {
    case RemoteUpdate::Kind::kConnection:
      connected_ = update->connected;
      ShowStatus();
      emit ConnectionChanged(connected_, uri_);
      break;
    case RemoteUpdate::Kind::kMap:
      if (update->map.width <= 0 || update->map.height <= 0) break;
      map_view_->SetImage(MapImage(update->map), ImageView::Kind::kGray);
      ++maps_shown_;
      emit MapShown(update->map.width, update->map.height);
      break;
    case RemoteUpdate::Kind::kOdometry:
      trajectory_.Add(update->stamp_s, update->pose.parent_from_child);
      if (scene_ != nullptr)
        scene_->SetTrajectory(kTrajectoryLayer, trajectory_, QColor(255, 170, 0));
      break;
    case RemoteUpdate::Kind::kWalls: {
      if (scene_ == nullptr) break;
      // Walls are drawn in the robot's frame: placed at its latest pose.
      std::vector<SceneView::Segment> segments(update->walls.segments.begin(),
                                               update->walls.segments.end());
      scene_->SetLines(kWallsLayer, segments, QColor(80, 200, 255));
      if (!trajectory_.empty()) {
        scene_->SetLayerPose(kWallsLayer, trajectory_.poses().back().world_from_sensor);
      }
      break;
    }
    case RemoteUpdate::Kind::kCloud: {
      if (scene_ == nullptr) break;
      auto cloud = std::make_shared<PointCloud>();
      cloud->points = update->cloud.points;
      cloud->width = static_cast<int>(cloud->points.size());
      const std::string topic = update->cloud.topic.substr(update->cloud.topic.rfind('/') + 1);
      scene_->SetPointCloud(std::string(kCloudLayerPrefix) + "/" + topic, cloud);
      break;
    }
    case RemoteUpdate::Kind::kTarget:
      if (scene_ != nullptr) scene_->SetPoses(kTargetLayer, {update->target.pose}, QColor(), 0.1);
      emit ButtonUpdate(update);
      break;
    case RemoteUpdate::Kind::kButtonImage:
    case RemoteUpdate::Kind::kGate:
    case RemoteUpdate::Kind::kStopState:
      emit ButtonUpdate(update);
      break;
  }
#endif
}

}  // namespace sightline
