// The inside of MappingPipeline (mapping_pipeline.h), shared by its two source files: the state
// of one run and what its files are written from. Not for other users.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/mapping/floor_plane.h"
#include "core/mapping/mapping_frame_processor.h"
#include "core/pipeline/mapping_pipeline.h"
#include "core/pipeline/mapping_recording.h"
#include "core/pipeline/statistics_log.h"

namespace sightline {

// One mapped frame's lines and scan geometry, for the accuracy figures.
struct MappedFrameLines {
  double time_s = 0;
  std::vector<WallSegment> lines;
  double fov_min_rad = 0, fov_max_rad = 0, resolution_rad = 0;
  int rays = 0;
};

// What the run's files are written from, one entry per mapped frame since the mapping chain
// last started (entry k belongs to the chain's trajectory()[k]).
struct MappingRunRecord {
  std::vector<std::string> frame_log;  // Degenerate frames and resets.
  std::string lines_csv;               // The rows of lines.csv.
  std::vector<MappedFrameLines> frames;
  std::map<std::string, int> statuses;  // Frames per chain status ("ok", "no walls", ...).
  // Per source of the person boxes used (ground truth, depth, hog, none): frames and boxes.
  std::map<std::string, std::pair<int, int>> people_sources;
  std::map<std::string, int> pose_sources;  // Frames per pose source (recording, rgbd, none).
  StatisticsLog stats;                      // Every mapped frame's statistics.

  // Adds one mapped frame; `reset_log` is the chain's log of resets.
  void Add(const MappingFrameResult& r, const std::vector<std::string>& reset_log);
  void Clear() { *this = MappingRunRecord(); }
};

struct MappingPipeline::State {
  std::shared_ptr<const MappingRequests> requests;
  int requests_seen = 0;
  MappingOptions options;
  MappingRunOptions run;
  bool configured = false;
  std::optional<PipelineSource> source;  // Set by Open.
  MappingRecording recording;
  std::optional<FloorCalibration> floor;
  std::string floor_log;  // How the floor in use was found, for mapping_log.txt.
  std::unique_ptr<FloorCalibrator> calibrator;
  std::vector<RgbdFrame> pending;  // Frames waiting for the floor calibration.
  std::string floor_failure;       // Why the last floor calibration found no floor.
  int64_t floorless_frames = 0;    // Frames given up on because they showed no floor.
  std::unique_ptr<MappingFrameProcessor> chain;
  MappingRunRecord record;

  // Starts the run again on the opened source with the current options: the recording's
  // extras, the floor (from mapping.run.floor_file; else the calibrated one if `keep_floor`).
  Status StartRun(bool keep_floor);
  // A new mapping chain on the floor in use; forgets the mapped frames.
  Status StartChain();
  // Forgets the floor: the next frames calibrate it again.
  void ForgetFloor();
  // Frames the automatic calibration waits for (fewer when the run is shorter).
  size_t FloorFramesWanted() const;
  // Takes a "Calibrate floor" request of the GUI, if one came.
  void TakeRequests();
  // Buffers a frame for the floor calibration; when enough are in, calibrates and maps them.
  StatusOr<std::shared_ptr<const MappingResult>> CalibrateWith(const RgbdFrame& frame);
  // Fits the floor on the buffered frames and maps them.
  StatusOr<std::shared_ptr<const MappingResult>> CalibrateAndMapPending();
  // Gives up on `frames` that show no floor (`why`); the next frames calibrate again.
  std::shared_ptr<const MappingResult> NoFloorIn(const std::vector<RgbdFrame>& frames,
                                                 const std::string& why);
  // Runs the mapping chain on one frame and records it for the run's files.
  StatusOr<std::shared_ptr<const MappingResult>> MapFrame(const RgbdFrame& frame);
};

// The run's files and figures (mapping_outputs.cpp).
StatusOr<RunResult> FinishMappingRun(const MappingPipeline::State& state,
                                     const std::string& out_dir);
// A run none of whose frames showed a floor: nothing mapped, mapping_log.txt says why.
StatusOr<RunResult> FinishFloorlessRun(const MappingPipeline::State& state,
                                       const std::string& out_dir);

}  // namespace sightline
