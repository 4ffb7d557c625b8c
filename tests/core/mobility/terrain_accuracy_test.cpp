// Accuracy on the simulator's terrain (Kinect noise): ramp slopes, flat-floor roughness and
// score, raised step and boxes, the rough patch against the floor (grid mode).
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "core/mobility/mobility_mapper.h"
#include "core/mobility/surface_properties.h"
#include "core/mobility/terrain_truth.h"
#include "core/sim/simulator.h"

namespace sightline {
namespace {

// The measured segments of one terrain frame by the kind of true region they fall in (the
// largest segment of each kind).
struct TerrainFrame {
  std::shared_ptr<const MobilityResult> result;
  std::map<std::string, const SegmentProperties*> by_kind;
  std::vector<TrueRegion> regions;
  std::vector<Eigen::Vector3d> world_points;  // Of result->points, map frame.
};

// The scored points inside the footprints of regions of `kind`, higher than min_z.
std::vector<size_t> PointsOver(const TerrainFrame& t, const std::string& kind, double min_z,
                               double max_z = 10) {
  std::vector<size_t> points;
  for (size_t i = 0; i < t.world_points.size(); ++i) {
    const Eigen::Vector3d& w = t.world_points[i];
    if (w.z() < min_z || w.z() > max_z) continue;
    for (const TrueRegion& r : t.regions) {
      if (r.kind == kind && InsidePolygon(r.polygon, w.head<2>())) {
        points.push_back(i);
        break;
      }
    }
  }
  return points;
}

TerrainFrame RunTerrain(double ramp_slope_deg, const std::string& mode, int frame = 0) {
  sim::SimulationOptions sim_options = sim::SimulationOptions::ForScene("terrain");
  sim_options.frames = frame + 1;
  sim_options.terrain.ramp_slope_deg = ramp_slope_deg;
  sim_options.terrain.wall_distance_m = 4.5;  // Room for the long 10 deg ramp.
  StatusOr<sim::Simulator> simulator = sim::Simulator::Create(sim_options);
  EXPECT_TRUE(simulator.ok()) << simulator.status().ToString();
  sim::SimulatedRgbd rgbd;
  EXPECT_TRUE(simulator->RenderRgbd(frame, &rgbd).ok());
  RgbdFrame input_frame;
  input_frame.color = rgbd.color;
  input_frame.depth_m = rgbd.depth_m;
  MobilityOptions options;
  options.mode = mode;
  MobilityMapper mapper(options);
  TerrainFrame out;
  out.result = mapper.Process(MobilityInputFromRgbd(input_frame, simulator->rgbd_camera()));
  std::vector<TrueRegion> regions;
  for (const sim::TerrainRegion& r : simulator->scene().regions) {
    regions.push_back({r.id, r.kind, r.slope_deg, r.roughness, r.height_m, r.polygon});
  }
  out.regions = regions;
  for (const Eigen::Vector3f& p : out.result->points) {
    out.world_points.push_back(rgbd.world_from_camera * p.cast<double>());
  }
  for (const SegmentMatch& m :
       MatchSegmentsToRegions(*out.result, rgbd.world_from_camera, regions)) {
    if (m.region < 0 || m.fraction < 0.8) continue;
    const SegmentProperties& s = out.result->segments[m.segment];
    const std::string& kind = regions[m.region].kind;
    if (out.by_kind.count(kind) == 0 || out.by_kind[kind]->points < s.points)
      out.by_kind[kind] = &s;
  }
  return out;
}

class TerrainAccuracy : public ::testing::TestWithParam<std::string> {};

TEST_P(TerrainAccuracy, RampSlopesWithinOneDegree) {
  for (double slope : {10.0, 20.0, 30.0}) {
    const TerrainFrame t = RunTerrain(slope, GetParam());
    ASSERT_TRUE(t.result->status.ok()) << t.result->status.ToString();
    ASSERT_TRUE(t.by_kind.count("ramp")) << "ramp of " << slope << " deg not segmented";
    const SegmentProperties& ramp = *t.by_kind.at("ramp");
    EXPECT_NEAR(ramp.slope_deg, slope, 1.0) << ramp.points << " points";
    EXPECT_FALSE(ramp.raised) << "a ramp touches the ground; height " << ramp.height_m;
    // The true slope sits on a band edge of Table I: either neighbouring band is right.
    EXPECT_GE(ramp.score_rule, RuleScore(slope + 1, 1.0));
    EXPECT_LE(ramp.score_rule, RuleScore(slope - 1, 1.0));
    EXPECT_GT(ramp.score_gpr, 0.2);
  }
}

TEST_P(TerrainAccuracy, FlatFloorIsSmoothAndTraversable) {
  const TerrainFrame t = RunTerrain(20, GetParam());
  ASSERT_TRUE(t.result->ground.found);
  ASSERT_FALSE(t.result->segments.empty());
  const SegmentProperties& ground = t.result->segments[0];
  ASSERT_TRUE(ground.is_ground);
  EXPECT_NEAR(ground.roughness, 1.0, 0.02);
  EXPECT_DOUBLE_EQ(ground.score_rule, 1.0);
  EXPECT_GE(ground.score_gpr, 0.95);
  EXPECT_NEAR(t.result->ground.d, 1.0, 0.03);  // Camera 1.0 m above the floor.
}

TEST_P(TerrainAccuracy, StepAndBoxesScoreZero) {
  const TerrainFrame t = RunTerrain(20, GetParam());
  for (const char* kind : {"step", "box"}) {
    int scored = 0, zero = 0;
    for (size_t i : PointsOver(t, kind, 0.05)) {
      if (t.result->segment[i] < 0) continue;
      ++scored;
      zero += t.result->segments[t.result->segment[i]].score_rule == 0.0;
    }
    ASSERT_GT(scored, 100) << kind;
    // The bottom edges of the front faces (normals bent by the floor) may score as low slopes.
    std::printf("%s: %d of %d scored points score 0\n", kind, zero, scored);
    EXPECT_GE(zero, 0.85 * scored) << kind;
  }
  ASSERT_TRUE(t.by_kind.count("step"));
  EXPECT_TRUE(t.by_kind.at("step")->raised);
  EXPECT_NEAR(t.by_kind.at("step")->height_m, 0.12, 0.03);
}

TEST_P(TerrainAccuracy, RoughPatchIsRougherThanTheFloor) {
  // The 5 cm facets stay within the ground's tolerance, so the patch joins the ground segment;
  // its roughness is measured on its own points, against the flat floor just in front of it.
  const TerrainFrame t = RunTerrain(20, GetParam());
  auto measure = [&](const std::vector<size_t>& indices) {
    std::vector<Eigen::Vector3f> points;
    for (size_t i : indices) points.push_back(t.result->points[i]);
    return MeasureSegment(1, false, points, t.result->ground, MobilityOptions());
  };
  std::vector<size_t> flat;
  for (size_t i : PointsOver(t, "floor", -0.05, 0.05)) {
    const Eigen::Vector3d& w = t.world_points[i];
    if (w.x() > 0.5 && w.x() < 1.15 && w.y() > -1.35 && w.y() < -0.55)
      flat.push_back(i);  // In front of it.
  }
  const std::vector<size_t> rough_points = PointsOver(t, "rough", -0.05);
  ASSERT_GT(rough_points.size(), 200u);
  ASSERT_GT(flat.size(), 200u);
  StatusOr<SegmentProperties> rough = measure(rough_points);
  StatusOr<SegmentProperties> floor = measure(flat);
  ASSERT_TRUE(rough.ok() && floor.ok());
  EXPECT_NEAR(floor->roughness, 1.0, 0.02);
  EXPECT_GT(rough->roughness, floor->roughness + 0.01);
  EXPECT_LT(rough->roughness, 1.15 + 0.02);  // Cell averaging can only smooth the facets.
  EXPECT_DOUBLE_EQ(t.result->segments[0].score_rule, 1.0);
}

// The pcl mode is not held to these figures: with the seed's 1 cm voxels and 16-neighbour
// normals, the Kinect's depth quantisation beyond ~2.5 m reads as terraces facing the camera.
INSTANTIATE_TEST_SUITE_P(Modes, TerrainAccuracy, ::testing::Values("grid"));

}  // namespace
}  // namespace sightline
