// How a perception pipeline runs inside the GUI: a FrameProcessor works on the playback worker
// thread, frame by frame; its immutable results reach the GUI thread in PlaybackResult.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/io/source.h"
#include "core/options/option_set.h"

namespace sightline {

// What a pipeline produced for one frame. Pipelines derive from it; their presenters downcast.
struct PipelineFrameResult {
  virtual ~PipelineFrameResult() = default;
  FrameStamp stamp;                                   // The input frame.
  Status status;                                      // Why the frame gave no result, if so.
  std::vector<std::pair<std::string, double>> stats;  // Named figures, e.g. {"lines_ms", 0.4}.
};

// Runs one pipeline on the worker thread. Never touched by the GUI thread after creation.
class FrameProcessor {
 public:
  virtual ~FrameProcessor() = default;
  // Applies new options (called on the worker thread, between frames). A bad value is reported
  // and the previous options stay in force.
  virtual Status Configure(const OptionSet& options) = 0;
  // Processes the next frame of the stream and advances the pipeline's state.
  virtual std::shared_ptr<const PipelineFrameResult> Process(const Frame& frame) = 0;
  // Runs the last frame again with the current options without advancing state, so that a
  // threshold change shows at once while paused.
  virtual std::shared_ptr<const PipelineFrameResult> Reprocess(const Frame& frame) = 0;
  // Forgets all state (a new dataset, a seek, or the user's reset).
  virtual void Reset() = 0;
};

}  // namespace sightline
