#include "core/mapping/rgbd_odometry.h"

#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <opencv2/rgbd.hpp>

#include "core/mapping/feature_motion.h"
#include "core/mapping/option_check.h"

namespace sightline {

using mapping_internal::Invalid;

bool RgbdOdometryOptions::IsValid(std::string* error) const {
  if (method != "rgbd" && method != "icp" && method != "rgbd_icp") {
    return Invalid(error, "mapping.pose.rgbd.method must be rgbd, icp or rgbd_icp");
  }
  if (!(min_depth_m >= 0 && max_depth_m > min_depth_m)) {
    return Invalid(error, "mapping.pose.rgbd.max_depth_m must exceed min_depth_m >= 0");
  }
  if (!(max_depth_diff_m > 0)) {
    return Invalid(error, "mapping.pose.rgbd.max_depth_diff_m must be positive");
  }
  if (pyramid_levels < 1 || pyramid_levels > 8) {
    return Invalid(error, "mapping.pose.rgbd.pyramid_levels must lie in [1, 8]");
  }
  if (iterations < 1) return Invalid(error, "mapping.pose.rgbd.iterations must be >= 1");
  if (!(max_points_part > 0 && max_points_part <= 1)) {
    return Invalid(error, "mapping.pose.rgbd.max_points_part must lie in (0, 1]");
  }
  if (!(min_valid_fraction >= 0 && min_valid_fraction <= 1)) {
    return Invalid(error, "mapping.pose.rgbd.min_valid_fraction must lie in [0, 1]");
  }
  if (!(min_gray_stddev >= 0)) {
    return Invalid(error, "mapping.pose.rgbd.min_gray_stddev must be >= 0");
  }
  if (!(max_speed_mps > 0 && max_turn_rate_deg_s > 0 && max_gap_s > 0)) {
    return Invalid(error,
                   "mapping.pose.rgbd.max_speed_mps, max_turn_rate_deg_s and max_gap_s must be "
                   "positive");
  }
  if (max_features < 10 || min_feature_inliers < 4) {
    return Invalid(error,
                   "mapping.pose.rgbd.max_features must be >= 10 and "
                   "min_feature_inliers >= 4");
  }
  if (!(keyframe_translation_m >= 0 && keyframe_rotation_deg >= 0)) {
    return Invalid(error, "mapping.pose.rgbd.keyframe_* must be >= 0");
  }
  return true;
}

OptionTable<RgbdOdometryOptions> RgbdOdometryOptions::Describe() {
  using O = RgbdOdometryOptions;
  return OptionTable<O>("mapping.pose.rgbd")
      .Choice("method", &O::method, {"rgbd", "icp", "rgbd_icp"},
              "RGB-D odometry: rgbd aligns brightness and depth (needs registered colour), icp "
              "aligns depth surfaces only (point-to-plane), rgbd_icp uses both.")
      .Double("min_depth_m", &O::min_depth_m, "m", 0, 10, 0.05,
              "Depth readings nearer than this are not used by the odometry.")
      .Double("max_depth_m", &O::max_depth_m, "m", 0.1, 20, 0.1,
              "Depth readings farther than this are not used by the odometry.")
      .Double("max_depth_diff_m", &O::max_depth_diff_m, "m", 0.001, 1, 0.005,
              "Odometry correspondences farther apart than this in depth are rejected.")
      .Int("pyramid_levels", &O::pyramid_levels, "levels", 1, 8, 1,
           "Image pyramid levels of the odometry (coarse to fine; more handle larger steps).")
      .Int("iterations", &O::iterations, "", 1, 100, 1, "Odometry iterations per pyramid level.")
      .Double("max_points_part", &O::max_points_part, "", 0.001, 1, 0.01,
              "Fraction of the pixels the odometry uses per pyramid level.")
      .Double("min_valid_fraction", &O::min_valid_fraction, "", 0, 1, 0.01,
              "A frame with a smaller fraction of depth pixels in range is not tracked (the "
              "pose is held).")
      .Double("min_gray_stddev", &O::min_gray_stddev, "grey levels", 0, 100, 0.5,
              "rgbd, rgbd_icp: a colour frame whose brightness varies less than this is not "
              "tracked (a black or blank frame).")
      .Double("max_speed_mps", &O::max_speed_mps, "m/s", 0.01, 100, 0.1,
              "An odometry step faster than this (sensor time) is rejected.")
      .Double("max_turn_rate_deg_s", &O::max_turn_rate_deg_s, "deg/s", 1, 10000, 10,
              "An odometry step turning faster than this (sensor time) is rejected.")
      .Double("max_gap_s", &O::max_gap_s, "s", 0.001, 100, 0.1,
              "Frames farther apart in sensor time are not aligned; tracking starts again "
              "from the held pose.")
      .Bool("constant_velocity", &O::constant_velocity,
            "Start each alignment from the last motion scaled by the time between frames.")
      .Bool("feature_guess", &O::feature_guess,
            "rgbd, rgbd_icp: start the alignment from ORB features matched with PnP RANSAC "
            "when they agree (fast turns at low frame rates).")
      .Int("max_features", &O::max_features, "features", 10, 10000, 50,
           "ORB features per frame for the feature guess.")
      .Int("min_feature_inliers", &O::min_feature_inliers, "features", 4, 1000, 1,
           "PnP inliers the feature guess needs to be used.")
      .Double("keyframe_translation_m", &O::keyframe_translation_m, "m", 0, 10, 0.01,
              "A frame becomes the odometry's reference when it moved this far from the last "
              "one (0 with keyframe_rotation_deg 0: every frame).")
      .Double("keyframe_rotation_deg", &O::keyframe_rotation_deg, "deg", 0, 180, 1,
              "... or turned this much.");
}

namespace {

Eigen::Isometry3d FromCv(const cv::Mat& rt) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) t.linear()(r, c) = rt.at<double>(r, c);
    t.translation()(r) = rt.at<double>(r, 3);
  }
  return t;
}

