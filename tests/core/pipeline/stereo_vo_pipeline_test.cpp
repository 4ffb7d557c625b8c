// The stereo-vo pipeline as one object: run headless through the registry's loop on kitti_clip1
// (its files and figures), and the object the GUI runs honouring stereo.calibration_file and
// stereo.gt_tolerance_s.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <opencv2/core.hpp>
#include <sstream>

#include "core/io/dataset.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/pipeline/stereo_vo_result.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using testing::ReadAll;

const TimingSummary* Stage(const RunMetrics& metrics, const std::string& stage) {
  for (const auto& [name, summary] : metrics.timing_ms) {
    if (name == stage) return &summary;
  }
  return nullptr;
}

double Figure(const std::vector<std::pair<std::string, double>>& figures, const std::string& key) {
  for (const auto& [name, value] : figures) {
    if (name == key) return value;
  }
  ADD_FAILURE() << key << " missing";
  return 0;
}

// The first `n` ground-truth poses of kitti_clip1.
Trajectory TruthPrefix(const std::string& dir, size_t n) {
  StatusOr<std::unique_ptr<Source>> source = OpenDataset(dir, SourceKind::kStereo);
  EXPECT_TRUE(source.ok());
  Trajectory truth;
  if (!source.ok() || (*source)->ground_truth() == nullptr) return truth;
  const std::vector<TimedPose>& poses = (*source)->ground_truth()->poses();
  for (size_t i = 0; i < std::min(n, poses.size()); ++i) truth.mutable_poses().push_back(poses[i]);
  return truth;
}

TEST(StereoVoPipeline, RunsHeadlessOnKittiThroughTheRegistry) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  constexpr int kFrames = 20;
  RunRequest request;
  request.pipeline = "stereo-vo";
  request.dataset_path = kitti;
  request.out_dir = testing::TempDir("stereo_vo_pipeline") + "/out";
  request.overrides = {"stereo.max_frames=" + std::to_string(kFrames)};
  StatusOr<RunReport> report = RunPipeline(BuiltinPipelines(), request);
  ASSERT_TRUE(report.ok()) << report.status().ToString();
  EXPECT_EQ(report->metrics.frames, kFrames);

  // frames.csv: today's columns in today's order, one row per frame.
  const std::string csv = ReadAll(request.out_dir + "/frames.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "frame,time_s,tracked,retracked,anchored,new_features,stereo_matches,correspondences,"
            "inliers,ransac_iterations,rigidity_failures,residual_px,disparity_offset_px,"
            "window_points,window_rms_px,translation_m,rotation_deg,gated,turn_searched,"
            "rectify_ms,pyramid_ms,"
            "tracking_ms,detection_ms,matching_ms,ransac_ms,refine_ms,window_ms,total_ms,status");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), kFrames + 1);
  const std::string trajectory = ReadAll(request.out_dir + "/trajectory.txt");
  size_t poses = 0;
  std::istringstream lines(trajectory);
  for (std::string line; std::getline(lines, line);) poses += (!line.empty() && line[0] != '#');
  EXPECT_EQ(poses, static_cast<size_t>(kFrames));

  // Timing: the odometry's stages as before, and "total" once per frame.
  for (const char* stage : {"read", "rectify", "tracking", "matching", "ransac", "refine"}) {
    EXPECT_NE(Stage(report->metrics, stage), nullptr) << stage;
  }
  ASSERT_EQ(report->metrics.timing_ms.back().first, "total");
  EXPECT_EQ(report->metrics.timing_ms.back().second.count, static_cast<size_t>(kFrames));
  ASSERT_NE(Stage(report->metrics, "rectify"), nullptr);
  EXPECT_EQ(Stage(report->metrics, "rectify")->count, static_cast<size_t>(kFrames));

  // The estimate follows the car: its length within 3 % of the ground truth's over these frames,
  // no frame gated, most stereo matches inliers.
  const double truth_m = TruthPrefix(kitti, kFrames).LengthM();
  ASSERT_GT(truth_m, 10.0);
  const auto& accuracy = report->result.accuracy;
  EXPECT_NEAR(Figure(accuracy, "estimated_length_m"), truth_m, 0.03 * truth_m);
  EXPECT_LT(Figure(accuracy, "ate_rmse_m"), 0.03 * truth_m);
  EXPECT_EQ(Figure(report->result.counts, "frames_gated"), 0);
  EXPECT_GT(Figure(report->result.counts, "inliers_per_frame"), 100);
}

