// The procedural textures give real feature detectors something to track.
#include <gtest/gtest.h>

#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include "core/sim/simulator.h"

namespace sightline::sim {
namespace {

TEST(Features, ShiTomasiFindsAtLeast200CornersOnACorridorFrame) {
  SimulationOptions options = SimulationOptions::ForScene("corridor");
  options.frames = 1;
  auto sim = Simulator::Create(options);
  ASSERT_TRUE(sim.ok());
  SimulatedRgbd rgbd;
  ASSERT_TRUE(sim->RenderRgbd(0, &rgbd).ok());
  cv::Mat grey;
  cv::cvtColor(rgbd.color, grey, cv::COLOR_BGR2GRAY);
  std::vector<cv::Point2f> corners;
  cv::goodFeaturesToTrack(grey, corners, 1000, 0.01, 8);
  EXPECT_GE(corners.size(), 200u);
  // The stereo camera's grey image too.
  SimulatedStereo stereo;
  ASSERT_TRUE(sim->RenderStereo(0, &stereo).ok());
  cv::goodFeaturesToTrack(stereo.left, corners, 1000, 0.01, 8);
  EXPECT_GE(corners.size(), 200u);
}

TEST(Features, CornersAreTrackableAcrossFrames) {
  SimulationOptions options = SimulationOptions::ForScene("corridor");
  options.frames = 2;
  options.sensors = "stereo";
  options.corridor.people = 0;
  auto sim = Simulator::Create(options);
  ASSERT_TRUE(sim.ok());
  SimulatedStereo a, b;
  ASSERT_TRUE(sim->RenderStereo(0, &a).ok());
  ASSERT_TRUE(sim->RenderStereo(1, &b).ok());
  std::vector<cv::Point2f> corners, tracked;
  cv::goodFeaturesToTrack(a.left, corners, 500, 0.01, 8);
  std::vector<uint8_t> status;
  std::vector<float> error;
  cv::calcOpticalFlowPyrLK(a.left, b.left, corners, tracked, status, error);
  // Compare with the true motion: reproject each corner with its exact depth.
  const StereoRig rig = sim->stereo_rig();
  const Eigen::Isometry3d b_from_a = b.world_from_left.inverse() * a.world_from_left;
  int good = 0, total = 0;
  for (size_t i = 0; i < corners.size(); ++i) {
    const int u = static_cast<int>(std::lround(corners[i].x));
    const int v = static_cast<int>(std::lround(corners[i].y));
    const float z = a.left_view.depth_m.at<float>(v, u);
    if (!status[i] || !(z > 0)) continue;
    const Eigen::Vector3d x = b_from_a * rig.left.Unproject(corners[i].x, corners[i].y, z);
    const Eigen::Vector2d expected = rig.left.Project(x);
    ++total;
    good += (expected - Eigen::Vector2d(tracked[i].x, tracked[i].y)).norm() < 1.0;
  }
  ASSERT_GT(total, 150);
  EXPECT_GT(good, total * 8 / 10) << good << " of " << total;
}

TEST(Features, SiftFindsKeypointsOnTheButtonPanel) {
  SimulationOptions options = SimulationOptions::ForScene("panel");
  options.frames = 150;
  auto sim = Simulator::Create(options);
  ASSERT_TRUE(sim.ok());
  SimulatedMono mono;
  ASSERT_TRUE(sim->RenderMono(100, &mono).ok());  // On the approach.
  cv::Ptr<cv::SIFT> sift = cv::SIFT::create();
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  sift->detectAndCompute(mono.image, cv::noArray(), keypoints, descriptors);
  EXPECT_GE(keypoints.size(), 100u);
  // Some keypoints sit on the target button.
  const ButtonSpec& target = sim->scene().buttons[sim->scene().hints.target_button];
  const Eigen::Vector2d center =
      sim->mono_camera().Project(mono.world_from_camera.inverse() * target.center);
  int on_button = 0;
  for (const cv::KeyPoint& k : keypoints) {
    on_button += (Eigen::Vector2d(k.pt.x, k.pt.y) - center).norm() < 40;
  }
  EXPECT_GE(on_button, 3);
}

}  // namespace
}  // namespace sightline::sim
