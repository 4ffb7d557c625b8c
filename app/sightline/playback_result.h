// What the playback worker hands the GUI for one frame: immutable, shared, ready to draw.
#pragma once

#include <QMetaType>
#include <memory>
#include <opencv2/core.hpp>

#include "app/sightline/frame_processor.h"
#include "core/common/frame.h"

namespace sightline {

// One frame prepared for the views. Built on the worker thread, read on the GUI thread.
struct PlaybackResult {
  FrameStamp stamp;
  int64_t frame_count = -1;
  cv::Mat primary_image;    // Colour or left or mono image (BGR or gray); may be empty.
  cv::Mat secondary_image;  // Depth (CV_32F metres) or right image; may be empty.
  bool secondary_is_depth = false;
  // A cloud source's cloud, in the sensor frame; null otherwise (an RGB-D frame's cloud is made
  // from its images on request: PlaybackController::MakeCloud).
  std::shared_ptr<const PointCloud> cloud;
  int cloud_stride = 2;  // The view options the frame was prepared with (RGB-D frames).
  double max_depth_m = 6.0;
  double prepare_ms = 0;  // Worker time to read and prepare the frame.
  std::shared_ptr<const PipelineFrameResult> pipeline;  // The active pipeline's result, if any.
  // The pipeline started over at this frame (its first, or after a seek or loop either way):
  // views that accumulate (trajectories, plots) start over too.
  bool pipeline_restarted = false;
};

}  // namespace sightline

Q_DECLARE_METATYPE(std::shared_ptr<const sightline::PlaybackResult>)
