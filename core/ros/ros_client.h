// Live ROS topics for a program that is not itself a ROS node (sightline-cli `run` and `record`
// on a ros:// URI): joins the master named by ROS_MASTER_URI once per process under an anonymous
// name, spins callbacks on a background thread, and shuts ROS down when `cancel` becomes true
// (Ctrl-C), so a source waiting for a frame returns Cancelled. ROS-free header.
#pragma once

#include <atomic>
#include <memory>
#include <string>

#include "core/common/status.h"
#include "core/io/source.h"

namespace sightline {

// ros::init (anonymous "sightline_cli", no SIGINT handler, no rosout) and a spinner, once per
// process; Unavailable naming ROS_MASTER_URI when no master answers. `cancel` may be null.
Status StartRosClient(const std::atomic<bool>* cancel);

// StartRosClient, then OpenRosLiveSource(uri).
StatusOr<std::unique_ptr<Source>> OpenRosLiveSourceAsClient(const std::string& uri,
                                                            const std::atomic<bool>* cancel);

}  // namespace sightline
