// The mapper's idle-time global adjustment (PTAM): slices of a bounded number of keyframes that
// lower the reprojection error of a disturbed map and stop once a pass over the map is done;
// and the bounded adjustment when the run stops.
#include "core/mono/local_mapper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <mutex>
#include <random>

#include "core/mono/features.h"
#include "core/mono/mono_slam.h"
#include "tests/core/mono/mono_test_util.h"
#include "tests/support/test_camera.h"

namespace sightline {
namespace {

// Root mean square reprojection error over every observation of the map [px].
double MapRmsPx(const SlamMap& map, const PinholeCamera& camera) {
  double sum = 0;
  int n = 0;
  for (const auto& [id, p] : map.points()) {
    for (const auto& [kf, index] : p.observations) {
      const KeyFrame& k = *map.keyframes()[kf];
      const Eigen::Vector2d uv = ProjectToPixel(camera, k.camera_from_map * p.position);
      sum += (uv - k.features.pixels[index]).squaredNorm();
      ++n;
    }
  }
  return n > 0 ? std::sqrt(sum / n) : 0;
}

// `keyframes` cameras 0.1 apart along x looking at a wall of points 4 away, with exact
// observations; then every pose but the first and every point disturbed.
void BuildDisturbedMap(int keyframes, const PinholeCamera& camera, SlamMap* map) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> wall_x(-1.5, 0.1 * keyframes + 1.5), wall_y(-1.5, 1.5);
  std::normal_distribution<double> noise(0, 1);
  std::vector<Eigen::Vector3d> truth;
  for (int i = 0; i < 40 * keyframes; ++i) truth.emplace_back(wall_x(rng), wall_y(rng), 4.0);
  std::vector<int64_t> ids;
  for (const Eigen::Vector3d& x : truth) {
    MapPoint p;
    p.position = x + 0.02 * Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    p.descriptor = cv::Mat::zeros(1, 32, CV_8U);
    ids.push_back(map->AddPoint(std::move(p)));
  }
  for (int k = 0; k < keyframes; ++k) {
    auto keyframe = std::make_shared<KeyFrame>();
    Eigen::Isometry3d camera_from_map = Eigen::Isometry3d::Identity();
    camera_from_map.translation() = Eigen::Vector3d(-0.1 * k, 0, 0);
    std::vector<std::pair<int64_t, int>> seen;
    for (size_t i = 0; i < truth.size(); ++i) {
      const Eigen::Vector2d uv = ProjectToPixel(camera, camera_from_map * truth[i]);
      if (uv.x() < 0 || uv.y() < 0 || uv.x() >= camera.width || uv.y() >= camera.height) continue;
      seen.emplace_back(ids[i], static_cast<int>(keyframe->features.pixels.size()));
      keyframe->features.pixels.push_back(uv);
      keyframe->features.keypoints.emplace_back(cv::Point2f(uv.x(), uv.y()), 7.f);
    }
    if (k > 0) {
      camera_from_map.translation() += 0.01 * Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    }
    keyframe->camera_from_map = camera_from_map;
    const int64_t id = map->AddKeyFrame(keyframe);
    for (const auto& [point, index] : seen) map->AddObservation(point, id, index);
  }
}

TEST(LocalMapper, IdleSlicesLowerTheReprojectionErrorAndStopAfterOnePass) {
  const PinholeCamera camera = testing::VgaCamera();
  SlamMap map;
  std::mutex mutex;
  constexpr int kKeyFrames = 30;
  BuildDisturbedMap(kKeyFrames, camera, &map);
  MonoMappingOptions options;
  options.idle_ba_window = 8;
  LocalMapper mapper(options, camera, 1.2, &map, &mutex);
  EXPECT_EQ(mapper.IdleBundle(5).keyframes, 0);  // Nothing changed yet: no work.
  mapper.MapChanged();
  const int slices = mapper.idle_slices_left();
  EXPECT_EQ(slices, (kKeyFrames + 3) / 4);  // Half-window steps over the whole map.
  const double before = MapRmsPx(map, camera);
  int adjusted = 0;
  while (mapper.idle_slices_left() > 0) {
    const IdleBundleStats slice = mapper.IdleBundle(5);
    EXPECT_LE(slice.keyframes, options.idle_ba_window);
    EXPECT_LE(slice.bundle.iterations, 5 + 1);  // Ceres counts the initial evaluation too.
    EXPECT_TRUE(slice.bundle.usable);
    adjusted += slice.keyframes;
  }
  const double after = MapRmsPx(map, camera);
  std::cout << "  idle slices = " << slices << ", rms " << before << " -> " << after << " px\n";
  EXPECT_GE(adjusted, kKeyFrames);  // Every keyframe was in a slice.
  EXPECT_LT(after, 0.5 * before);
  EXPECT_EQ(mapper.IdleBundle(5).keyframes, 0);  // The pass is done: idle time stays idle.
}

TEST(MonoSlamStop, LargeMapsGetABoundedAdjustmentSmallOnesTheFullOne) {
  StatusOr<testing::PanelSequence> panel = testing::RenderPanel();
  ASSERT_TRUE(panel.ok()) << panel.status().ToString();
  // The default: the panel's map is small, so the full global adjustment runs (two rounds).
  MonoSlam full;
  ASSERT_TRUE(full.Configure(panel->camera).ok());
  testing::RunFrames(&full, panel->frames);
  full.Stop();
  const int keyframes = static_cast<int>(full.Snapshot()->keyframes.size());
  EXPECT_TRUE(full.idle_bundle().stop_full);
  EXPECT_EQ(full.idle_bundle().stop_keyframes_adjusted, 2 * keyframes);
  // The same map counted as large: at most final_ba_max_slices slices of idle_ba_window.
  MonoSlamOptions options;
  options.mapping.final_ba_max_keyframes = 5;
  options.mapping.final_ba_max_slices = 2;
  options.mapping.idle_ba_window = 6;
  options.mapping.idle_ba_iterations = 0;  // No idle time used: the whole pass is left at stop.
  MonoSlam bounded(options);
  ASSERT_TRUE(bounded.Configure(panel->camera).ok());
  testing::RunFrames(&bounded, panel->frames);
  bounded.Stop();
  const IdleBundleTotals stop = bounded.idle_bundle();
  ASSERT_GT(bounded.Snapshot()->keyframes.size(), 12u);
  EXPECT_FALSE(stop.stop_full);
  EXPECT_EQ(stop.stop_slices, 2);
  EXPECT_EQ(stop.stop_keyframes_adjusted, 12);
  EXPECT_LE(stop.stop_iterations, 2 * (options.mapping.final_ba_iterations + 1));
  EXPECT_EQ(stop.slices, 0);
}

}  // namespace
}  // namespace sightline
