// Floor plane calibration (seed 000, section 4.3.2): a RANSAC plane fit on one or more depth
// frames or clouds. The plane model is core/common/floor.h; the file that stores it is
// core/io/floor_file.h.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/camera.h"
#include "core/common/floor.h"
#include "core/common/status.h"
#include "core/mapping/floor_types.h"
#include "core/options/option_table.h"

namespace sightline {

// Fits the floor plane by MSAC (RANSAC scored by the truncated squared distance) with a
// least-squares refit. Construct once, call Fit as often as needed (deterministic per call).
//
//   FloorPlaneEstimator estimator(options);
//   std::vector<Eigen::Vector3f> points;
//   for (const auto& depth : frames) AppendDepthPoints(depth, camera, options.max_depth_m,
//   &points); StatusOr<FloorFitResult> fit = estimator.Fit(points);
class FloorPlaneEstimator {
 public:
  explicit FloorPlaneEstimator(FloorPlaneOptions options = {}) : options_(std::move(options)) {}

  // RANSAC with a least-squares refit on camera-frame points (NaN points are skipped). Fails
  // with a clear message when there are too few valid points or no plane passes the floor tests
  // (orientation, camera height, inlier ratio, lowest plane).
  StatusOr<FloorFitResult> Fit(const std::vector<Eigen::Vector3f>& points_in_camera) const;

  const FloorPlaneOptions& options() const { return options_; }

 private:
  FloorPlaneOptions options_;
};

// Appends the camera-frame points of a metric depth image (NaN / <= 0 / beyond max_depth_m
// skipped), sampling every `step`-th pixel.
void AppendDepthPoints(const cv::Mat& depth_m, const PinholeCamera& camera, double max_depth_m,
                       int step, std::vector<Eigen::Vector3f>* points);

// The floor calibration of a run, the one way Sightline calibrates the floor (the mapping
// pipeline on its first frames, `sightline-cli floor`): collects the points of frames (depth
// sampled every 2nd pixel, or clouds) and fits the plane on them.
//
//   FloorCalibrator calibrator(options.floor, 5);
//   for (...) calibrator.AddDepth(frame.depth_m, camera);   // Until calibrator.Full().
//   StatusOr<FloorCalibration> floor = calibrator.Calibrate(dataset_path);
class FloorCalibrator {
 public:
  FloorCalibrator(FloorPlaneOptions options, int frames)
      : estimator_(std::move(options)), wanted_(frames) {}

  // Adds the points of one depth image (metres) seen by `camera`.
  void AddDepth(const cv::Mat& depth_m, const PinholeCamera& camera);
  // Adds the points of one cloud (camera frame).
  void AddCloud(const std::vector<Eigen::Vector3f>& points);
  // Frames added, and whether they are as many as wanted.
  int frames() const { return frames_; }
  bool Full() const { return frames_ >= wanted_; }
  // Fits the floor on the frames so far.
  StatusOr<FloorFitResult> Fit() const;
  // ... as a calibration file's content naming `source`.
  StatusOr<FloorCalibration> Calibrate(const std::string& source) const;
  // Forgets the frames.
  void Clear();

 private:
  FloorPlaneEstimator estimator_;
  int wanted_ = 1;
  int frames_ = 0;
  std::vector<Eigen::Vector3f> points_;
};

}  // namespace sightline
