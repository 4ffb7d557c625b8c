// sightline-node's publishers: one set per pipeline, fed each frame's typed result on the
// pipeline loop's thread. Messages come from core/ros/ros_publish.h.
#pragma once

#include <ros/node_handle.h>

#include <memory>
#include <string>

#include "core/pipeline/pipeline.h"
#include "core/ros/ros_publish.h"

namespace sightline::node {

class ResultPublisher {
 public:
  virtual ~ResultPublisher() = default;
  // Publishes one frame's result (stamped with its sensor time).
  virtual void Publish(const PipelineResult& result) = 0;
};

// The publishers of pipeline `pipeline` ("mapping", "stereo-vo", "mono-slam", "mobility";
// any other publishes its diagnostics only; "button" is MakeButtonPublisher's), advertised on `nh`
// (the node's namespace), plus `diagnostics` from `table`.
std::unique_ptr<ResultPublisher> MakeResultPublisher(const std::string& pipeline,
                                                     const StatisticTable& table,
                                                     ros::NodeHandle& nh, const RosFrames& frames);

// mono-slam's publishers (odom + tf in frames.map, map_points, keyframes, diagnostics as
// `pipeline`), which the button pipeline's publisher also uses.
std::unique_ptr<ResultPublisher> MakeSlamPublisher(const std::string& pipeline,
                                                   const StatisticTable& table, ros::NodeHandle& nh,
                                                   const RosFrames& frames);

}  // namespace sightline::node
