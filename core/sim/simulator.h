// The simulator in memory: a scene, the sensors' motion and noise, rendered frame by frame.
// Tests and benchmarks use it directly; Simulate() (simulate.h) writes its frames to disk.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/common/camera.h"
#include "core/common/status.h"
#include "core/common/trajectory.h"
#include "core/sim/motion.h"
#include "core/sim/renderer.h"
#include "core/sim/scene.h"
#include "core/sim/simulation_options.h"

namespace sightline::sim {

// One RGB-D frame as the sensor reports it, with the exact render it came from.
struct SimulatedRgbd {
  cv::Mat color;      // CV_8UC3 BGR, with colour noise.
  cv::Mat depth_m;    // CV_32FC1 metres, NaN = no reading (range, incidence, noise model).
  RenderedView view;  // Exact depth, objects and incidence; view.image is the clean colour.
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
};

// One rectified stereo pair (grey) and the exact render of the left image.
struct SimulatedStereo {
  cv::Mat left, right;  // CV_8UC1 with image noise.
  RenderedView left_view;
  Eigen::Isometry3d world_from_left = Eigen::Isometry3d::Identity();
};

// One monocular colour image and its exact render.
struct SimulatedMono {
  cv::Mat image;  // CV_8UC3 BGR with image noise.
  RenderedView view;
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
};

// Builds the scene and the motion of SimulationOptions and renders any frame on request.
// Deterministic: frame i of a sensor depends only on (options, i). Not thread-safe (scratch
// buffers); make one Simulator per thread.
//
//   auto sim = Simulator::Create(SimulationOptions::ForScene("corridor"));
//   if (!sim.ok()) return sim.status();
//   SimulatedRgbd frame;
//   SIGHTLINE_RETURN_IF_ERROR(sim->RenderRgbd(0, &frame));
class Simulator {
 public:
  // Builds the built-in scene named by options.scene. InvalidArgument for invalid options.
  static StatusOr<Simulator> Create(const SimulationOptions& options);
  // Uses a caller-built scene (options.scene then only names defaults such as the sensors).
  static StatusOr<Simulator> Create(const SimulationOptions& options, Scene scene);

  const SimulationOptions& options() const { return options_; }
  const Scene& scene() const { return scene_; }
  const MotionPlan& motion() const { return motion_; }
  int frames() const { return options_.frames; }
  double TimeOf(int frame) const { return motion_.times_s.at(frame); }

  PinholeCamera rgbd_camera() const { return options_.rgbd.Camera(); }
  StereoRig stereo_rig() const { return options_.stereo.Rig(); }
  PinholeCamera mono_camera() const { return options_.mono.Camera(); }

  // Renders frame `frame` (0 <= frame < frames()) of one sensor. OutOfRange otherwise.
  Status RenderRgbd(int frame, SimulatedRgbd* out);
  Status RenderStereo(int frame, SimulatedStereo* out);
  Status RenderMono(int frame, SimulatedMono* out);
  // Renders the mono camera at any pose, e.g. a live camera in the hand of an arm that moves as
  // it is told: the scene at `time_s` (its moving parts), image noise drawn from `noise_index`
  // (RenderMono(i) equals RenderMonoAt(its pose, TimeOf(i), i)).
  Status RenderMonoAt(const Eigen::Isometry3d& world_from_camera, double time_s,
                      int64_t noise_index, SimulatedMono* out);

  // The true pose of the sensor carrier (robot base, handheld body or end effector).
  Trajectory BodyGroundTruth() const;
  // Wheel odometry of the robot base (robot and static motions; empty otherwise).
  Trajectory WheelOdometry() const;
  // Arm motions: base_from_end_effector as the arm reports it (with pose noise); else empty.
  Trajectory ArmPoses() const;

 private:
  Simulator(SimulationOptions options, Scene scene, MotionPlan motion)
      : options_(std::move(options)), scene_(std::move(scene)), motion_(std::move(motion)) {}
  Status CheckFrame(int frame) const;

  SimulationOptions options_;
  Scene scene_;
  MotionPlan motion_;
  Renderer renderer_;
};

// Builds the built-in scene `options.scene` with the options' seed.
StatusOr<Scene> BuildScene(const SimulationOptions& options);

}  // namespace sightline::sim
