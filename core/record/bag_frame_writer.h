// A FrameWriter that records into one ROS 1 bag, DIR/recording.bag, in Sightline's bag layout
// (BagWriter::WriteRgbdFrame and its siblings; core/ros/bag_source.h reads it back).
// Stamps are the frames' sensor times (shifted by whole seconds when they start before 1 s:
// a bag holds no time 0; a note says so). lz4 chunks. A bag is indexed when the recording
// ends; one cut off before (power loss) opens after `rosbag reindex`.
#pragma once

#include <memory>
#include <string>

#include "core/common/status.h"
#include "core/io/source.h"
#include "core/record/frame_writers.h"

namespace sightline {

// The bag's file name inside a recording folder.
inline constexpr const char* kRecordingBagName = "recording.bag";

// Creates DIR/recording.bag for frames like `info` describes. InvalidArgument for point
// clouds or a source without calibration; Unavailable naming the file when it cannot be
// created or when Sightline was built without ROS.
StatusOr<std::unique_ptr<FrameWriter>> CreateBagFrameWriter(const std::string& dir,
                                                            const SourceInfo& info);

}  // namespace sightline
