#include "core/pipeline/stage.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace sightline {
namespace {

class SquareStage : public Stage<int, int> {
 public:
  std::string Name() const override { return "square"; }
  StatusOr<int> Process(const int& x) override {
    if (x < 0) return InvalidArgument("negative input " + std::to_string(x));
    if (x == 13) throw std::runtime_error("unlucky");
    return x * x;
  }
};

TEST(Stage, RunsInlineWithTiming) {
  SquareStage stage;
  TimingStats timing;
  StatusOr<int> r = RunTimed(stage, 7, &timing);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(*r, 49);
  EXPECT_EQ(timing.Summary("square").count, 1u);
}

TEST(StageWorker, ProcessesEveryQueuedInputOnItsThreadAndTurnsThrowsIntoStatus) {
  SquareStage stage;
  TimingStats timing;
  BoundedQueue<int> inputs("inputs", 2, QueuePolicy::kBlockWhenFull);
  std::mutex mutex;
  std::vector<int> outputs;
  std::vector<std::string> errors;
  StageWorker<int, int> worker(&stage, &inputs, &timing, [&](StatusOr<int> r) {
    std::lock_guard<std::mutex> lock(mutex);
    if (r.ok())
      outputs.push_back(*r);
    else
      errors.push_back(r.status().message());
  });
  worker.Start();
  for (int i : {1, 2, -3, 13, 4}) ASSERT_TRUE(inputs.Push(i));
  inputs.Shutdown();
  worker.Join();
  EXPECT_EQ(outputs, (std::vector<int>{1, 4, 16}));
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0], "negative input -3");
  EXPECT_EQ(errors[1], "square threw: unlucky");
  EXPECT_EQ(timing.Summary("square").count, 5u);
}

TEST(StageWorker, StopEndsAnIdleWorker) {
  SquareStage stage;
  BoundedQueue<int> inputs("inputs", 2, QueuePolicy::kBlockWhenFull);
  StageWorker<int, int> worker(&stage, &inputs, nullptr, nullptr);
  worker.Start();
  worker.Stop();  // Must return although no input ever arrives.
  EXPECT_TRUE(worker.cancelled());
  EXPECT_EQ(worker.processed(), 0u);
}

}  // namespace
}  // namespace sightline
