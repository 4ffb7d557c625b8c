// A processing stage and the worker that runs it on its own thread between bounded queues.
#pragma once

#include <atomic>
#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <thread>

#include "core/common/bounded_queue.h"
#include "core/common/status.h"
#include "core/common/timing.h"

namespace sightline {

// One step of a pipeline: processes one input and returns. Holds no thread logic, so the same
// stage runs inline in a test or the CLI, or on a StageWorker in the GUI.
template <typename In, typename Out>
class Stage {
 public:
  virtual ~Stage() = default;
  // Name used for timing statistics, e.g. "occupancy".
  virtual std::string Name() const = 0;
  virtual StatusOr<Out> Process(const In& input) = 0;
};

// Runs `stage` inline once, adding its duration to `timing` under the stage's name.
template <typename In, typename Out>
StatusOr<Out> RunTimed(Stage<In, Out>& stage, const In& input, TimingStats* timing) {
  ScopedTimer timer(timing, stage.Name());
  return stage.Process(input);
}

// Runs a stage on a worker thread: pops inputs from a queue, hands each result (or error) to a
// callback on the worker thread. Exceptions thrown by the stage become Status values; they never
// escape the thread.
//
//   BoundedQueue<Input> inputs("inputs", 4, QueuePolicy::kBlockWhenFull);
//   StageWorker<Input, Output> worker(&stage, &inputs, &timing,
//       [](StatusOr<Output> r) { ... });
//   worker.Start();
//   inputs.Push(x); ...
//   worker.Stop();  // Or inputs.Shutdown() to finish the queued inputs first, then Join().
template <typename In, typename Out>
class StageWorker {
 public:
  using OutputCallback = std::function<void(StatusOr<Out>)>;

  StageWorker(Stage<In, Out>* stage, BoundedQueue<In>* input, TimingStats* timing,
              OutputCallback on_output)
      : stage_(stage), input_(input), timing_(timing), on_output_(std::move(on_output)) {}
  ~StageWorker() { Stop(); }
  StageWorker(const StageWorker&) = delete;
  StageWorker& operator=(const StageWorker&) = delete;

  void Start() {
    if (thread_.joinable()) return;
    cancel_ = false;
    thread_ = std::thread([this] { Loop(); });
  }
  // Cancels: the current input finishes, queued inputs are left, the thread ends.
  void Stop() {
    cancel_ = true;
    input_->Shutdown();
    Join();
  }
  // Waits for the thread to end (after the input queue is shut down and drained).
  void Join() {
    if (thread_.joinable()) thread_.join();
  }
  bool cancelled() const { return cancel_; }
  uint64_t processed() const { return processed_; }

 private:
  void Loop() {
    while (!cancel_) {
      std::optional<In> item = input_->Pop();
      if (!item || cancel_) break;
      StatusOr<Out> result = Internal("stage did not run");
      try {
        if (timing_ != nullptr) {
          result = RunTimed(*stage_, *item, timing_);
        } else {
          result = stage_->Process(*item);
        }
      } catch (const std::exception& e) {
        result = Internal(stage_->Name() + " threw: " + e.what());
      } catch (...) {
        result = Internal(stage_->Name() + " threw an unknown exception");
      }
      ++processed_;
      if (on_output_) on_output_(std::move(result));
    }
  }

  Stage<In, Out>* stage_;
  BoundedQueue<In>* input_;
  TimingStats* timing_;
  OutputCallback on_output_;
  std::thread thread_;
  std::atomic<bool> cancel_{false};
  std::atomic<uint64_t> processed_{0};
};

}  // namespace sightline
