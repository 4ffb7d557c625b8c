// The mapper end to end on ray-cast synthetic clouds: the ground is the lowest up-facing plane,
// and bad input gives a clear status, never a crash.
#include "core/mobility/mobility_mapper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/mobility/ground_plane.h"

namespace sightline {
namespace {

// A plane n . x + d = 0 limited to a box of the camera frame.
struct Patch {
  Eigen::Vector3f normal;
  float d;
  Eigen::Vector3f min, max;
};

// An organized 640x480 cloud (f = 525) seeing the nearest patch along each ray.
std::shared_ptr<PointCloud> RayCast(const std::vector<Patch>& patches) {
  auto cloud = std::make_shared<PointCloud>();
  cloud->width = 640;
  cloud->height = 480;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int v = 0; v < 480; ++v) {
    for (int u = 0; u < 640; ++u) {
      const Eigen::Vector3f ray((u - 319.5f) / 525.f, (v - 239.5f) / 525.f, 1.f);
      float best = std::numeric_limits<float>::infinity();
      for (const Patch& p : patches) {
        const float den = p.normal.dot(ray);
        if (std::abs(den) < 1e-6f) continue;
        const float t = -p.d / den;
        const Eigen::Vector3f x = t * ray;
        if (t > 0 && t < best && (x.array() >= p.min.array()).all() &&
            (x.array() <= p.max.array()).all()) {
          best = t;
        }
      }
      cloud->points.push_back(std::isfinite(best) ? Eigen::Vector3f(best * ray)
                                                  : Eigen::Vector3f(nan, nan, nan));
    }
  }
  return cloud;
}

const Eigen::Vector3f kLow(-100, -100, 0), kHigh(100, 100, 100);

// Floor 1.0 m below a level camera.
Patch Floor() { return {Eigen::Vector3f(0, -1, 0), 1.0f, kLow, kHigh}; }
// A low table top 0.6 m below the camera (0.4 m high), 1.5-3 m ahead, 4 m wide: it holds more
// points than the floor seen around it.
Patch Table() {
  return {Eigen::Vector3f(0, -1, 0), 0.6f, Eigen::Vector3f(-2, -1, 1.5f), Eigen::Vector3f(2, 1, 3)};
}
// A wall 2.5 m ahead.
Patch Wall(float z = 2.5f) { return {Eigen::Vector3f(0, 0, -1), z, kLow, kHigh}; }

MobilityInput Input(std::shared_ptr<PointCloud> cloud) {
  MobilityInput input;
  input.cloud = std::move(cloud);
  return input;
}

TEST(RansacIterations, FollowsSeedEquationSix) {
  // k = log(1 - p) / log(1 - w^3).
  EXPECT_EQ(RansacIterations(0.99, 0.5), 35);
  EXPECT_EQ(RansacIterations(0.99, 0.15), 1363);
}

TEST(ExpectedUp, TurnsWithThePitch) {
  const Eigen::Vector3d up = ExpectedUpFromMount(30, 0);
  EXPECT_NEAR(up.y(), -std::cos(M_PI / 6), 1e-9);
  EXPECT_NEAR(up.z(), -std::sin(M_PI / 6), 1e-9);
}

TEST(MobilityMapper, GroundIsTheLowestUpFacingPlaneNotTheLargest) {
  for (const char* mode : {"grid", "pcl"}) {
    MobilityOptions options;
    options.mode = mode;
    MobilityMapper mapper(options);
    auto result = mapper.Process(Input(RayCast({Floor(), Table(), Wall(3.2f)})));
    ASSERT_TRUE(result->status.ok()) << mode << ": " << result->status.ToString();
    ASSERT_TRUE(result->ground.found);
    EXPECT_NEAR(result->ground.d, 1.0, 0.01) << mode;  // Camera height above the floor.
    ASSERT_FALSE(result->segments.empty());
    EXPECT_TRUE(result->segments[0].is_ground);
    EXPECT_DOUBLE_EQ(result->segments[0].score_rule, 1.0);
    // The table top is flat but raised 0.4 m: score 0.
    bool table_seen = false;
    for (const SegmentProperties& s : result->segments) {
      // The wall above the table is raised too; the table top is the level one.
      if (s.is_ground || s.points < 300 || s.slope_deg > 10) continue;
      table_seen = true;
      EXPECT_NEAR(s.height_m, 0.4, 0.02);
      EXPECT_LT(s.slope_deg, 2.0);
      EXPECT_EQ(s.score_rule, 0.0);
      EXPECT_EQ(s.score_gpr, 0.0);
    }
    EXPECT_TRUE(table_seen) << mode;
  }
}

TEST(MobilityMapper, NoGroundPlaneIsSaid) {
  MobilityMapper mapper;
  auto result = mapper.Process(Input(RayCast({Wall()})));
  EXPECT_EQ(result->status.code(), StatusCode::kNotFound);
  EXPECT_NE(result->status.message().find("no ground plane"), std::string::npos)
      << result->status.message();
  EXPECT_FALSE(result->ground.found);
  for (const SegmentProperties& s : result->segments) EXPECT_EQ(s.score_rule, 0.0);
}

TEST(MobilityMapper, EmptyCloudIsAClearError) {
  MobilityMapper mapper;
  auto result = mapper.Process(Input(std::make_shared<PointCloud>()));
  EXPECT_EQ(result->status.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(result->status.message().find("no points"), std::string::npos);
  auto null_cloud = mapper.Process(MobilityInput{});
  EXPECT_FALSE(null_cloud->status.ok());
}

TEST(MobilityMapper, EverythingBeyondRangeIsReported) {
  MobilityMapper mapper;  // Wheelchair: 5 m.
  auto result = mapper.Process(Input(RayCast({Wall(7.0f)})));
  EXPECT_EQ(result->status.code(), StatusCode::kOutOfRange);
  EXPECT_NE(result->status.message().find("5.00 m range cut"), std::string::npos)
      << result->status.message();
}

TEST(MobilityMapper, CloudOfNansIsReported) {
  auto cloud = RayCast({});
  MobilityMapper mapper;
  for (const char* mode : {"grid", "pcl"}) {
    MobilityOptions options;
    options.mode = mode;
    ASSERT_TRUE(mapper.Configure(options).ok());
    auto result = mapper.Process(Input(cloud));
    EXPECT_EQ(result->status.code(), StatusCode::kOutOfRange) << mode;
    EXPECT_TRUE(result->points.empty());
  }
}

TEST(MobilityMapper, NansAmongPointsAreSkipped) {
  auto cloud = RayCast({Floor(), Wall(3.0f)});
  for (size_t i = 0; i < cloud->size(); i += 7) cloud->points[i].x() = std::nanf("");
  MobilityMapper mapper;
  auto result = mapper.Process(Input(cloud));
  ASSERT_TRUE(result->status.ok()) << result->status.ToString();
  EXPECT_NEAR(result->ground.d, 1.0, 0.01);
  for (const Eigen::Vector3f& p : result->points) EXPECT_TRUE(p.allFinite());
}

TEST(MobilityMapper, UnorganizedCloudNeedsThePclMode) {
  auto cloud = RayCast({Floor()});
  cloud->width = static_cast<int>(cloud->size());
  cloud->height = 1;
  MobilityMapper mapper;
  auto result = mapper.Process(Input(cloud));
  EXPECT_EQ(result->status.code(), StatusCode::kFailedPrecondition);
  EXPECT_NE(result->status.message().find("mode pcl"), std::string::npos);
}

TEST(MobilityMapper, InvalidOptionsAreRejectedByName) {
  MobilityMapper mapper;
  MobilityOptions options;
  options.grid_stride = 0;
  const Status s = mapper.Configure(options);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("mobility.grid_stride"), std::string::npos);
}

TEST(MobilityMapper, ReportsEveryStageWithItsPoints) {
  MobilityMapper mapper;
  auto result = mapper.Process(Input(RayCast({Floor(), Wall(3.0f)})));
  std::vector<std::string> names;
  for (const StageReport& s : result->stages) names.push_back(s.name);
  const std::vector<std::string> expected = {"downsample", "range_cut", "denoise",      "normals",
                                             "rgbn",       "ground",    "segmentation", "surface",
                                             "mobility",   "maps"};
  EXPECT_EQ(names, expected);
  EXPECT_EQ(result->stages[0].points, 640 * 480);
  EXPECT_FALSE(result->projection.empty());
  EXPECT_EQ(result->projection.cols, 640);
}

}  // namespace
}  // namespace sightline
