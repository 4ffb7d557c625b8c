#include "core/mapping/mapping_frame_processor.h"

#include <chrono>
#include <cstdio>

#include "core/mapping/option_check.h"

namespace sightline {

using mapping_internal::Invalid;

bool MappingOptions::IsValid(std::string* error) const {
  if (extractor != "multi_line_ransac" && extractor != "split_and_merge") {
    return Invalid(error, "mapping.extractor must be multi_line_ransac or split_and_merge");
  }
  if (pose_source != "auto" && pose_source != "recording" && pose_source != "rgbd" &&
      pose_source != "none") {
    return Invalid(error, "mapping.pose.source must be auto, recording, rgbd or none");
  }
  return odometry.IsValid(error) && floor.IsValid(error) && occupancy.IsValid(error) &&
         scan.IsValid(error) && ransac.IsValid(error) && split_merge.IsValid(error) &&
         rotation.IsValid(error) && stitch.IsValid(error) && people.IsValid(error);
}

OptionTable<MappingOptions> MappingOptions::Describe() {
  using O = MappingOptions;
  return OptionTable<O>("")
      .Choice("mapping.extractor", &O::extractor, {"multi_line_ransac", "split_and_merge"},
              "Wall-line extractor: the published multi-line RANSAC or split-and-merge.")
      .Nested(&O::floor, FloorPlaneOptions::Describe())
      .Nested(&O::occupancy, OccupancyImageOptions::Describe())
      .Nested(&O::scan, PolarScanOptions::Describe())
      .Nested(&O::ransac, MultiLineRansacOptions::Describe())
      .Nested(&O::split_merge, SplitAndMergeOptions::Describe())
      .Nested(&O::rotation, ManhattanRotationOptions::Describe())
      .Nested(&O::stitch, OccupancyGridMapOptions::Describe())
      .Nested(&O::people, PersonDetectorOptions::Describe())
      .Choice("mapping.pose.source", &O::pose_source, {"auto", "recording", "rgbd", "none"},
              "Where the robot's translation comes from: the recording's odometry "
              "(odometry.txt, a bag's odometry or tf, a live source's), RGB-D odometry on the "
              "depth and colour frames, none (heading from the walls only), or auto (the "
              "recording's odometry when it has one, else RGB-D odometry when the frames have "
              "colour or the method is icp, else none).")
      .Nested(&O::odometry, RgbdOdometryOptions::Describe());
}

namespace {

// Milliseconds since `start`.
double MsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

MappingFrameProcessor::MappingFrameProcessor(MappingOptions options)
    : options_(std::move(options)),
      occupancy_(options_.occupancy),
      scanner_(options_.scan),
      depth_people_(options_.people),
      rotation_(options_.rotation),
      visual_odometry_(options_.odometry),
      map_(options_.stitch) {
  if (options_.extractor == "split_and_merge") {
    extractor_ = std::make_unique<SplitAndMerge>(options_.split_merge);
  } else {
    extractor_ = std::make_unique<MultiLineRansac>(options_.ransac);
  }
}

MappingFrameProcessor::~MappingFrameProcessor() = default;

StatusOr<std::vector<PersonBox>> MappingFrameProcessor::HogPeople(const cv::Mat& color) {
  if (!detector_) detector_ = std::make_unique<HogPersonDetector>(options_.people);
  return detector_->Detect(color);
}

void MappingFrameProcessor::CheckWithHog(const cv::Mat& color, const cv::Size& depth_size,
                                         std::vector<PersonBox>* people) {
  if (!detector_) detector_ = std::make_unique<HogPersonDetector>(options_.people);
  // A box within one depth sample of the border is cut off by it.
  const double margin =
      std::max(2.0, static_cast<double>(depth_size.width) / options_.people.depth_target_columns);
  std::vector<PersonBox> kept;
  for (const PersonBox& p : *people) {
    const cv::Rect2d& b = p.box;
    const bool cut = b.x < margin || b.y < margin || b.br().x > depth_size.width - margin ||
                     b.br().y > depth_size.height - margin;
    // Where the depth cluster's head and feet are in view, HOG is asked about the whole body
    // from the floor to the head (the cluster's box misses what the depth lost: far legs, an
    // arm), otherwise about the part in view.
    const cv::Rect2d& asked = p.body.empty() ? b : p.body;
    const cv::Point2d s = p.ScaleTo(color.size());
    const double score = detector_->Score(
        color, cv::Rect2d(asked.x * s.x, asked.y * s.y, asked.width * s.x, asked.height * s.y));
    const double needed =
        cut ? options_.people.depth_hog_min_score_cut : options_.people.depth_hog_min_score;
    if (score >= needed) kept.push_back(p);
  }
  *people = std::move(kept);
}

Status MappingFrameProcessor::Configure(const FloorPlane& floor, const PinholeCamera& camera) {
  configured_ = false;
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  SIGHTLINE_RETURN_IF_ERROR(occupancy_.Configure(floor, camera));
  SIGHTLINE_RETURN_IF_ERROR(depth_people_.Configure(floor, camera));
  SIGHTLINE_RETURN_IF_ERROR(visual_odometry_.Configure(camera));
  SIGHTLINE_RETURN_IF_ERROR(scanner_.Configure(
      options_.occupancy.width_cells, options_.occupancy.height_cells,
      options_.occupancy.cell_size_m, occupancy_.fov_min_rad(), occupancy_.fov_max_rad()));
  base_from_camera_ = Eigen::Isometry3d::Identity();
  base_from_camera_.linear() = occupancy_.base_from_camera_rotation();
  base_from_camera_.translation() = Eigen::Vector3d(0, 0, floor.CameraHeightM());
  configured_ = true;
  Restart();
  return Status::Ok();
}

void MappingFrameProcessor::Restart() {
  rotation_.Restart(0);
  odometry_.Reset();
  visual_odometry_.Reset();
  active_pose_source_.clear();
  odometry_log_.clear();
  map_.Clear();
  pose_ = Pose2d();
  trajectory_.clear();
  times_.clear();
  camera_poses_.clear();
  reset_log_.clear();
  frames_ = 0;
}

StatusOr<bool> MappingFrameProcessor::SourcePose(const MappingInput& input,
                                                 MappingFrameResult* result,
                                                 std::optional<Pose2d>* world_from_base) {
  if (active_pose_source_.empty()) {
    const std::string& wanted = options_.pose_source;
    // auto: the recording's odometry, else RGB-D odometry when the frames can feed it (colour,
    // or depth alone for icp), else none.
    const bool can_track = !input.color.empty() || options_.odometry.method == "icp";
    active_pose_source_ = wanted != "auto"             ? wanted
                          : input.odometry.has_value() ? "recording"
                          : can_track                  ? "rgbd"
                                                       : "none";
  }
  result->pose_source = active_pose_source_;
  world_from_base->reset();
  if (active_pose_source_ == "recording") *world_from_base = input.odometry;
  if (active_pose_source_ != "rgbd") return true;
  // People move: their boxes (scaled to the depth image) are left out of the alignment.
  std::vector<cv::Rect> moving;
  for (const PersonBox& p : result->people) {
    if (p.image_size.width <= 0 || p.image_size.height <= 0) continue;
    const cv::Point2d s = p.ScaleTo(input.depth_m.size());
    moving.emplace_back(
        cv::Rect2d(p.box.x * s.x, p.box.y * s.y, p.box.width * s.x, p.box.height * s.y));
  }
  const auto start = std::chrono::steady_clock::now();
  StatusOr<RgbdOdometryStep> step =
      visual_odometry_.Track(input.stamp, input.depth_m, input.color, moving);
  result->times.odometry_ms = MsSince(start);
  if (!step.ok()) return step.status();
  if (step->ok) {
    *world_from_base = FloorPoseOfCamera(base_from_camera_, step->world_from_camera);
    return true;
  }
  result->odometry_failure = step->failure;
  char text[64];
  std::snprintf(text, sizeof(text),
                "frame %lld (t = %.3f s): ", static_cast<long long>(input.stamp.sequence_id),
                input.stamp.sensor_time_s);
  odometry_log_.push_back(text + step->failure);
  return false;
}

StatusOr<std::shared_ptr<const MappingFrameResult>> MappingFrameProcessor::Process(
    const MappingInput& input, TimingStats* timing) {
  if (!configured_) return FailedPrecondition("mapping: Configure() was not called");
  if (!input.depth_m.empty() && input.depth_m.type() != CV_32FC1) {
    return InvalidArgument("mapping: depth must be CV_32FC1 metres (NaN = invalid)");
  }
  auto result = std::make_shared<MappingFrameResult>();
  result->stamp = input.stamp;
  result->frame_index = frames_;
  MappingStageTimes& times = result->times;
  const auto frame_start = std::chrono::steady_clock::now();

  // People.
  const std::string& source = options_.people.source;
  const bool use_truth = (source == "ground_truth" || source == "auto") && input.people.has_value();
  const bool use_depth = source == "depth" || (source == "auto" && !input.people.has_value());
  if (use_truth) {
    result->people = *input.people;
    result->people_source = "ground truth";
  } else if (use_depth || (source == "hog" && !input.color.empty())) {
    auto start = std::chrono::steady_clock::now();
    StatusOr<std::vector<PersonBox>> found =
        use_depth ? depth_people_.Detect(input.depth_m) : HogPeople(input.color);
    if (!found.ok()) return found.status();
    result->people = std::move(*found);
    result->people_source = use_depth ? "depth" : "hog";
    // HOG as the second cue when the colour image is registered to the depth image (the same
    // shape within 2 %).
    if (use_depth && options_.people.depth_hog_check && !input.color.empty() &&
        !input.depth_m.empty() &&
        std::abs(static_cast<double>(input.color.cols) * input.depth_m.rows /
                     (static_cast<double>(input.color.rows) * input.depth_m.cols) -
                 1.0) < 0.02) {
      if (!result->people.empty()) CheckWithHog(input.color, input.depth_m.size(), &result->people);
      result->people_source = "depth+hog";
    }
    times.people_ms = MsSince(start);
    if (timing) timing->Add("people", times.people_ms);
  } else {
    result->people_source = "none";
  }

  // Occupancy image.
  auto start = std::chrono::steady_clock::now();
  StatusOr<OccupancyImage> image = occupancy_.Build(input.depth_m, result->people);
  if (!image.ok()) return image.status();
  result->occupancy = std::move(*image);
  times.occupancy_ms = MsSince(start);

  // Polar scan.
  start = std::chrono::steady_clock::now();
  StatusOr<PolarScan> scan = scanner_.Scan(result->occupancy);
  if (!scan.ok()) return scan.status();
  result->scan = std::move(*scan);
  times.scan_ms = MsSince(start);

  // Wall lines.
  start = std::chrono::steady_clock::now();
  StatusOr<LineExtraction> lines = extractor_->Extract(result->scan);
  if (!lines.ok()) return lines.status();
  result->lines = std::move(*lines);
  times.lines_ms = MsSince(start);

  // Pose source: a failed RGB-D odometry step holds the position (no increment; the next
  // tracked frame's increment spans the gap) and the frame is not stitched.
  std::optional<Pose2d> source_pose;
  StatusOr<bool> tracked = SourcePose(input, result.get(), &source_pose);
  if (!tracked.ok()) return tracked.status();

  // Rotation and dead reckoning.
  start = std::chrono::steady_clock::now();
  if (frames_ == 0 && source_pose) {
    pose_ = *source_pose;  // The estimate lives in the pose source's world frame.
    rotation_.Restart(pose_.heading_rad);
  }
  const OdometryIncrement step = *tracked ? odometry_.Update(source_pose) : OdometryIncrement();
  const double previous_heading = pose_.heading_rad;
  result->rotation = rotation_.Update(result->lines.lines, step);
  rotation_.Classify(result->rotation, &result->lines.lines);
  if (step.valid) {
    const double c = std::cos(previous_heading), s = std::sin(previous_heading);
    const Eigen::Vector2d& d = step.translation_in_previous_base;
    pose_.x += c * d.x() - s * d.y();
    pose_.y += s * d.x() + c * d.y();
  }
  pose_.heading_rad = result->rotation.heading_rad;
  result->pose = pose_;
  result->world_from_camera = pose_.ToIsometry() * base_from_camera_;
  times.rotation_ms = MsSince(start);

  // Map stitching.
  start = std::chrono::steady_clock::now();
  if (result->rotation.reset) {
    result->reset = true;
    char text[64];
    std::snprintf(text, sizeof(text), "frame %lld (t = %.3f s): ", static_cast<long long>(frames_),
                  input.stamp.sensor_time_s);
    reset_log_.push_back(text + result->rotation.reset_reason);
    if (options_.stitch.clear_on_reset) {
      map_.Clear();
      result->map_cleared = true;
    }
  }
  if (*tracked) SIGHTLINE_RETURN_IF_ERROR(map_.Insert(result->occupancy, pose_, &result->scan));
  times.stitch_ms = MsSince(start);

  trajectory_.push_back(pose_);
  times_.push_back(input.stamp.sensor_time_s);
  camera_poses_.push_back(result->world_from_camera);
  if (options_.stitch.render_every_n > 0 && frames_ % options_.stitch.render_every_n == 0 &&
      !map_.empty()) {
    result->map_image = std::make_shared<const cv::Mat>(map_.RenderBgr(trajectory_));
    result->map_gray = std::make_shared<const cv::Mat>(map_.RenderGray());
    result->map_occupied_threshold = map_.options().occupied_threshold;
    result->map_free_threshold = map_.options().free_threshold;
    result->map_origin = map_.origin();
    result->map_resolution_m = map_.resolution_m();
    result->trajectory = std::make_shared<const std::vector<Pose2d>>(trajectory_);
  }

  // What was degenerate, for people.
  const OccupancyImage& occ = result->occupancy;
  const int valid = occ.sampled_pixels - occ.invalid_pixels;
  if (input.depth_m.empty()) {
    result->status = "no depth";
  } else if (valid == 0) {
    result->status = "no valid depth";
  } else if (!*tracked) {
    result->status = "odometry failed";
  } else if (occ.person_pixels > occ.occupied_pixels && occ.person_pixels > valid / 4) {
    result->status = "view blocked by people";
  } else if (occ.floor_pixels == 0) {
    result->status = "no floor visible";
  } else if (result->lines.lines.empty()) {
    result->status = "no walls";
  } else {
    result->status = "ok";
  }
  times.total_ms = MsSince(frame_start);
  if (timing) {
    timing->Add("occupancy", times.occupancy_ms);
    timing->Add("scan", times.scan_ms);
    timing->Add("lines", times.lines_ms);
    if (result->pose_source == "rgbd") timing->Add("odometry", times.odometry_ms);
    timing->Add("rotation", times.rotation_ms);
    timing->Add("stitch", times.stitch_ms);
  }
  ++frames_;
  return std::shared_ptr<const MappingFrameResult>(std::move(result));
}

}  // namespace sightline
