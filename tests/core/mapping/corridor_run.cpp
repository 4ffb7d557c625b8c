#include "tests/core/mapping/corridor_run.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "core/sim/observations.h"
#include "core/sim/simulator.h"

namespace sightline::testing {

sim::SimulationOptions CorridorSimulation(double metres, double rate_hz, double speed_mps,
                                          double heading_drift_deg_per_m, int seed) {
  sim::SimulationOptions o = sim::SimulationOptions::ForScene("corridor");
  o.seed = seed;
  o.sensors = "rgbd";
  o.rgbd.resolution = "320x240";
  o.rate_hz = rate_hz;
  o.motion.speed_mps = speed_mps;
  o.frames = static_cast<int>(metres / speed_mps * rate_hz) + 1;
  o.odometry.heading_drift_deg_per_m = heading_drift_deg_per_m;
  // A 100 m loop with four 90 deg left turns: 30 m + 20 m + 30 m + 20 m.
  o.corridor.loop_length_m = 30.0;
  o.corridor.loop_width_m = 20.0;
  return o;
}

std::vector<TrueWall> TrueObstacleOutlines(const sim::Scene& scene, double min_height_m,
                                           double max_height_m) {
  std::vector<TrueWall> outlines;
  int id = 0;
  for (const sim::Primitive& primitive : scene.primitives()) {
    const sim::ObjectKind kind = scene.objects().at(primitive.object).kind;
    if (kind == sim::ObjectKind::kFloor || kind == sim::ObjectKind::kCeiling ||
        kind == sim::ObjectKind::kPerson) {
      continue;
    }
    if (const auto* patch = std::get_if<sim::PlanarPatch>(&primitive.shape)) {
      if (std::abs(patch->normal().z()) > 0.1) continue;  // Only vertical surfaces.
      const std::vector<Eigen::Vector2d> outline = patch->Outline();
      double z_lo = 1e9, z_hi = -1e9;
      Eigen::Vector2d lo(1e9, 1e9), hi(-1e9, -1e9);
      // The footprint of a vertical patch is the segment spanned by its corners' (x, y).
      const Eigen::Vector3d along =
          Eigen::Vector3d(patch->normal().y(), -patch->normal().x(), 0).normalized();
      double t_lo = 1e9, t_hi = -1e9;
      Eigen::Vector3d base = patch->At(outline[0].x(), outline[0].y());
      for (const Eigen::Vector2d& st : outline) {
        const Eigen::Vector3d p = patch->At(st.x(), st.y());
        z_lo = std::min(z_lo, p.z());
        z_hi = std::max(z_hi, p.z());
        const double t = along.dot(p - base);
        t_lo = std::min(t_lo, t);
        t_hi = std::max(t_hi, t);
      }
      (void)lo;
      (void)hi;
      if (z_hi < min_height_m || z_lo > max_height_m || t_hi - t_lo < 1e-6) continue;
      const Eigen::Vector3d a = base + t_lo * along, b = base + t_hi * along;
      outlines.push_back({id++, a.head<2>(), b.head<2>()});
    } else if (const auto* cylinder = std::get_if<sim::Cylinder>(&primitive.shape)) {
      if (cylinder->base.z() > max_height_m ||
          cylinder->base.z() + cylinder->height < min_height_m) {
        continue;
      }
      const int sides = 16;
      for (int k = 0; k < sides; ++k) {
        const double a0 = 2 * M_PI * k / sides, a1 = 2 * M_PI * (k + 1) / sides;
        const Eigen::Vector2d c = cylinder->base.head<2>();
        outlines.push_back({id++,
                            c + cylinder->radius * Eigen::Vector2d(std::cos(a0), std::sin(a0)),
                            c + cylinder->radius * Eigen::Vector2d(std::cos(a1), std::sin(a1))});
      }
    }
  }
  return outlines;
}

namespace {

// Position errors of `estimate` against the truth, both anchored at their first pose.
void MeasureDrift(const std::vector<Pose2d>& estimate,
                  const std::vector<Eigen::Vector2d>& true_positions,
                  const std::vector<double>& true_heading, CorridorScore* score) {
  const Pose2d true_first{true_positions[0].x(), true_positions[0].y(), true_heading[0]};
  const Eigen::Isometry3d truth_from_estimate =
      true_first.ToIsometry() * estimate[0].ToIsometry().inverse();
  for (size_t k = 0; k < estimate.size(); ++k) {
    if (k > 0) score->path_m += (true_positions[k] - true_positions[k - 1]).norm();
    const Eigen::Vector3d p =
        truth_from_estimate * Eigen::Vector3d(estimate[k].x, estimate[k].y, 0);
    const double e = (p.head<2>() - true_positions[k]).norm();
    score->position_error_max_m = std::max(score->position_error_max_m, e);
    score->position_error_final_m = e;
  }
}

}  // namespace

StatusOr<std::vector<CorridorScore>> RunCorridor(const sim::SimulationOptions& simulation,
                                                 const std::vector<MappingOptions>& configs,
                                                 int floor_frames) {
  StatusOr<sim::Simulator> made = sim::Simulator::Create(simulation);
  if (!made.ok()) return made.status();
  sim::Simulator& simulator = *made;
  const PinholeCamera camera = simulator.rgbd_camera();
  const Trajectory odometry = simulator.WheelOdometry();
  const Eigen::Isometry3d body_from_camera = simulator.motion().body_from_camera;
  const double camera_forward_m = body_from_camera.translation().x();
  std::vector<TrueWall> walls;
  for (const sim::WallLine& w : simulator.scene().walls) walls.push_back({w.id, w.start, w.end});
  const std::vector<TrueWall> obstacles = TrueObstacleOutlines(
      simulator.scene(), configs.at(0).floor.epsilon_m, configs.at(0).occupancy.max_height_m);

  // Floor from the first frames.
  sim::SimulatedRgbd frame;
  std::vector<Eigen::Vector3f> points;
  for (int k = 0; k < floor_frames; ++k) {
    SIGHTLINE_RETURN_IF_ERROR(simulator.RenderRgbd(k, &frame));
    AppendDepthPoints(frame.depth_m, camera, 6.0, 1, &points);
  }
  StatusOr<FloorFitResult> floor = FloorPlaneEstimator(configs.at(0).floor).Fit(points);
  if (!floor.ok()) return floor.status();

  std::vector<std::unique_ptr<MappingFrameProcessor>> processors;
  std::vector<CorridorScore> scores(configs.size());
  for (const MappingOptions& options : configs) {
    processors.push_back(std::make_unique<MappingFrameProcessor>(options));
    SIGHTLINE_RETURN_IF_ERROR(processors.back()->Configure(floor->plane, camera));
  }
  const Eigen::Isometry3d camera_from_base = processors[0]->base_from_camera().inverse();
  std::vector<double> true_heading;
  std::vector<Eigen::Vector2d> true_positions;
  for (int k = 0; k < simulator.frames(); ++k) {
    SIGHTLINE_RETURN_IF_ERROR(simulator.RenderRgbd(k, &frame));
    MappingInput input;
    input.stamp.sequence_id = k;
    input.stamp.sensor_time_s = simulator.TimeOf(k);
    input.depth_m = frame.depth_m;
    input.color = frame.color;
    Pose2d odo = Pose2d::FromIsometry(odometry.poses().at(k).world_from_sensor);
    odo.x += camera_forward_m * std::cos(odo.heading_rad);
    odo.y += camera_forward_m * std::sin(odo.heading_rad);
    input.odometry = odo;
    std::vector<PersonBox> people;
    std::vector<int> people_pixels;
    std::vector<double> people_range_m;
    for (const sim::PersonObservation& p : sim::ObservePeople(simulator.scene(), frame.view, k)) {
      if (p.pixels == 0) continue;
      PersonBox box;
      box.id = p.person;
      box.box = cv::Rect2d(p.u0, p.v0, p.u1 - p.u0 + 1, p.v1 - p.v0 + 1);
      box.image_size = cv::Size(camera.width, camera.height);
      people.push_back(box);
      people_pixels.push_back(p.pixels);
      double range = 1e9;
      for (const sim::WalkingPerson& person : simulator.scene().people) {
        if (person.id != p.person) continue;
        const Eigen::Vector2d at = sim::PersonPose(person, simulator.TimeOf(k)).position;
        range = (at - frame.world_from_camera.translation().head<2>()).norm();
      }
      people_range_m.push_back(range);
    }
    input.people = people;
    const Eigen::Isometry3d world_from_base = frame.world_from_camera * camera_from_base;
    // What can hide a wall from the scan: static obstacles and the walking people (a 0.25 m
    // circle around each body).
    std::vector<TrueWall> occluders = obstacles;
    for (const sim::WalkingPerson& person : simulator.scene().people) {
      const Eigen::Vector2d c = sim::PersonPose(person, simulator.TimeOf(k)).position;
      for (int side = 0; side < 8; ++side) {
        const double a0 = M_PI * side / 4, a1 = M_PI * (side + 1) / 4;
        occluders.push_back({-1, c + 0.25 * Eigen::Vector2d(std::cos(a0), std::sin(a0)),
                             c + 0.25 * Eigen::Vector2d(std::cos(a1), std::sin(a1))});
      }
    }
    const Pose2d true_base = Pose2d::FromIsometry(world_from_base);
    true_heading.push_back(true_base.heading_rad);
    true_positions.push_back(true_base.position());

    for (size_t c = 0; c < configs.size(); ++c) {
      const auto start = std::chrono::steady_clock::now();
      StatusOr<std::shared_ptr<const MappingFrameResult>> r = processors[c]->Process(input);
      if (!r.ok()) return r.status().WithContext("frame " + std::to_string(k));
      CorridorScore& score = scores[c];
      score.frame_ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count());
      score.statuses.push_back((*r)->status);
      if ((*r)->pose_source == "rgbd") score.odometry_ms.push_back((*r)->times.odometry_ms);
      // People found against the true boxes.
      std::vector<cv::Rect2d> detections;
      for (const PersonBox& b : (*r)->people) {
        if (b.id < 0) detections.push_back(b.box);
      }
      score.people_detections += static_cast<int>(detections.size());
      for (const cv::Rect2d& d : detections) {
        bool on_a_person = false;
        for (const PersonBox& t : people) on_a_person |= (d & t.box).area() >= 0.2 * d.area();
        score.people_false += on_a_person ? 0 : 1;
      }
      for (size_t i = 0; i < people.size(); ++i) {
        if (people_pixels[i] < kPersonMinPixels || people_range_m[i] < kPersonMinRangeM ||
            people_range_m[i] > kPersonMaxRangeM) {
          continue;
        }
        ++score.people_visible;
        bool found = false;
        for (const cv::Rect2d& d : detections) {
          found |= (d & people[i].box).area() >= 0.5 * std::min(d.area(), people[i].box.area());
        }
        if (found) {
          ++score.people_found;
        } else {
          char text[120];
          std::snprintf(text, sizeof(text), "frame %d: person %d (%d px, %.1f m)", k, people[i].id,
                        people_pixels[i], people_range_m[i]);
          score.people_missed.push_back(text);
        }
      }
      // Lines against the true walls, placed with the true pose.
      std::vector<int> matched;
      for (const WallSegment& line : (*r)->lines.lines) {
        const Eigen::Vector3d a =
            world_from_base * Eigen::Vector3d(line.start.x(), line.start.y(), 0);
        const Eigen::Vector3d b = world_from_base * Eigen::Vector3d(line.end.x(), line.end.y(), 0);
        auto match = MatchSegmentToWalls(a.head<2>(), b.head<2>(), walls);
        if (!match) continue;
        score.wall_angle_errors_deg.push_back(match->angle_error_deg);
        matched.push_back(match->wall_index);
      }
      const PolarScan& scan = (*r)->scan;
      for (const WallVisibility& v : VisibleWalls(true_base, scan.fov_min_rad, scan.fov_max_rad,
                                                  scan.resolution_rad, 4.5, walls, occluders)) {
        if (v.visible_length_m < kVisibleWallMinLengthM ||
            v.rays < kVisibleWallMinRayFraction * scan.rays_cast) {
          continue;
        }
        ++score.visible_walls;
        if (std::find(matched.begin(), matched.end(), v.wall_index) != matched.end()) {
          ++score.found_walls;
        } else {
          char text[120];
          std::snprintf(text, sizeof(text), "frame %d: wall %d (%.1f m, %d rays, %zu lines)", k,
                        walls[v.wall_index].id, v.visible_length_m, v.rays,
                        (*r)->lines.lines.size());
          score.missed.push_back(text);
        }
      }
    }
  }
  for (size_t c = 0; c < configs.size(); ++c) {
    CorridorScore& score = scores[c];
    const MappingFrameProcessor& p = *processors[c];
    std::vector<double> est_heading;
    std::vector<Eigen::Vector2d> est_positions;
    for (const Pose2d& pose : p.trajectory()) {
      est_heading.push_back(pose.heading_rad);
      est_positions.push_back(pose.position());
    }
    score.heading = ComputeHeadingErrors(est_heading, true_heading);
    if (!score.wall_angle_errors_deg.empty()) {
      std::vector<double> e = score.wall_angle_errors_deg;
      std::nth_element(e.begin(), e.begin() + e.size() / 2, e.end());
      score.wall_angle_error_deg_median = e[e.size() / 2];
    }
    const Pose2d truth_from_estimate = AlignSe2(est_positions, true_positions);
    score.map = CompareMapWithWalls(p.map(), walls, truth_from_estimate, kMapToleranceCells);
    score.map_all_obstacles =
        CompareMapWithWalls(p.map(), obstacles, truth_from_estimate, kMapToleranceCells);
    score.resets = static_cast<int>(p.reset_log().size());
    score.odometry_failures = p.odometry_failures();
    MeasureDrift(p.trajectory(), true_positions, true_heading, &score);
    score.frames = simulator.frames();
  }
  return scores;
}

}  // namespace sightline::testing
