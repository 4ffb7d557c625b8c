// The pipelines of the program a command runs in: sightline-cli-full has every pipeline
// (program_pipelines_full.cpp: BuiltinPipelines()), sightline-cli-stereo only stereo-vo
// (program_pipelines_stereo.cpp). command_run.cpp and command_options.cpp take them from here.
#pragma once

#include <atomic>
#include <string>

#include "core/pipeline/pipeline_registry.h"

namespace sightline::cli {

PipelineRegistry ProgramPipelines();

// How this program opens `path` when core's readers and drivers do not: in sightline-cli-full
// built with ROS, a ros:// URI joins the master as a client (core/ros/ros_client.h; `cancel`
// shuts it down on Ctrl-C). Empty when the usual opening applies.
SourceOpener ProgramSourceOpener(const std::string& path, const std::atomic<bool>* cancel);

}  // namespace sightline::cli