// Drives the registry's stereo-vo object, as the GUI's worker does, over kitti_clip1's first
// `frames` frames with `overrides`, on `source` (kitti_clip1's info and ground truth, changed
// by the test).
struct Driven {
  Status status;  // Of Configure or Open.
  std::vector<std::shared_ptr<const StereoVoResult>> results;
  Trajectory Estimate() const {
    Trajectory t;
    for (const auto& r : results) t.Add(r->stamp.sensor_time_s, r->odometry->world_from_camera);
    return t;
  }
};

Driven Drive(const std::string& dir, const PipelineSource& source,
             const std::vector<std::string>& overrides, int frames,
             const std::vector<std::string>& after_open = {}) {
  Driven out;
  const PipelineInfo info = *BuiltinPipelines().Find("stereo-vo");
  OptionSet options;
  EXPECT_TRUE(info.declare_options(&options).ok());
  for (const std::string& o : overrides) EXPECT_TRUE(options.ApplyOverride(o).ok()) << o;
  std::unique_ptr<Pipeline> pipeline = info.create();
  out.status = pipeline->Configure(options);
  if (out.status.ok()) out.status = pipeline->Open(source);
  // Options changed once the source is open, as the GUI's parameter panel does.
  for (const std::string& o : after_open) EXPECT_TRUE(options.ApplyOverride(o).ok()) << o;
  if (out.status.ok() && !after_open.empty()) out.status = pipeline->Configure(options);
  if (!out.status.ok()) return out;
  StatusOr<std::unique_ptr<Source>> frames_source = OpenDataset(dir, SourceKind::kStereo);
  EXPECT_TRUE(frames_source.ok());
  for (int i = 0; i < frames && frames_source.ok() && (*frames_source)->Grab().ok(); ++i) {
    StatusOr<Frame> frame = (*frames_source)->Retrieve();
    EXPECT_TRUE(frame.ok());
    StatusOr<std::shared_ptr<const PipelineResult>> r = pipeline->Process(*frame);
    EXPECT_TRUE(r.ok()) << r.status().ToString();
    if (!r.ok()) break;
    out.results.push_back(std::dynamic_pointer_cast<const StereoVoResult>(*r));
    EXPECT_NE(out.results.back(), nullptr);
  }
  return out;
}

PipelineSource KittiSource(const std::string& dir) {
  StatusOr<std::unique_ptr<Source>> source = OpenDataset(dir, SourceKind::kStereo);
  EXPECT_TRUE(source.ok());
  return source.ok() ? PipelineSource::From(**source) : PipelineSource();
}

// An OpenCV stereo YAML (the layout `sightline-cli calibrate stereo` writes) for `rig`.
std::string WriteCalibration(const std::string& name, const StereoRig& rig) {
  const std::string path = testing::TempDir("stereo_vo_calibration") + "/" + name + ".yaml";
  cv::FileStorage fs(path, cv::FileStorage::WRITE);
  auto k = [](const PinholeCamera& c) -> cv::Mat {
    return (cv::Mat_<double>(3, 3) << c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1);
  };
  const Eigen::Vector3d t = rig.right_from_left.translation();
  fs << "image_width" << rig.left.width << "image_height" << rig.left.height;
  fs << "M1" << k(rig.left) << "D1" << cv::Mat::zeros(1, 5, CV_64F);
  fs << "M2" << k(rig.right) << "D2" << cv::Mat::zeros(1, 5, CV_64F);
  fs << "R" << cv::Mat::eye(3, 3, CV_64F) << "T" << (cv::Mat_<double>(3, 1) << t.x(), t.y(), t.z());
  return path;
}