cv::Mat ToCv(const Eigen::Isometry3d& t) {
  cv::Mat rt = cv::Mat::eye(4, 4, CV_64FC1);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) rt.at<double>(r, c) = t.linear()(r, c);
    rt.at<double>(r, 3) = t.translation()(r);
  }
  return rt;
}

double AngleDeg(const Eigen::Isometry3d& t) {
  return RadToDeg(Eigen::AngleAxisd(t.linear()).angle());
}

// The motion `step` that took `from_dt_s` stretched to `to_dt_s` (constant velocity).
Eigen::Isometry3d ScaleMotion(const Eigen::Isometry3d& step, double from_dt_s, double to_dt_s) {
  const double k = from_dt_s > 0 ? to_dt_s / from_dt_s : 1.0;
  Eigen::AngleAxisd rotation(step.linear());
  Eigen::Isometry3d scaled = Eigen::Isometry3d::Identity();
  scaled.linear() = Eigen::AngleAxisd(rotation.angle() * k, rotation.axis()).toRotationMatrix();
  scaled.translation() = step.translation() * k;
  return scaled;
}

std::string Format(const char* format, double a, double b = 0, double c = 0) {
  char text[200];
  std::snprintf(text, sizeof(text), format, a, b, c);
  return text;
}

// Lifts OpenCV's own limits on one step (0.15 m, 15 deg by default).
template <typename T>
void Unlimited(T* odometry) {
  odometry->setMaxTranslation(1e3);
  odometry->setMaxRotation(180);
}

}  // namespace

