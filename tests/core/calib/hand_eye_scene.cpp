#include "hand_eye_scene.h"

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <random>

#include "board_renderer.h"
#include "core/io/camera_yaml.h"
#include "core/sim/simulator.h"

namespace sightline::testing {

StatusOr<HandEyeScene> MakeHandEyeScene(int views, const ChessboardOptions& board) {
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("panel");
  options.frames = 2;
  auto simulator = sim::Simulator::Create(options);
  if (!simulator.ok()) return simulator.status();
  const sim::MotionPlan& plan = simulator->motion();
  HandEyeScene scene;
  scene.camera = simulator->mono_camera();
  scene.end_effector_from_camera = plan.body_from_camera;
  // The board 0.5 m in front of the camera's first pose, facing it.
  const Eigen::Isometry3d world_from_board =
      plan.WorldFromCamera(0) * BoardFromCameraLookingAt(board, 0.5, 0, 0, 0).inverse();
  const Eigen::Isometry3d base_from_world = plan.world_from_arm_base.inverse();
  std::mt19937 engine(7);
  std::normal_distribution<double> normal(0, options.arm.pose_noise_m);
  for (int i = 0; i < views; ++i) {
    const double off_axis = 12 + 20 * (i % 3) / 2.0;  // 12, 22, 32 deg.
    const double azimuth = 360.0 * i / views;
    const double roll = ((i % 5) - 2) * 10.0;
    const double distance = 0.42 + 0.05 * (i % 4);
    const Eigen::Isometry3d board_from_camera =
        BoardFromCameraLookingAt(board, distance, off_axis, azimuth, roll);
    const Eigen::Isometry3d world_from_camera = world_from_board * board_from_camera;
    Eigen::Isometry3d base_from_ee =
        base_from_world * world_from_camera * scene.end_effector_from_camera.inverse();
    base_from_ee.translation() += Eigen::Vector3d(normal(engine), normal(engine), normal(engine));
    const double t = 0.1 * i;
    scene.times_s.push_back(t);
    scene.base_from_end_effector.Add(t, base_from_ee);
    scene.camera_from_board.push_back(board_from_camera.inverse());
    scene.images.push_back(
        RenderBoardView(scene.camera, board_from_camera.inverse(), board, 2.0, 100 + i));
  }
  return scene;
}

Status WriteHandEyeScene(const HandEyeScene& scene, const std::string& dir) {
  const std::string views = dir + "/views";
  std::filesystem::create_directories(views);
  std::ofstream times(views + "/times.txt");
  for (size_t i = 0; i < scene.images.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof(name), "%06zu.png", i);
    if (!cv::imwrite(views + "/" + name, scene.images[i])) {
      return Unavailable("cannot write " + views + "/" + name);
    }
    times << scene.times_s[i] << " " << name << "\n";
  }
  CameraFile camera;
  camera.camera = scene.camera;
  SIGHTLINE_RETURN_IF_ERROR(WriteCameraYaml(camera, views + "/camera.yaml"));
  return WriteTumTrajectory(scene.base_from_end_effector, dir + "/arm_poses.txt");
}

}  // namespace sightline::testing
