#include "core/mobility/mobility_mapper.h"

#include <chrono>
#include <cstdio>
#include <limits>

#include "core/common/depth_cloud.h"
#include "core/mobility/grid_normals.h"
#include "core/mobility/grid_stages.h"
#include "core/mobility/ground_plane.h"
#include "core/mobility/mobility_map.h"
#include "core/mobility/pcl_stages.h"
#include "core/mobility/region_growing.h"
#include "core/mobility/surface_properties.h"

namespace sightline {
namespace {

using Clock = std::chrono::steady_clock;

// Times one stage into result->stages with the points that entered it.
class StageClock {
 public:
  StageClock(MobilityResult* result, const char* name, size_t points)
      : result_(result), name_(name), points_(static_cast<int64_t>(points)), start_(Clock::now()) {}
  ~StageClock() {
    result_->stages.push_back(
        {name_, std::chrono::duration<double, std::milli>(Clock::now() - start_).count(), points_});
  }

 private:
  MobilityResult* result_;
  const char* name_;
  int64_t points_;
  Clock::time_point start_;
};

// Downsampling, range cut, denoising and normals of either mode; the k-d tree of the pcl mode
// is kept for the region growing.
Status PointStages(const PointCloud& cloud, const MobilityOptions& o, WorkingCloud* work,
                   std::unique_ptr<PclNeighborSearch>* search, MobilityResult* result) {
  const double range = o.RangeCutM();
  if (o.mode == "grid") {
    {
      StageClock t(result, "downsample", cloud.size());
      StatusOr<WorkingCloud> grid = GridDownsample(cloud, o.grid_stride);
      if (!grid.ok()) return grid.status();
      *work = std::move(*grid);
    }
    {
      StageClock t(result, "range_cut", work->size());
      RangeCut(range, work);
    }
  } else {
    {
      StageClock t(result, "range_cut", cloud.size());
      *work = CloudPoints(cloud);
      RangeCut(range, work);
    }
    {
      StageClock t(result, "downsample", work->size());
      PclVoxelDownsample(o.voxel_m, work);
    }
  }
  if (work->size() < static_cast<size_t>(o.min_points)) {
    char text[200];
    std::snprintf(text, sizeof(text),
                  "%zu point(s) left within the %.2f m range cut (at least %d needed; the cloud "
                  "has %zu points)",
                  work->size(), range, o.min_points, cloud.size());
    return OutOfRange(text);
  }
  if (o.mode == "grid") {
    {
      StageClock t(result, "denoise", work->size());
      GridRemoveOutliers(o.sor_alpha, work);
    }
    {
      StageClock t(result, "normals", work->size());
      GridNormals(o.normal_window, o.max_curvature, work);
    }
  } else {
    {
      StageClock t(result, "denoise", work->size());
      PclRemoveOutliers(o.sor_k, o.sor_alpha, work);
    }
    StageClock t(result, "normals", work->size());
    *search = std::make_unique<PclNeighborSearch>(work->points);
    (*search)->ComputeNormals(o.normal_k, o.max_curvature, work);
  }
  if (work->size() < 3) return OutOfRange("fewer than 3 points left after denoising");
  return Status::Ok();
}

// Gathers the points of each label into one vector per segment.
std::vector<std::vector<Eigen::Vector3f>> SegmentPoints(const WorkingCloud& work,
                                                        const std::vector<int>& label, int count) {
  std::vector<int> sizes(count, 0);
  for (int l : label) {
    if (l >= 0) ++sizes[l];
  }
  std::vector<std::vector<Eigen::Vector3f>> points(count);
  for (int s = 0; s < count; ++s) points[s].reserve(sizes[s]);
  for (size_t i = 0; i < label.size(); ++i) {
    if (label[i] >= 0) points[label[i]].push_back(work.points[i]);
  }
  return points;
}

}  // namespace

MobilityInput MobilityInputFromRgbd(const RgbdFrame& frame, const PinholeCamera& camera) {
  MobilityInput input;
  input.stamp = frame.stamp;
  input.cloud = std::make_shared<PointCloud>(DepthToCloud(frame.depth_m, cv::Mat(), camera, 1));
  input.color = frame.color;
  input.camera = camera;
  return input;
}

MobilityInput MobilityInputFromCloud(const CloudFrame& frame) {
  MobilityInput input;
  input.stamp = frame.stamp;
  input.cloud = frame.cloud;
  if (frame.cloud) input.color = CloudColorImage(*frame.cloud);
  return input;
}

MobilityMapper::MobilityMapper(MobilityOptions options)
    : options_(std::move(options)), gpr_(GprScore::TrainOnTable()) {}

Status MobilityMapper::Configure(const MobilityOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);
  options_ = options;
  return Status::Ok();
}

