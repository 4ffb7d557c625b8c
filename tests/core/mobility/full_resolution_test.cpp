// Grid mode at full resolution (grid_stride 1: every finite pixel) against the seed's PCL path
// on every real cloud the other mobility tests use: the same ground within 1 cm, and every large
// segment of the PCL path scores the same (Table I rule) in both.
//
// Correspondence: the PCL path's points are 1 cm voxel centroids, which lie in the voxel of the
// input points they average. Each grid point votes its segment into its 1 cm voxel; a PCL point
// takes the majority segment of its voxel (grid points in it that were dropped by denoising or
// left unsegmented vote "none"). A PCL segment is large when it holds at least 3 % of the PCL
// path's segmented points and 500 points. Its grid partner is the grid segment most of its
// points take; the partner must score the same, and so must the grid segments of at least 90 %
// of the segment's points that the grid scored (the grid may split a far wall that the PCL
// path keeps whole, or the reverse: every piece must score alike). The grid must score at
// least a quarter of the segment's points: at stride 1 its 7 x 7 pixel normal window leaves
// much of office1's walls 4-5 m away unsegmented (depth steps read as edges), which scores
// nothing there rather than something else.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <unordered_map>

#include "core/io/dataset.h"
#include "core/io/pcd_source.h"
#include "core/mobility/mobility_mapper.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

constexpr double kVoxelM = 0.01;          // The PCL path's voxel (MobilityOptions::voxel_m).
constexpr double kLargeFraction = 0.03;   // Of the PCL path's segmented points.
constexpr int kLargeMinPoints = 500;      // PCL path points.
constexpr double kMinScoredShare = 0.25;  // Of the large segment's points.
constexpr double kMinEqualShare = 0.9;    // Of the large segment's points the grid scored.

int64_t VoxelKey(const Eigen::Vector3f& p) {
  const int64_t x = static_cast<int64_t>(std::floor(p.x() / kVoxelM)) + (1 << 20);
  const int64_t y = static_cast<int64_t>(std::floor(p.y() / kVoxelM)) + (1 << 20);
  const int64_t z = static_cast<int64_t>(std::floor(p.z() / kVoxelM)) + (1 << 20);
  return (x << 42) | (y << 21) | z;
}

// The majority grid segment of each 1 cm voxel (-1 = unsegmented wins).
std::unordered_map<int64_t, int> VoxelSegments(const MobilityResult& grid) {
  std::unordered_map<int64_t, std::map<int, int>> votes;
  for (size_t i = 0; i < grid.points.size(); ++i)
    ++votes[VoxelKey(grid.points[i])][grid.segment[i]];
  std::unordered_map<int64_t, int> majority;
  for (const auto& [key, counts] : votes) {
    int best = -1, best_count = -1;
    for (const auto& [segment, count] : counts) {
      if (count > best_count) best = segment, best_count = count;
    }
    majority[key] = best;
  }
  return majority;
}

