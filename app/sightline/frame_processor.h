// How a perception pipeline runs inside the GUI: the core Pipeline object (core/pipeline) works
// on the playback worker thread, frame by frame; its immutable results reach the GUI thread in
// PlaybackResult. FrameProcessor is the shape of the GUI-only processors that are not yet core
// pipelines; it adapts them to the Pipeline interface.
#pragma once

#include <memory>
#include <string>

#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/options/option_set.h"
#include "core/pipeline/pipeline.h"

namespace sightline {

// What a pipeline produced for one frame (presenters downcast to their pipeline's result).
using PipelineFrameResult = PipelineResult;

// A GUI-only processor: processes frames but writes no run files and publishes no statistics
// table. Never touched by the GUI thread after creation.
class FrameProcessor : public Pipeline {
 public:
  Status Open(const PipelineSource& source) override {
    (void)source;
    return Status::Ok();
  }
  StatusOr<std::shared_ptr<const PipelineResult>> Process(const Frame& frame) final {
    return ProcessFrame(frame);
  }
  StatusOr<std::shared_ptr<const PipelineResult>> Reprocess(const Frame& frame) final {
    return ReprocessFrame(frame);
  }
  StatusOr<RunResult> Finish(const std::string& out_dir) override {
    return FailedPrecondition("this pipeline cannot save its results to " + out_dir + " yet");
  }
  const StatisticTable& Statistics() const override {
    static const StatisticTable kNone;
    return kNone;
  }

 protected:
  // Processes the next frame of the stream and advances the pipeline's state.
  virtual std::shared_ptr<const PipelineFrameResult> ProcessFrame(const Frame& frame) = 0;
  // Runs the last frame again with the current options without advancing state.
  virtual std::shared_ptr<const PipelineFrameResult> ReprocessFrame(const Frame& frame) = 0;
};

}  // namespace sightline
