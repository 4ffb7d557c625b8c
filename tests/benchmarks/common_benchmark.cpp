// Benchmarks of the per-frame plumbing every pipeline pays for.
#include <benchmark/benchmark.h>

#include <thread>

#include "core/common/bounded_queue.h"
#include "core/common/depth_cloud.h"

namespace sightline {
namespace {

// Back-projection of a Kinect-sized depth image with colour (the GUI's 3D view does this per
// frame at the given stride).
void BM_DepthToCloud(benchmark::State& state) {
  const int stride = static_cast<int>(state.range(0));
  PinholeCamera camera;
  camera.width = 640;
  camera.height = 480;
  camera.fx = camera.fy = 525;
  camera.cx = 319.5;
  camera.cy = 239.5;
  cv::Mat depth(480, 640, CV_32FC1);
  cv::randu(depth, 0.5f, 5.0f);
  cv::Mat color(480, 640, CV_8UC3, cv::Scalar(40, 80, 120));
  for (auto _ : state) {
    PointCloud cloud = DepthToCloud(depth, color, camera, stride);
    benchmark::DoNotOptimize(cloud.points.data());
  }
  state.SetItemsProcessed(state.iterations() * (640 / stride) * (480 / stride));
}
BENCHMARK(BM_DepthToCloud)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

// Items per second through a bounded queue between two threads.
void BM_BoundedQueueHandOff(benchmark::State& state) {
  const auto policy = state.range(0) == 0 ? QueuePolicy::kBlockWhenFull : QueuePolicy::kDropOldest;
  constexpr int kItems = 10000;
  for (auto _ : state) {
    BoundedQueue<int> queue("bench", 8, policy);
    std::thread consumer([&] {
      while (queue.Pop()) {
      }
    });
    for (int i = 0; i < kItems; ++i) queue.Push(i);
    queue.Shutdown();
    consumer.join();
  }
  state.SetItemsProcessed(state.iterations() * kItems);
}
BENCHMARK(BM_BoundedQueueHandOff)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace sightline