TEST(StereoVoPipeline, TheGuiObjectHonoursTheCalibrationFile) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  constexpr int kFrames = 6;
  const PipelineSource kitti_source = KittiSource(kitti);
  ASSERT_TRUE(kitti_source.info.stereo.has_value());
  const Driven own = Drive(kitti, kitti_source, {}, kFrames);
  ASSERT_TRUE(own.status.ok()) << own.status.ToString();
  ASSERT_EQ(own.results.size(), static_cast<size_t>(kFrames));

  // Without the source's calibration and without the option: the error names the option.
  PipelineSource uncalibrated = kitti_source;
  uncalibrated.info.stereo.reset();
  Driven none = Drive(kitti, uncalibrated, {}, kFrames);
  EXPECT_EQ(none.status.code(), StatusCode::kFailedPrecondition);
  EXPECT_NE(none.status.message().find("stereo.calibration_file=FILE"), std::string::npos)
      << none.status.message();

  // The file's rig is the one used: twice the baseline, twice the distance travelled.
  StereoRig wide = *kitti_source.info.stereo;
  wide.right_from_left.translation() *= 2.0;
  const std::string file = WriteCalibration("wide", wide);
  const Driven from_file = Drive(kitti, uncalibrated, {"stereo.calibration_file=" + file}, kFrames);
  ASSERT_TRUE(from_file.status.ok()) << from_file.status.ToString();
  ASSERT_EQ(from_file.results.size(), static_cast<size_t>(kFrames));
  EXPECT_NEAR(from_file.Estimate().LengthM(), 2.0 * own.Estimate().LengthM(),
              0.05 * 2.0 * own.Estimate().LengthM());

  // Set while the source is open, the file replaces the source's rig at once.
  const Driven changed =
      Drive(kitti, kitti_source, {}, kFrames, {"stereo.calibration_file=" + file});
  ASSERT_TRUE(changed.status.ok()) << changed.status.ToString();
  ASSERT_EQ(changed.results.size(), static_cast<size_t>(kFrames));
  EXPECT_NEAR(changed.Estimate().LengthM(), from_file.Estimate().LengthM(),
              0.02 * from_file.Estimate().LengthM());

  // A file for another image size is refused, naming both sizes.
  StereoRig other = wide;
  other.left.width = other.right.width = 640;
  const Driven wrong =
      Drive(kitti, kitti_source,
            {"stereo.calibration_file=" + WriteCalibration("other_size", other)}, kFrames);
  EXPECT_EQ(wrong.status.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(wrong.status.message().find("640x"), std::string::npos) << wrong.status.message();
}

TEST(StereoVoPipeline, TheGuiObjectPairsGroundTruthWithinTheTolerance) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  constexpr int kFrames = 4;
  // The ground truth 30 ms late: outside the default 20 ms, inside 50 ms.
  PipelineSource late = KittiSource(kitti);
  ASSERT_NE(late.ground_truth, nullptr);
  Trajectory shifted = *late.ground_truth;
  for (TimedPose& p : shifted.mutable_poses()) p.time_s += 0.03;
  late.ground_truth = std::make_shared<const Trajectory>(shifted);

  const Driven strict = Drive(kitti, late, {}, kFrames);
  ASSERT_TRUE(strict.status.ok()) << strict.status.ToString();
  ASSERT_EQ(strict.results.size(), static_cast<size_t>(kFrames));
  for (const auto& r : strict.results) EXPECT_FALSE(r->ground_truth.has_value());

  const Driven loose = Drive(kitti, late, {"stereo.gt_tolerance_s=0.05"}, kFrames);
  ASSERT_TRUE(loose.status.ok()) << loose.status.ToString();
  ASSERT_EQ(loose.results.size(), static_cast<size_t>(kFrames));
  // Re-expressed relative to the first frame, as the estimate is: identity there, then the
  // true motion, which the estimate follows within 5 %.
  for (const auto& r : loose.results) ASSERT_TRUE(r->ground_truth.has_value());
  EXPECT_LT(loose.results.front()->ground_truth->translation().norm(), 1e-9);
  const Trajectory truth = TruthPrefix(kitti, kFrames);
  const double truth_m = truth.LengthM();
  ASSERT_GT(truth_m, 1.0);
  Trajectory drawn;
  for (const auto& r : loose.results) drawn.Add(r->stamp.sensor_time_s, *r->ground_truth);
  EXPECT_NEAR(drawn.LengthM(), truth_m, 1e-6 * truth_m);
  const Eigen::Vector3d end_truth = loose.results.back()->ground_truth->translation();
  const Eigen::Vector3d end_estimate =
      loose.results.back()->odometry->world_from_camera.translation();
  EXPECT_LT((end_truth - end_estimate).norm(), 0.05 * truth_m);
}

}  // namespace
}  // namespace sightline
