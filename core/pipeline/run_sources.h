// How a headless run (pipeline_registry.cpp) opens what it runs on. Two definitions, one per
// library, so the run loop links no more than its program needs:
//   sightline_pipeline        run_sources_live.cpp: sensor URIs, .oni and .bag files, sim://
//                             and datasets (OpenRunSource, OpenSource, DeclareSourceOptions);
//   sightline_pipeline_stereo run_sources_recorded.cpp: recorded datasets only (core/io's
//                             readers), without the sensor drivers, ROS or the simulator.
#pragma once

#include <memory>
#include <string>

#include "core/common/status.h"
#include "core/io/source.h"
#include "core/options/option_set.h"

namespace sightline {

// True for a path a driver or the simulator opens rather than a dataset folder.
bool IsRunSourceLive(const std::string& uri);

// Opens a path for which IsRunSourceLive is true, with the drivers' options in `options`.
StatusOr<std::unique_ptr<Source>> OpenLiveRunSource(const std::string& uri,
                                                    const OptionSet& options);

// Opens any path, a sensor URI or a dataset of any kind, for a pipeline that takes any kind.
StatusOr<std::unique_ptr<Source>> OpenAnyRunSource(const std::string& uri,
                                                   const OptionSet& options);

// Declares the options of the driver that opens `uri` (io.rosbag.* for a .bag) that `options`
// lacks, before a profile and --set are applied. Nothing for datasets.
Status DeclareRunSourceOptions(const std::string& uri, OptionSet* options);

// What a run on `uri` sets up once its options are final (a sim:// run's tap and hand-eye,
// sim_panel_source.h). Nothing for datasets.
Status PrepareRunSource(const std::string& uri, const std::string& out_dir, OptionSet* options);

}  // namespace sightline
