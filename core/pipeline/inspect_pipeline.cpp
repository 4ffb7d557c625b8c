#include "core/pipeline/inspect_pipeline.h"

#include <cmath>
#include <fstream>
#include <opencv2/core.hpp>

#include "core/common/timing.h"
#include "core/io/dataset.h"

namespace sightline {

bool InspectOptions::IsValid(std::string* error) const {
  if (max_frames < 0) {
    if (error) *error = "inspect.max_frames must be >= 0";
    return false;
  }
  if (!(max_depth_m > 0)) {
    if (error) *error = "inspect.max_depth_m must be positive";
    return false;
  }
  return true;
}

OptionTable<InspectOptions> InspectOptions::Describe() {
  return OptionTable<InspectOptions>("inspect")
      .Int("max_frames", &InspectOptions::max_frames, "frames", 0, 1e9, 1,
           "Frames to read; 0 reads the whole recording.")
      .Double("max_depth_m", &InspectOptions::max_depth_m, "m", 0.1, 100, 0.1,
              "Depth readings beyond this count as invalid.")
      .Double("gt_tolerance_s", &InspectOptions::gt_tolerance_s, "s", 0, 1, 0.005,
              "A frame has ground truth when a pose lies within this time.");
}

namespace {

// A number describing the frame's content: valid depth fraction, mean intensity or finite points.
double CheckFrame(const Frame& frame, const InspectOptions& options, std::string* what) {
  if (const auto* rgbd = std::get_if<RgbdFrame>(&frame)) {
    *what = "valid_depth_fraction";
    if (rgbd->depth_m.empty()) return 0;
    const cv::Mat valid = (rgbd->depth_m > 0) & (rgbd->depth_m <= options.max_depth_m);
    return static_cast<double>(cv::countNonZero(valid)) / rgbd->depth_m.total();
  }
  if (const auto* stereo = std::get_if<StereoFrame>(&frame)) {
    *what = "mean_intensity_left";
    return stereo->left.empty() ? 0 : cv::mean(stereo->left)[0];
  }
  if (const auto* mono = std::get_if<MonoFrame>(&frame)) {
    *what = "mean_intensity";
    return mono->image.empty() ? 0 : cv::mean(mono->image)[0];
  }
  const auto& cloud = std::get<CloudFrame>(frame);
  *what = "finite_points";
  size_t finite = 0;
  if (cloud.cloud) {
    for (const auto& p : cloud.cloud->points) finite += p.allFinite() ? 1 : 0;
  }
  return static_cast<double>(finite);
}

StatusOr<RunResult> RunInspect(const RunContext& context) {
  const InspectOptions options = context.options.Extract(InspectOptions::Describe());
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);

  StatusOr<std::unique_ptr<Source>> opened = OpenDataset(context.dataset_path);
  if (!opened.ok()) return opened.status();
  Source& source = **opened;
  const Trajectory* gt = source.ground_truth();
  int64_t total = source.info().frame_count;
  if (options.max_frames > 0 && (total < 0 || total > options.max_frames)) {
    total = options.max_frames;
  }

  const std::string csv_path = context.out_dir + "/frames.csv";
  std::ofstream csv(csv_path);
  if (!csv) return NotFound("cannot write " + csv_path);

  RunResult result;
  result.dataset_format = source.info().format;
  int64_t with_gt = 0;
  bool header_written = false;
  while (total < 0 || result.frames < total) {
    if (context.Cancelled())
      return Cancelled("run cancelled after " + std::to_string(result.frames) + " frames");
    ScopedTimer frame_timer(context.timing, "total");
    StatusOr<Frame> frame = Internal("not read");
    {
      ScopedTimer t(context.timing, "read");
      Status grabbed = source.Grab();
      if (grabbed.code() == StatusCode::kOutOfRange) break;
      if (!grabbed.ok()) return grabbed;
      frame = source.Retrieve();
    }
    if (!frame.ok()) return frame.status();
    std::string what;
    double value = 0;
    {
      ScopedTimer t(context.timing, "check");
      value = CheckFrame(*frame, options, &what);
    }
    const FrameStamp& stamp = StampOf(*frame);
    const bool has_gt = gt != nullptr && gt->Nearest(stamp.sensor_time_s, options.gt_tolerance_s);
    with_gt += has_gt ? 1 : 0;
    if (!header_written) {
      csv << "frame,time_s," << what << ",has_gt\n";
      header_written = true;
    }
    char line[128];
    std::snprintf(line, sizeof(line), "%lld,%.6f,%.6g,%d\n",
                  static_cast<long long>(stamp.sequence_id), stamp.sensor_time_s, value,
                  has_gt ? 1 : 0);
    csv << line;
    ++result.frames;
    if (context.progress) context.progress(result.frames, total);
  }
  csv.flush();
  if (!csv) return Unavailable("write to " + csv_path + " failed (disk full?)");
  if (result.frames == 0) return OutOfRange(context.dataset_path + " holds no frames");
  result.outputs.push_back("frames.csv");
  if (gt != nullptr) {
    result.accuracy.emplace_back("gt_coverage", static_cast<double>(with_gt) / result.frames);
  }
  return result;
}

}  // namespace

PipelineInfo InspectPipeline() {
  PipelineInfo info;
  info.name = "inspect";
  info.summary = "read and check every frame of a dataset; time the decoding";
  info.declare_options = [](OptionSet* set) { return set->Declare(InspectOptions::Describe()); };
  info.run = RunInspect;
  return info;
}

}  // namespace sightline