struct RgbdOdometry::Impl {
  PinholeCamera camera;
  cv::Size size;  // Depth size the odometry object was made for.
  cv::Ptr<cv::rgbd::Odometry> odometry;
  cv::Ptr<cv::rgbd::OdometryFrame> keyframe;  // The reference of the next alignment.
  std::unique_ptr<FeatureMotion> features;    // With feature_guess and colour.
  FeatureFrame keyframe_features;
  Eigen::Isometry3d world_from_keyframe = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d keyframe_from_last = Eigen::Isometry3d::Identity();  // Last tracked frame.
  double last_time_s = 0;
  Eigen::Isometry3d last_step = Eigen::Isometry3d::Identity();  // previous_from_current.
  double last_step_dt_s = 0;                                    // 0 = no velocity yet.
  Eigen::Isometry3d held = Eigen::Isometry3d::Identity();       // Last tracked world_from_camera.
  bool tracking = false;

  // Aligns the keyframe with `frame` from the guess keyframe_from_current; "" or why it failed.
  std::string Align(const RgbdOdometryOptions& o, cv::Ptr<cv::rgbd::OdometryFrame>& frame,
                    const Eigen::Isometry3d& guess, double gap_s,
                    Eigen::Isometry3d* keyframe_from_current) {
    cv::Mat current_from_keyframe;
    bool aligned = false;
    try {
      aligned = odometry->compute(keyframe, frame, current_from_keyframe, ToCv(guess.inverse()));
    } catch (const cv::Exception& e) {
      return std::string("alignment failed: ") + e.what();
    }
    if (!aligned || current_from_keyframe.empty()) {
      return "alignment failed (too few correspondences or no convergence)";
    }
    *keyframe_from_current = FromCv(current_from_keyframe).inverse();
    if (!keyframe_from_current->matrix().allFinite()) return "alignment diverged (not finite)";
    const Eigen::Isometry3d last_from_current =
        keyframe_from_last.inverse() * *keyframe_from_current;
    const double speed = last_from_current.translation().norm() / gap_s;
    const double turn_rate = AngleDeg(last_from_current) / gap_s;
    if (speed > o.max_speed_mps || turn_rate > o.max_turn_rate_deg_s) {
      return Format(
          "implausible step: %.2f m/s, %.0f deg/s over %.3f s (max_speed_mps, "
          "max_turn_rate_deg_s)",
          speed, turn_rate, gap_s);
    }
    return "";
  }

  // The OpenCV odometry for depth frames of `depth_size`.
  void Make(const RgbdOdometryOptions& o, cv::Size depth_size) {
    const PinholeCamera c = camera.Scaled(depth_size.width, depth_size.height);
    cv::Mat k = (cv::Mat_<float>(3, 3) << c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1);
    const std::vector<int> iterations(o.pyramid_levels, o.iterations);
    const float min_d = static_cast<float>(o.min_depth_m),
                max_d = static_cast<float>(o.max_depth_m);
    const float diff = static_cast<float>(o.max_depth_diff_m);
    const float part = static_cast<float>(o.max_points_part);
    // Plausibility is judged in Track on sensor time, not by OpenCV's per-step limits.
    if (o.method == "icp") {
      auto icp = cv::rgbd::ICPOdometry::create(k, min_d, max_d, diff, part, iterations);
      Unlimited(icp.get());
      odometry = icp;
    } else {
      const std::vector<float> gradients(o.pyramid_levels, 10.f);  // OpenCV's default.
      if (o.method == "rgbd") {
        auto rgbd =
            cv::rgbd::RgbdOdometry::create(k, min_d, max_d, diff, iterations, gradients, part);
        Unlimited(rgbd.get());
        odometry = rgbd;
      } else {
        auto both =
            cv::rgbd::RgbdICPOdometry::create(k, min_d, max_d, diff, part, iterations, gradients);
        Unlimited(both.get());
        odometry = both;
      }
    }
    if (o.feature_guess && o.method != "icp") {
      features = std::make_unique<FeatureMotion>(o.max_features, o.min_feature_inliers);
    }
    size = depth_size;
    keyframe.release();
    tracking = false;
  }
};

