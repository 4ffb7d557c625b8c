#include "core/sim/simulator.h"

#include "core/sim/random.h"
#include "core/sim/sensor_noise.h"

namespace sightline::sim {
namespace {

// Seed streams: one per purpose, so adding a sensor never changes another's noise.
enum Stream : uint64_t {
  kMotionStream = 1,
  kDepthNoise = 2,
  kColorNoise = 3,
  kLeftNoise = 4,
  kRightNoise = 5,
  kMonoNoise = 6,
  kOdometryStream = 7,
  kArmStream = 8,
};

}  // namespace

StatusOr<Scene> BuildScene(const SimulationOptions& options) {
  const uint64_t seed = static_cast<uint64_t>(options.seed);
  if (options.scene == "corridor") return BuildCorridor(options.corridor, seed);
  if (options.scene == "terrain") return BuildTerrain(options.terrain, seed);
  if (options.scene == "panel") return BuildPanel(options.panel, seed);
  return InvalidArgument("sim.scene = '" + options.scene + "': must be corridor, terrain or panel");
}

StatusOr<Simulator> Simulator::Create(const SimulationOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);
  StatusOr<Scene> scene = BuildScene(options);
  if (!scene.ok()) return scene.status();
  return Create(options, std::move(*scene));
}

StatusOr<Simulator> Simulator::Create(const SimulationOptions& options, Scene scene) {
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);
  StatusOr<MotionPlan> motion =
      PlanMotion(scene, options.motion, options.arm, options.frames, options.rate_hz,
                 DeriveSeed(static_cast<uint64_t>(options.seed), kMotionStream));
  if (!motion.ok()) return motion.status();
  return Simulator(options, std::move(scene), std::move(*motion));
}

Status Simulator::CheckFrame(int frame) const {
  if (frame < 0 || frame >= frames()) {
    return OutOfRange("frame " + std::to_string(frame) + " outside [0, " +
                      std::to_string(frames()) + ")");
  }
  return Status::Ok();
}

Status Simulator::RenderRgbd(int frame, SimulatedRgbd* out) {
  SIGHTLINE_RETURN_IF_ERROR(CheckFrame(frame));
  const uint64_t seed = static_cast<uint64_t>(options_.seed);
  out->world_from_camera = motion_.WorldFromCamera(frame);
  SIGHTLINE_RETURN_IF_ERROR(renderer_.Render(scene_, scene_.DynamicPrimitives(TimeOf(frame)),
                                             rgbd_camera(), out->world_from_camera,
                                             ImageKind::kColor, &out->view));
  const NoiseModel noise = options_.noise.Effective();
  ApplyDepthModel(out->view, options_.rgbd, noise, DeriveSeed(seed, kDepthNoise, frame),
                  &out->depth_m);
  out->view.image.copyTo(out->color);
  AddImageNoise(noise.color_sigma, DeriveSeed(seed, kColorNoise, frame), &out->color);
  return Status::Ok();
}

Status Simulator::RenderStereo(int frame, SimulatedStereo* out) {
  SIGHTLINE_RETURN_IF_ERROR(CheckFrame(frame));
  const uint64_t seed = static_cast<uint64_t>(options_.seed);
  const StereoRig rig = stereo_rig();
  const std::vector<Primitive> dynamic = scene_.DynamicPrimitives(TimeOf(frame));
  out->world_from_left = motion_.WorldFromCamera(frame);
  SIGHTLINE_RETURN_IF_ERROR(renderer_.Render(scene_, dynamic, rig.left, out->world_from_left,
                                             ImageKind::kGrey, &out->left_view));
  out->left_view.image.copyTo(out->left);
  RenderedView right_view;
  SIGHTLINE_RETURN_IF_ERROR(renderer_.Render(scene_, dynamic, rig.right,
                                             out->world_from_left * rig.right_from_left.inverse(),
                                             ImageKind::kGrey, &right_view));
  out->right = right_view.image;
  const double sigma = options_.noise.Effective().grey_sigma;
  AddImageNoise(sigma, DeriveSeed(seed, kLeftNoise, frame), &out->left);
  AddImageNoise(sigma, DeriveSeed(seed, kRightNoise, frame), &out->right);
  return Status::Ok();
}

Status Simulator::RenderMono(int frame, SimulatedMono* out) {
  SIGHTLINE_RETURN_IF_ERROR(CheckFrame(frame));
  return RenderMonoAt(motion_.WorldFromCamera(frame), TimeOf(frame), frame, out);
}

Status Simulator::RenderMonoAt(const Eigen::Isometry3d& world_from_camera, double time_s,
                               int64_t noise_index, SimulatedMono* out) {
  out->world_from_camera = world_from_camera;
  SIGHTLINE_RETURN_IF_ERROR(renderer_.Render(scene_, scene_.DynamicPrimitives(time_s),
                                             mono_camera(), out->world_from_camera,
                                             ImageKind::kColor, &out->view));
  out->view.image.copyTo(out->image);
  AddImageNoise(options_.noise.Effective().grey_sigma,
                DeriveSeed(static_cast<uint64_t>(options_.seed), kMonoNoise,
                           static_cast<uint64_t>(noise_index)),
                &out->image);
  return Status::Ok();
}

Trajectory Simulator::BodyGroundTruth() const {
  Trajectory t;
  for (size_t i = 0; i < motion_.times_s.size(); ++i) {
    t.Add(motion_.times_s[i], motion_.world_from_body[i]);
  }
  return t;
}

Trajectory Simulator::WheelOdometry() const {
  if (!motion_.is_robot()) return {};
  return SimulateWheelOdometry(motion_.times_s, motion_.world_from_body, options_.odometry,
                               DeriveSeed(static_cast<uint64_t>(options_.seed), kOdometryStream));
}

Trajectory Simulator::ArmPoses() const {
  Trajectory t;
  if (!motion_.is_arm()) return t;
  std::mt19937 engine = MakeEngine(DeriveSeed(static_cast<uint64_t>(options_.seed), kArmStream));
  const Eigen::Isometry3d base_from_world = motion_.world_from_arm_base.inverse();
  for (size_t i = 0; i < motion_.times_s.size(); ++i) {
    Eigen::Isometry3d base_from_ee = base_from_world * motion_.world_from_body[i];
    const double s = options_.arm.pose_noise_m;
    const Eigen::Vector3d noise(Normal(engine), Normal(engine), Normal(engine));
    base_from_ee.translation() += s * noise;
    t.Add(motion_.times_s[i], base_from_ee);
  }
  return t;
}

}  // namespace sightline::sim
