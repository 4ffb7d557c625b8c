// What reading frames from a ROS bag costs against the folder reader of the same frames: the
// TUM fr1_desk frames as a TUM folder (colour PNG + 16-bit depth PNG) and as a bag (rgb8 + 32FC1
// messages), each read from the first frame to the last per iteration; and opening the bag.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <memory>
#include <string>

#include "core/io/tum_rgbd_source.h"
#include "core/ros/bag_source.h"

namespace sightline {
namespace {

std::string DataPath(const std::string& name) {
  const char* env = std::getenv("SIGHTLINE_DATA_DIR");
  return std::string(env ? env : SIGHTLINE_DEFAULT_DATA_DIR) + "/" + name;
}

// Reads every frame of an opened source once per iteration; items = frames.
void ReadAll(benchmark::State& state, Source& source, const std::string& what) {
  if (Status opened = source.Open(); !opened.ok()) {
    state.SkipWithError((what + ": " + opened.ToString()).c_str());
    return;
  }
  int64_t frames = 0;
  for (auto _ : state) {
    if (!source.Seek(0).ok()) {
      state.SkipWithError((what + ": cannot seek").c_str());
      return;
    }
    while (source.Grab().ok()) {
      StatusOr<Frame> frame = source.Retrieve();
      if (!frame.ok()) {
        state.SkipWithError(frame.status().ToString().c_str());
        return;
      }
      benchmark::DoNotOptimize(&*frame);
      ++frames;
    }
  }
  state.SetItemsProcessed(frames);
}

void BM_ReadTumFolder(benchmark::State& state) {
  TumRgbdSource source(DataPath("tum_fr1_desk"));
  ReadAll(state, source, "tum_fr1_desk");
}
BENCHMARK(BM_ReadTumFolder)->Unit(benchmark::kMillisecond);

void BM_ReadTumBag(benchmark::State& state) {
  BagSource source(DataPath("rosbags/tum_fr1_desk.bag"));
  ReadAll(state, source, "rosbags/tum_fr1_desk.bag");
}
BENCHMARK(BM_ReadTumBag)->Unit(benchmark::kMillisecond);

// Opening the bag: the record-layout check (every record, and every record inside every chunk,
// read once) and rosbag's index. Paid once per open, not per frame.
void BM_OpenTumBag(benchmark::State& state) {
  for (auto _ : state) {
    BagSource source(DataPath("rosbags/tum_fr1_desk.bag"));
    if (Status opened = source.Open(); !opened.ok()) {
      state.SkipWithError(opened.ToString().c_str());
      return;
    }
  }
}
BENCHMARK(BM_OpenTumBag)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace sightline