// Runs both paths on one input and checks the ground and the large segments.
void ExpectGridMatchesPcl(const MobilityInput& input, const std::string& name) {
  MobilityOptions grid_options;
  grid_options.grid_stride = 1;
  MobilityOptions pcl_options;
  pcl_options.mode = "pcl";
  const auto grid = MobilityMapper(grid_options).Process(input);
  const auto pcl = MobilityMapper(pcl_options).Process(input);
  ASSERT_TRUE(grid->status.ok()) << name << ": " << grid->status.ToString();
  ASSERT_TRUE(pcl->status.ok()) << name << ": " << pcl->status.ToString();
  ASSERT_TRUE(grid->ground.found && pcl->ground.found) << name;
  EXPECT_NEAR(grid->ground.d, pcl->ground.d, 0.01) << name << ": camera height above the ground";
  EXPECT_EQ(grid->segments[0].score_rule, pcl->segments[0].score_rule) << name << ": ground";

  const std::unordered_map<int64_t, int> voxel_segment = VoxelSegments(*grid);
  int segmented = 0;
  std::vector<std::map<int, int>> partners(pcl->segments.size());
  for (size_t i = 0; i < pcl->points.size(); ++i) {
    const int s = pcl->segment[i];
    if (s < 0) continue;
    ++segmented;
    const auto it = voxel_segment.find(VoxelKey(pcl->points[i]));
    ++partners[s][it == voxel_segment.end() ? -1 : it->second];
  }
  const int large = std::max(kLargeMinPoints, static_cast<int>(kLargeFraction * segmented));
  int large_segments = 0, equal_scores = 0;
  for (size_t s = 0; s < pcl->segments.size(); ++s) {
    const SegmentProperties& p = pcl->segments[s];
    if (p.points < large) continue;
    ++large_segments;
    int partner = -1, overlap = 0, scored = 0, equal = 0;
    for (const auto& [g, count] : partners[s]) {
      if (g < 0) continue;
      scored += count;
      equal += grid->segments[g].score_rule == p.score_rule ? count : 0;
      if (count > overlap) partner = g, overlap = count;
    }
    ASSERT_GE(partner, 0) << name << ": PCL segment " << s << " has no grid partner";
    const SegmentProperties& g = grid->segments[partner];
    const double scored_share = static_cast<double>(scored) / p.points;
    const double equal_share = static_cast<double>(equal) / std::max(1, scored);
    std::printf(
        "%s: PCL segment %zu (%d points, slope %.1f deg, roughness %.3f, height %.3f m, rule "
        "%.2f) ~ grid segment %d (%.0f %% overlap, slope %.1f, roughness %.3f, height %.3f, "
        "rule %.2f); grid scores %.0f %% of its points, %.1f %% of them alike\n",
        name.c_str(), s, p.points, p.slope_deg, p.roughness, p.height_m, p.score_rule, partner,
        100.0 * overlap / p.points, g.slope_deg, g.roughness, g.height_m, g.score_rule,
        100 * scored_share, 100 * equal_share);
    EXPECT_EQ(p.score_rule, g.score_rule)
        << name << ": PCL segment " << s << " vs grid " << partner;
    EXPECT_GE(scored_share, kMinScoredShare) << name << ": PCL segment " << s;
    EXPECT_GE(equal_share, kMinEqualShare) << name << ": PCL segment " << s;
    equal_scores += p.score_rule == g.score_rule && equal_share >= kMinEqualShare;
  }
  std::printf("%s: ground %.4f m (grid) vs %.4f m (pcl); %d of %d large segments score equal\n",
              name.c_str(), grid->ground.d, pcl->ground.d, equal_scores, large_segments);
  EXPECT_GE(large_segments, 1) << name;
}

MobilityInput PcdInput(const std::string& path) {
  StatusOr<PointCloud> cloud = ReadPcdFile(path);
  EXPECT_TRUE(cloud.ok()) << cloud.status().ToString();
  CloudFrame frame;
  frame.cloud = std::make_shared<PointCloud>(cloud.ok() ? std::move(*cloud) : PointCloud());
  return MobilityInputFromCloud(frame);
}

TEST(FullResolution, Office1MatchesPclPath) {
  SIGHTLINE_REQUIRE_DATA(path, "pcl_clouds/office1.pcd");
  ExpectGridMatchesPcl(PcdInput(path), "office1");
}

TEST(FullResolution, MilkCartoonMatchesPclPath) {
  SIGHTLINE_REQUIRE_DATA(path, "pcl_clouds/milk_cartoon_all_small_clorox.pcd");
  ExpectGridMatchesPcl(PcdInput(path), "milk_cartoon");
}

TEST(FullResolution, GrabberSequenceMatchesPclPath) {
  for (const char* name : {"frame_20121214T142255.814212.pcd", "frame_20121214T142256.068683.pcd",
                           "frame_20121214T142256.332395.pcd"}) {
    SIGHTLINE_REQUIRE_DATA(path, std::string("pcl_clouds/grabber_sequences/pcd/") + name);
    ExpectGridMatchesPcl(PcdInput(path), name);
  }
}

TEST(FullResolution, TumDeskMatchesPclPathInEveryFrame) {
  SIGHTLINE_REQUIRE_DATA(path, "tum_fr1_desk");
  StatusOr<std::unique_ptr<Source>> source = OpenDataset(path, SourceKind::kRgbd);
  ASSERT_TRUE(source.ok()) << source.status().ToString();
  const PinholeCamera camera = (*source)->info().rgbd->color;
  int frames = 0;
  while ((*source)->Grab().ok()) {
    StatusOr<Frame> frame = (*source)->Retrieve();
    ASSERT_TRUE(frame.ok());
    ExpectGridMatchesPcl(MobilityInputFromRgbd(std::get<RgbdFrame>(*frame), camera),
                         "tum_fr1_desk frame " + std::to_string(frames));
    ++frames;
  }
  EXPECT_EQ(frames, 9);
}

}  // namespace
}  // namespace sightline
