#include "core/ros/ros_client.h"

#include <ros/ros.h>

#include <chrono>
#include <cstdlib>
#include <mutex>
#include <thread>
#include <vector>

#include "core/ros/ros_live_source.h"

namespace sightline {
namespace {

// Shuts ROS down once `cancel` is set; lives until the process ends.
void WatchCancel(const std::atomic<bool>* cancel) {
  if (cancel == nullptr) return;
  std::thread([cancel] {
    while (!cancel->load()) {
      if (!ros::ok()) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ros::requestShutdown();
  }).detach();
}

}  // namespace

Status StartRosClient(const std::atomic<bool>* cancel) {
  static std::mutex mutex;
  static std::unique_ptr<ros::AsyncSpinner> spinner;
  std::lock_guard<std::mutex> lock(mutex);
  if (spinner) return Status::Ok();
  const char* master = std::getenv("ROS_MASTER_URI");
  const std::string where = master != nullptr ? master : "(ROS_MASTER_URI unset)";
  if (!ros::isInitialized()) {
    int argc = 0;
    ros::init(argc, nullptr, "sightline_cli",
              ros::init_options::AnonymousName | ros::init_options::NoSigintHandler |
                  ros::init_options::NoRosout);
  }
  if (!ros::master::check()) {
    return Unavailable("no ROS master answers at " + where +
                       " (start roscore, or set ROS_MASTER_URI)");
  }
  ros::start();
  spinner = std::make_unique<ros::AsyncSpinner>(1);
  spinner->start();
  WatchCancel(cancel);
  return Status::Ok();
}

StatusOr<std::unique_ptr<Source>> OpenRosLiveSourceAsClient(const std::string& uri,
                                                            const std::atomic<bool>* cancel) {
  SIGHTLINE_RETURN_IF_ERROR(StartRosClient(cancel));
  return OpenRosLiveSource(uri);
}

}  // namespace sightline