std::shared_ptr<const MobilityResult> MobilityMapper::Process(const MobilityInput& input) const {
  auto result = std::make_shared<MobilityResult>();
  const MobilityOptions& o = options_;
  result->stamp = input.stamp;
  result->mode = o.mode;
  result->use_gpr = o.score == "gpr";
  std::string error;
  if (!o.IsValid(&error)) {
    result->status = InvalidArgument(error);
    return result;
  }
  if (!input.cloud || input.cloud->empty()) {
    result->status = InvalidArgument("the frame holds no points");
    return result;
  }
  const PointCloud& cloud = *input.cloud;
  result->input_width = cloud.width;
  result->input_height = cloud.height;
  result->expected_up = input.up_in_camera
                            ? input.up_in_camera->normalized()
                            : ExpectedUpFromMount(o.mount_pitch_deg, o.mount_roll_deg);
  WorkingCloud work;
  std::unique_ptr<PclNeighborSearch> search;
  if (Status s = PointStages(cloud, o, &work, &search, result.get()); !s.ok()) {
    result->status = s;
    return result;
  }
  {
    StageClock t(result.get(), "rgbn", work.size());
    result->rgbn = EncodeNormals(work.normals);
  }
  std::vector<uint8_t> is_ground;
  {
    StageClock t(result.get(), "ground", work.size());
    StatusOr<GroundPlane> ground =
        FindGround(work, result->expected_up, o, &is_ground, &result->ransac_iterations);
    if (ground.ok()) {
      result->ground = *ground;
    } else {
      result->status = ground.status();
      result->ground.normal = result->expected_up;
    }
  }
  std::vector<int> label;
  int regions = 0;
  {
    std::vector<uint8_t> eligible(work.size());
    for (size_t i = 0; i < work.size(); ++i)
      eligible[i] = !is_ground[i] && work.normals[i].allFinite();
    StageClock t(result.get(), "segmentation", work.size() - result->ground.inliers);
    if (work.gridded()) {
      label = GrowGridRegions(work, result->rgbn, eligible, o.color_threshold, o.max_depth_jump,
                              o.min_segment_points, &regions);
    } else {
      const NeighborFunction neighbors = [&](int i, std::vector<int>* out) {
        search->Radius(i, o.pcl_neighbor_radius_m, out);
      };
      label = GrowRegions(result->rgbn, eligible, o.color_threshold, o.min_segment_points,
                          neighbors, &regions);
    }
  }
  // Segment 0 is the ground when found; regions follow.
  const int offset = result->ground.found ? 1 : 0;
  for (size_t i = 0; i < label.size(); ++i) {
    if (is_ground[i])
      label[i] = 0;
    else if (label[i] >= 0)
      label[i] += offset;
  }
  {
    StageClock t(result.get(), "surface", work.size());
    const std::vector<std::vector<Eigen::Vector3f>> members =
        SegmentPoints(work, label, regions + offset);
    std::vector<int> new_index(members.size(), -1);
    for (size_t s = 0; s < members.size(); ++s) {
      StatusOr<SegmentProperties> props =
          MeasureSegment(static_cast<int>(result->segments.size()), offset == 1 && s == 0,
                         members[s], result->ground, o);
      if (!props.ok()) continue;  // Degenerate (collinear, one cell): left unsegmented.
      new_index[s] = static_cast<int>(result->segments.size());
      result->segments.push_back(*props);
    }
    for (int& l : label) l = l >= 0 ? new_index[l] : -1;
  }
  {
    StageClock t(result.get(), "mobility", result->segments.size());
    for (SegmentProperties& s : result->segments) {
      s.raised = s.height_m > o.MaxStepM() && s.foot_m > o.ramp_foot_m;
      const bool scorable = result->ground.found && !s.raised;
      s.score_rule = scorable ? RuleScore(s.slope_deg, s.roughness) : 0;
      s.score_gpr = scorable ? gpr_.Predict(s.slope_deg, s.roughness) : 0;
    }
  }
  result->points = std::move(work.points);
  result->pixel = std::move(work.pixel);
  result->segment = std::move(label);
  {
    StageClock t(result.get(), "maps", result->points.size());
    // PointScore through a table per segment: entry 0 is "unsegmented" (NaN).
    std::vector<float> segment_score(result->segments.size() + 1,
                                     std::numeric_limits<float>::quiet_NaN());
    for (size_t s = 0; s < result->segments.size(); ++s) {
      const SegmentProperties& p = result->segments[s];
      segment_score[s + 1] = static_cast<float>(result->use_gpr ? p.score_gpr : p.score_rule);
    }
    std::vector<float> scores(result->points.size());
    for (size_t i = 0; i < scores.size(); ++i) scores[i] = segment_score[result->segment[i] + 1];
    result->map = BuildTopView(result->points, scores, result->ground, o.map_cell_m, o.RangeCutM());
    std::optional<PinholeCamera> camera = input.camera;
    if (!camera) {
      StatusOr<PinholeCamera> estimated = EstimateIntrinsics(cloud);
      if (estimated.ok()) camera = *estimated;
    }
    if (camera) {
      const int dot = o.mode == "grid" ? o.grid_stride : 3;
      result->projection = ProjectScores(result->points, scores, *camera, input.color,
                                         o.rgb_offset_x_m, o.rgb_offset_y_m, dot);
    }
  }
  return result;
}

}  // namespace sightline
