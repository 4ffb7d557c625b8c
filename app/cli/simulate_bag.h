// `sightline-cli simulate SCENE --out DIR --format bag`: the simulator's recording as one ROS bag.
#pragma once

#include <atomic>
#include <functional>
#include <string>

#include "core/common/status.h"
#include "core/sim/simulation_options.h"

namespace sightline::cli {

// What a bag holds after SimulateToBag.
struct SimulatedBag {
  std::string path;
  int frames = 0;
  int64_t messages = 0;
};

// Renders every frame of `options`' sensors into `path`: RGB-D as /camera/rgb/image_color
// (bgr8), /camera/depth/image (32FC1) and /camera/rgb/camera_info; stereo as
// /stereo/{left,right}/image_raw (mono8) and camera_info (the right P gives the baseline); mono
// as /mono/image_raw and /mono/camera_info; each camera's true pose on /tf (world -> its frame,
// the images' frame_id), wheel odometry on /odom (odom -> base_link) and an arm's reported poses
// on /tf (base_link -> end_effector). Stamps are the simulator's times plus 1 s (a bag holds no
// time 0). Unavailable when built without ROS.
StatusOr<SimulatedBag> SimulateToBag(const sim::SimulationOptions& options, const std::string& path,
                                     const std::function<void(int64_t, int64_t)>& progress,
                                     const std::atomic<bool>* cancel);

}  // namespace sightline::cli
