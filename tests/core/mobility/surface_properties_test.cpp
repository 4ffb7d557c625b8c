#include "core/mobility/surface_properties.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace sightline {
namespace {

// Points on z = height(x, y) over a square of side `size`, spacing `step`, in a frame where
// the plane is tilted by `tilt_deg` about x.
std::vector<Eigen::Vector3f> Surface(double size, double step, double tilt_deg,
                                     const std::function<double(double, double)>& height) {
  const Eigen::AngleAxisd tilt(tilt_deg * M_PI / 180, Eigen::Vector3d::UnitX());
  std::vector<Eigen::Vector3f> points;
  for (double x = 0; x < size; x += step) {
    for (double y = 0; y < size; y += step) {
      points.push_back(
          (tilt * Eigen::Vector3d(x, y, height(x, y)) + Eigen::Vector3d(0, 0, 2)).cast<float>());
    }
  }
  return points;
}

MobilityOptions Options() {
  MobilityOptions o;
  o.roughness_max_range_m = 100;
  return o;
}

GroundPlane Ground() {
  GroundPlane g;
  g.found = true;
  g.normal = Eigen::Vector3d::UnitZ();
  g.d = 0;
  return g;
}

TEST(Roughness, FlatPlaneIsOne) {
  const auto points = Surface(1.0, 0.01, 25, [](double, double) { return 0.0; });
  StatusOr<SegmentProperties> s = MeasureSegment(1, false, points, Ground(), Options());
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  EXPECT_NEAR(s->roughness, 1.0, 1e-6);
  EXPECT_NEAR(s->slope_deg, 25.0, 0.01);
  EXPECT_NEAR(s->area_m2, 1.0, 0.1);
}

TEST(Roughness, RidgesGiveTheirExactAreaRatio) {
  // A zigzag of period 0.12 m and facet slope 30 deg: 3D / projected area = 1 / cos 30.
  const double slope = std::tan(30 * M_PI / 180);
  auto zigzag = [slope](double x, double) {
    const double phase = std::fmod(x, 0.12);
    return slope * (phase < 0.06 ? phase : 0.12 - phase);
  };
  const auto points = Surface(1.2, 0.005, 0, zigzag);
  MobilityOptions o = Options();
  o.roughness_cell_m = 0.01;  // Cells resolve the 6 cm facets (averaging rounds the ridges).
  std::vector<double> measured;
  for (const char* triangulation : {"grid", "delaunay"}) {
    o.triangulation = triangulation;
    StatusOr<SegmentProperties> s = MeasureSegment(1, false, points, Ground(), o);
    ASSERT_TRUE(s.ok()) << s.status().ToString();
    EXPECT_NEAR(s->roughness, 1 / std::cos(30 * M_PI / 180), 0.03) << triangulation;
    measured.push_back(s->roughness);
  }
  EXPECT_NEAR(measured[0], measured[1], 0.01);  // One triangulation or the other.
}

TEST(Roughness, NeverBelowOneAndOrdered) {
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0, 1);
  double previous = 1.0;
  for (double amplitude : {0.002, 0.01, 0.03}) {
    const auto points =
        Surface(0.8, 0.01, 10, [&](double, double) { return amplitude * noise(rng); });
    StatusOr<SegmentProperties> s = MeasureSegment(1, false, points, Ground(), Options());
    ASSERT_TRUE(s.ok());
    EXPECT_GE(s->roughness, 1.0);
    EXPECT_GT(s->roughness, previous) << amplitude;
    previous = s->roughness;
  }
}

TEST(MeasureSegment, OnePointIsAClearError) {
  StatusOr<SegmentProperties> s =
      MeasureSegment(4, false, {Eigen::Vector3f(0, 0, 1)}, Ground(), Options());
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.status().message().find("segment 4"), std::string::npos) << s.status().message();
  EXPECT_NE(s.status().message().find("3 points"), std::string::npos) << s.status().message();
}

TEST(MeasureSegment, CollinearPointsAreAClearError) {
  std::vector<Eigen::Vector3f> line;
  for (int i = 0; i < 20; ++i) line.emplace_back(0.01f * i, 0, 1);
  StatusOr<SegmentProperties> s = MeasureSegment(2, false, line, Ground(), Options());
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.status().message().find("collinear"), std::string::npos) << s.status().message();
}

TEST(MeasureSegment, RaisedHeightIsTheLowQuantile) {
  // A ramp from z = 0 to z = 0.3 is not raised; a box top at 0.3 is.
  const auto ramp = Surface(1.0, 0.01, 0, [](double x, double) { return 0.3 * x - 2.0; });
  const auto top = Surface(0.5, 0.01, 0, [](double, double) { return 0.3 - 2.0; });
  StatusOr<SegmentProperties> r = MeasureSegment(1, false, ramp, Ground(), Options());
  StatusOr<SegmentProperties> t = MeasureSegment(2, false, top, Ground(), Options());
  ASSERT_TRUE(r.ok() && t.ok());
  EXPECT_LT(r->height_m, 0.03);
  EXPECT_NEAR(t->height_m, 0.3, 1e-3);
}

}  // namespace
}  // namespace sightline
