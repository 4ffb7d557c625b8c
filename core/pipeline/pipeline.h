// One perception pipeline as one object, run the same way by every front end: the CLI's
// headless loop (RunHeadless), the GUI's playback worker, and any other driver of frames.
//
//   std::unique_ptr<Pipeline> pipeline = info.create();
//   pipeline->Configure(options);                   // Validated options, by value.
//   pipeline->Open(PipelineSource::From(source));   // Calibration, ground truth, folder.
//   while (...) {
//     StatusOr<std::shared_ptr<const PipelineResult>> r = pipeline->Process(frame);
//     if (!r.ok()) break;                           // The run cannot go on.
//     draw_or_write(**r);                           // (*r)->status: this frame's problem.
//   }
//   StatusOr<RunResult> summary = pipeline->Finish(out_dir);  // The run's files.
//
// Decisions inside a pipeline use the frames' sensor timestamps (data time), never the host
// clock, so a recording gives the same outputs at any playback speed or machine load. A check
// that guards a live device by the host clock is named as such where it is made.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/common/trajectory.h"
#include "core/io/source.h"
#include "core/options/option_set.h"

namespace sightline {

// One per-frame figure a pipeline publishes, e.g. {"vo/inliers", "count", "..."}. Every front
// end names and labels figures from this table: frames.csv columns, metrics.json timing
// ("ms" figures) and counts, the GUI's plots and statistics dock.
struct StatisticInfo {
  std::string key;          // "module/name", e.g. "mapping/lines_ms".
  std::string unit;         // "ms", "count", "px", "m", "deg", "%", "" for a flag.
  std::string description;  // One line for a user.
};
using StatisticTable = std::vector<StatisticInfo>;

// The row of `table` whose key is `key`, or null.
const StatisticInfo* FindStatistic(const StatisticTable& table, const std::string& key);

// What a pipeline produced for one frame: built once, then shared read-only (views, writers
// and other threads may hold it). Pipelines derive from it with everything their views and
// writers need.
struct PipelineResult {
  virtual ~PipelineResult() = default;
  FrameStamp stamp;                                   // The input frame.
  Status status;                                      // Why this frame gave no result, if so.
  std::vector<std::pair<std::string, double>> stats;  // Keys from the pipeline's Statistics().

  // The value of statistic `key`, if this frame has it.
  std::optional<double> Stat(const std::string& key) const;
};

// What a pipeline knows of its source when it opens: what the source says of itself and the
// recording's ground truth (null when there is none or the source is live).
struct PipelineSource {
  SourceInfo info;
  std::shared_ptr<const Trajectory> ground_truth;
  // The platform's odometry the source carries beside its frames (Source::odometry()), or null.
  std::shared_ptr<const Trajectory> odometry;
  // The arm's poses (base_from_end_effector) the source carries (Source::arm_poses()), or null.
  std::shared_ptr<const Trajectory> arm_poses;
  // A live source's odometry and arm poses so far (Source::odometry() / arm_poses(), which a
  // live source extends at each frame's stamp before handing the frame on), for pipelines that
  // take them frame by frame; empty for recordings. They read the source: call them only while
  // it is open, from the thread that drives it.
  std::function<const Trajectory*()> live_odometry, live_arm_poses;

  // The info and a copy of the ground truth of an opened source (and, for a live source, the
  // live poses, which refer to `source`).
  static PipelineSource From(const Source& source);
};

// What a finished run returns besides its files.
struct RunResult {
  std::string dataset_format;  // As the source reported it.
  int64_t frames = 0;
  std::vector<std::pair<std::string, double>> accuracy;  // Keys as documented per pipeline.
  std::vector<std::pair<std::string, double>> counts;
  std::vector<std::string> outputs;  // Files written, relative to out_dir.
  std::vector<std::string> notes;    // Facts a user should read (also in the CLI's output).
  // Why the run achieved nothing although it ran: no frame tracked, never initialised, every
  // frame gated, no target sent when one was asked for. Empty for a run with results. The CLI
  // prints it first and exits with kExitNothingAchieved; metrics.json states it as "failure".
  std::string nothing_achieved;
  // Why the run stopped before its source ended although its files so far were written: a
  // cancel (Ctrl-C, SIGTERM, the GUI's Stop) or an error at a frame. Ok for a run that ran to
  // the end of its source or its frame limit. metrics.json states it as "ended" and
  // "end_reason".
  Status ended_early;
};

// `sightline-cli run`'s exit codes: 0 results written; 1 an error (bad input, options, data;
// when it came mid-run, the files up to that frame are written); 3 the run completed and wrote
// its files but achieved nothing (RunResult::nothing_achieved); 130 the run was cancelled
// (Ctrl-C or SIGTERM) and wrote its files up to then.
constexpr int kExitError = 1;
constexpr int kExitNothingAchieved = 3;
constexpr int kExitCancelled = 130;

// One pipeline. Not thread-safe: one thread drives it at a time (the GUI's worker, the CLI's
// loop). Every pipeline is constructible many times in one process.
class Pipeline {
 public:
  virtual ~Pipeline() = default;

  // Applies options (the pipeline's whole option set, already validated against its tables).
  // Called before Open and again between frames when a user changes a value; a bad value is
  // an error naming its key and the previous options stay in force.
  virtual Status Configure(const OptionSet& options) = 0;
  // Starts a run on a source: its calibration, kind and ground truth. Forgets any earlier run.
  // Errors say what the source lacks (e.g. no stereo calibration) and how to give it.
  virtual Status Open(const PipelineSource& source) = 0;
  // Whether the frame at stream index `index` is wanted (e.g. every k-th frame); the loop
  // grabs unwanted frames without decoding them.
  virtual bool Wants(int64_t index) const {
    (void)index;
    return true;
  }
  // Frames to read from the source at most (before Wants), 0 = all; a live source runs until
  // this limit or a cancel.
  virtual int64_t FrameLimit() const { return 0; }
  // Processes the next frame and advances the pipeline's state. An error means the run cannot
  // go on (the CLI exits with it, the GUI stops the pipeline and says why); a problem with
  // this frame alone is the result's status.
  virtual StatusOr<std::shared_ptr<const PipelineResult>> Process(const Frame& frame) = 0;
  // Runs a frame again with the current options so that a changed threshold shows at once
  // while paused. By default this restarts the run's state from that frame.
  virtual StatusOr<std::shared_ptr<const PipelineResult>> Reprocess(const Frame& frame) {
    Reset();
    return Process(frame);
  }
  // Forgets the run's state (a seek, or the user's reset); options and source stay.
  virtual void Reset() = 0;
  // The run ends early (cancelled, or an error; `reason` says which): live outputs are told at
  // once, e.g. arm clients get a stop line naming the reason. Files are not written here; the
  // headless loop calls Finish after Abort to write the results so far.
  virtual void Abort(const std::string& reason) { (void)reason; }
  // Writes the run's files so far into `out_dir` (which exists) and returns its figures. The
  // CLI calls it after the last frame; the GUI for File > Save results, after which the run
  // may go on (Finish leaves the run's state as it is).
  virtual StatusOr<RunResult> Finish(const std::string& out_dir) = 0;
  // The per-frame statistics this pipeline publishes.
  virtual const StatisticTable& Statistics() const = 0;
};

}  // namespace sightline
