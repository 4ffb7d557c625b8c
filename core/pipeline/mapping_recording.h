// What a mapping run reads beside the depth frames of a recording (MappingPipeline): wheel
// odometry, person boxes, true walls and the camera's offset.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/common/camera.h"
#include "core/common/frame.h"
#include "core/common/trajectory.h"
#include "core/io/source.h"
#include "core/mapping/mapping_accuracy.h"
#include "core/mapping/mapping_frame_processor.h"
#include "core/mapping/person_boxes.h"
#include "core/pipeline/pipeline.h"

namespace sightline {

struct MappingRunOptions;

// A recording's extra files for mapping, found in its top folder (the parent of an rgbd/
// sensor folder): odometry.txt, people.csv, walls.csv, scene.yaml.
struct MappingRecording {
  std::string root;                    // The folder the files were looked for in.
  PinholeCamera camera;                // The depth camera.
  std::optional<Trajectory> odometry;  // world_from_base of the wheel odometry.
  // Without `odometry`: a live source's odometry so far (PipelineSource::live_odometry).
  std::function<const Trajectory*()> live_odometry;
  std::optional<PersonBoxTable> people;        // Ground-truth person boxes.
  std::optional<std::vector<TrueWall>> walls;  // True wall faces, for accuracy.
  double camera_forward_m = 0;                 // Optical centre ahead of the odometry base [m].
  // The pose source the mapping chain is given: "recording" when the odometry above is used,
  // else mapping.pose.source as asked (auto: RGB-D odometry when the frames have colour).
  std::string pose_source = "auto";
  std::vector<std::string> log_lines;  // What was found, for the run's log.

  // One frame's mapping input: depth, colour, the odometry pose (moved to the camera) within
  // `tolerance_s` of the frame, and the frame's person boxes.
  MappingInput MakeInput(const RgbdFrame& frame, double tolerance_s) const;
};

// The folder holding a recording's extra files for a dataset path.
std::string MappingRecordingRoot(const std::string& dataset_path);

// Loads the extras of the recording the source was opened from. The odometry is the folder's
// odometry.txt, else the one the source carries (a ROS bag's Odometry topic or tf), else for a
// live source its odometry frame by frame (ros:// tf); it is kept only when `pose_source`
// (mapping.pose.source) uses it: auto or recording. The log says which pose source the run
// has. Errors name the bad file, or say that pose_source recording found no odometry.
StatusOr<MappingRecording> LoadMappingRecording(const PipelineSource& source,
                                                const MappingRunOptions& run,
                                                const std::string& pose_source = "auto");

}  // namespace sightline