RgbdOdometry::RgbdOdometry(RgbdOdometryOptions options)
    : options_(std::move(options)), impl_(std::make_unique<Impl>()) {}

RgbdOdometry::~RgbdOdometry() = default;

Status RgbdOdometry::Configure(const PinholeCamera& camera) {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  SIGHTLINE_RETURN_IF_ERROR(camera.Validate());
  impl_ = std::make_unique<Impl>();
  impl_->camera = camera;
  Reset();
  return Status::Ok();
}

void RgbdOdometry::Reset() {
  const PinholeCamera camera = impl_->camera;
  impl_ = std::make_unique<Impl>();
  impl_->camera = camera;
  failures_ = 0;
}

StatusOr<RgbdOdometryStep> RgbdOdometry::Track(const FrameStamp& stamp, const cv::Mat& depth_m,
                                               const cv::Mat& color,
                                               const std::vector<cv::Rect>& moving) {
  Impl& s = *impl_;
  if (s.camera.width <= 0) return FailedPrecondition("rgbd odometry: Configure() was not called");
  if (!depth_m.empty() && depth_m.type() != CV_32FC1) {
    return InvalidArgument("rgbd odometry: depth must be CV_32FC1 metres");
  }
  if (!color.empty() && color.type() != CV_8UC3 && color.type() != CV_8UC1) {
    return InvalidArgument("rgbd odometry: colour must be CV_8UC3 (BGR) or CV_8UC1");
  }
  RgbdOdometryStep step;
  step.world_from_camera = s.held;
  auto fail = [&](std::string why) {
    ++failures_;
    step.ok = false;
    step.failure = std::move(why);
    return step;
  };
  if (depth_m.empty()) return fail("no depth image");

  // Depth in range (NaN and 0 are none) and the mask of the pixels used.
  const bool wants_color = options_.method != "icp";
  cv::Mat depth = depth_m.clone();
  cv::patchNaNs(depth, 0.0);
  cv::Mat mask = (depth >= options_.min_depth_m) & (depth <= options_.max_depth_m);
  for (const cv::Rect& box : moving) mask(box & cv::Rect(0, 0, mask.cols, mask.rows)).setTo(0);
  step.valid_fraction = static_cast<double>(cv::countNonZero(mask)) / mask.total();
  if (step.valid_fraction < options_.min_valid_fraction) {
    return fail(
        Format("%.1f %% of the depth pixels in range, fewer than min_valid_fraction %.1f %%",
               100 * step.valid_fraction, 100 * options_.min_valid_fraction));
  }
  cv::Mat gray;
  if (wants_color) {
    if (color.empty()) return fail("no colour image (method " + options_.method + " needs one)");
    if (color.channels() == 3) {
      cv::cvtColor(color, gray, cv::COLOR_BGR2GRAY);
    } else {
      gray = color.clone();
    }
    if (gray.size() != depth.size()) cv::resize(gray, gray, depth.size(), 0, 0, cv::INTER_AREA);
    cv::Scalar mean, stddev;
    cv::meanStdDev(gray, mean, stddev, mask);
    if (stddev[0] < options_.min_gray_stddev) {
      return fail(Format("blank colour image (brightness spread %.1f < min_gray_stddev %.1f)",
                         stddev[0], options_.min_gray_stddev));
    }
  }
  if (!s.odometry || s.size != depth.size()) s.Make(options_, depth.size());
  cv::Ptr<cv::rgbd::OdometryFrame> frame = cv::rgbd::OdometryFrame::create(
      gray, depth, mask, cv::Mat(), static_cast<int>(stamp.sequence_id));
  const double t = stamp.sensor_time_s;
  FeatureFrame current_features;
  if (s.features) current_features = s.features->Detect(gray, depth, mask);

  // The first usable frame, or the first after a gap: the reference, at the held pose.
  const double gap_s = t - s.last_time_s;
  if (!s.tracking || gap_s > options_.max_gap_s) {
    s.odometry->prepareFrameCache(frame, cv::rgbd::OdometryFrame::CACHE_ALL);
    const bool restarted = s.tracking;
    s.keyframe = frame;
    s.keyframe_features = std::move(current_features);
    s.last_time_s = t;
    s.world_from_keyframe = s.held;
    s.keyframe_from_last = Eigen::Isometry3d::Identity();
    s.last_step_dt_s = 0;
    s.tracking = true;
    step.keyframe = true;
    if (!restarted) {
      step.ok = step.first = true;
      return step;
    }
    step.restarted = true;
    return fail(
        Format("%.2f s since the last tracked frame (max_gap_s %.2f s): tracking starts "
               "again here, the motion in between is lost",
               gap_s, options_.max_gap_s));
  }
  if (!(gap_s > 0)) return fail(Format("time %.6f s is not after the last tracked frame", t));

  // Align the keyframe with this frame. Guesses in order: the features' motion (when enough of
  // them agree on one: fast turns), the constant-velocity prediction, no motion since the last
  // frame (the motion changed). The first that aligns plausibly is taken.
  s.odometry->prepareFrameCache(frame, cv::rgbd::OdometryFrame::CACHE_ALL);
  std::vector<Eigen::Isometry3d> guesses;
  if (s.features) {
    int inliers = 0;
    const PinholeCamera scaled = s.camera.Scaled(depth.cols, depth.rows);
    if (auto current_from_keyframe =
            s.features->Estimate(s.keyframe_features, current_features, scaled, &inliers)) {
      guesses.push_back(current_from_keyframe->inverse());
    }
  }
  if (options_.constant_velocity && s.last_step_dt_s > 0) {
    guesses.push_back(s.keyframe_from_last * ScaleMotion(s.last_step, s.last_step_dt_s, gap_s));
  }
  guesses.push_back(s.keyframe_from_last);
  Eigen::Isometry3d keyframe_from_current;
  std::string failure;
  for (const Eigen::Isometry3d& guess : guesses) {
    const std::string why = s.Align(options_, frame, guess, gap_s, &keyframe_from_current);
    if (why.empty()) {
      failure.clear();
      break;
    }
    if (failure.empty()) failure = why;
  }
  if (!failure.empty()) return fail(failure);
  const Eigen::Isometry3d last_from_current =
      s.keyframe_from_last.inverse() * keyframe_from_current;

  // Tracked.
  s.last_step = last_from_current;
  s.last_step_dt_s = gap_s;
  s.last_time_s = t;
  s.keyframe_from_last = keyframe_from_current;
  s.held = s.world_from_keyframe * keyframe_from_current;
  step.ok = true;
  step.world_from_camera = s.held;
  const bool every_frame =
      options_.keyframe_translation_m <= 0 && options_.keyframe_rotation_deg <= 0;
  if (every_frame ||
      (options_.keyframe_translation_m > 0 &&
       keyframe_from_current.translation().norm() >= options_.keyframe_translation_m) ||
      (options_.keyframe_rotation_deg > 0 &&
       AngleDeg(keyframe_from_current) >= options_.keyframe_rotation_deg)) {
    s.keyframe = frame;
    s.keyframe_features = std::move(current_features);
    s.world_from_keyframe = s.held;
    s.keyframe_from_last = Eigen::Isometry3d::Identity();
    step.keyframe = true;
  }
  return step;
}

Pose2d FloorPoseOfCamera(const Eigen::Isometry3d& base_from_camera,
                         const Eigen::Isometry3d& odometry_world_from_camera) {
  // The world is the base at the first frame: world_from_base = B * W_C * B^-1.
  const Eigen::Isometry3d world_from_base =
      base_from_camera * odometry_world_from_camera * base_from_camera.inverse();
  return Pose2d::FromIsometry(world_from_base);
}

}  // namespace sightline
