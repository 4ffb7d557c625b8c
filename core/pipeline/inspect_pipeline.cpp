#include "core/pipeline/inspect_pipeline.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <opencv2/core.hpp>

#include "core/common/timing.h"

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

}  // namespace

const StatisticTable& InspectStatistics() {
  static const StatisticTable kTable = {
      {"inspect/check_ms", "ms", "Checking the frame's content."},
      {"inspect/valid_depth_fraction", "", "RGB-D: fraction of depth pixels in (0, max_depth_m]."},
      {"inspect/mean_intensity_left", "", "Stereo: mean grey value of the left image."},
      {"inspect/mean_intensity", "", "Mono: mean grey value."},
      {"inspect/finite_points", "count", "Cloud: points with finite coordinates."},
      {"inspect/has_gt", "", "1 when a ground-truth pose lies within gt_tolerance_s."},
  };
  return kTable;
}

InspectPipeline::InspectPipeline() = default;
InspectPipeline::~InspectPipeline() = default;

Status InspectPipeline::Configure(const OptionSet& options) {
  const InspectOptions parsed = options.Extract(InspectOptions::Describe());
  std::string error;
  if (!parsed.IsValid(&error)) return InvalidArgument(error);
  options_ = parsed;
  return Status::Ok();
}

Status InspectPipeline::Open(const PipelineSource& source) {
  ground_truth_ = source.ground_truth;
  Reset();
  return Status::Ok();
}

StatusOr<std::shared_ptr<const PipelineResult>> InspectPipeline::Process(const Frame& frame) {
  auto result = std::make_shared<PipelineResult>();
  result->stamp = StampOf(frame);
  const double start = HostTimeS();
  std::string what;
  const double value = CheckFrame(frame, options_, &what);
  const double check_ms = (HostTimeS() - start) * 1000.0;
  const bool has_gt = ground_truth_ != nullptr &&
                      ground_truth_->Nearest(result->stamp.sensor_time_s, options_.gt_tolerance_s);
  if (column_.empty()) column_ = what;
  char line[128];
  std::snprintf(line, sizeof(line), "%lld,%.6f,%.6g,%d\n",
                static_cast<long long>(result->stamp.sequence_id), result->stamp.sensor_time_s,
                value, has_gt ? 1 : 0);
  rows_ += line;
  ++frames_;
  with_gt_ += has_gt ? 1 : 0;
  result->stats = {{"inspect/check_ms", check_ms},
                   {"inspect/" + what, value},
                   {"inspect/has_gt", has_gt ? 1.0 : 0.0}};
  return std::shared_ptr<const PipelineResult>(std::move(result));
}

void InspectPipeline::Reset() {
  column_.clear();
  rows_.clear();
  frames_ = 0;
  with_gt_ = 0;
}

StatusOr<RunResult> InspectPipeline::Finish(const std::string& out_dir) {
  const std::string csv_path = out_dir + "/frames.csv";
  std::ofstream csv(csv_path);
  if (!csv) return NotFound("cannot write " + csv_path);
  if (frames_ > 0) csv << "frame,time_s," << column_ << ",has_gt\n" << rows_;
  csv.flush();
  if (!csv) return Unavailable("write to " + csv_path + " failed (disk full?)");
  RunResult result;
  result.frames = frames_;
  result.outputs.push_back("frames.csv");
  if (ground_truth_ != nullptr && frames_ > 0) {
    result.accuracy.emplace_back("gt_coverage", static_cast<double>(with_gt_) / frames_);
  }
  return result;
}

PipelineInfo InspectPipelineInfo() {
  PipelineInfo info;
  info.name = "inspect";
  info.title = "Inspect frames";
  info.summary = "read and check every frame of a dataset; time the decoding";
  info.declare_options = [](OptionSet* set) { return set->Declare(InspectOptions::Describe()); };
  info.create = [] { return std::unique_ptr<Pipeline>(std::make_unique<InspectPipeline>()); };
  return info;
}

}  // namespace sightline
