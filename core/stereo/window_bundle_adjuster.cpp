#include "core/stereo/window_bundle_adjuster.h"

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/stereo/option_check.h"
#include "core/stereo/reprojection.h"

namespace sightline {

using stereo_internal::CenterWeight;
using stereo_internal::Invalid;
using stereo_internal::Skew;

bool WindowBundleOptions::IsValid(std::string* error) const {
  if (frames < 2 || frames > 30) return Invalid(error, "stereo.window.frames must lie in [2, 30]");
  if (fixed_frames < 0 || fixed_frames > 30) {
    return Invalid(error, "stereo.window.fixed_frames must lie in [0, 30]");
  }
  if (!(min_parallax >= 0 && min_parallax <= 1)) {
    return Invalid(error, "stereo.window.min_parallax must lie in [0, 1]");
  }
  if (!(min_rotation_deg >= 0 && min_rotation_deg <= 180)) {
    return Invalid(error, "stereo.window.min_rotation_deg must lie in [0, 180]");
  }
  if (max_iterations < 1 || max_iterations > 100) {
    return Invalid(error, "stereo.window.max_iterations must lie in [1, 100]");
  }
  if (!(huber_px > 0)) return Invalid(error, "stereo.window.huber_px must be > 0");
  if (!(max_error_px > 0)) return Invalid(error, "stereo.window.max_error_px must be > 0");
  if (!(min_disparity_px >= 0))
    return Invalid(error, "stereo.window.min_disparity_px must be >= 0");
  return true;
}

OptionTable<WindowBundleOptions> WindowBundleOptions::Describe() {
  using O = WindowBundleOptions;
  return OptionTable<O>("stereo.window")
      .Bool("enabled", &O::enabled,
            "Refine the last frames' poses and their tracks' points together on the stereo "
            "reprojection error (sliding-window bundle adjustment), so per-frame errors do not "
            "add up.")
      .Int("frames", &O::frames, "frames", 2, 30, 1,
           "Frames in the window; the oldest is held fixed.")
      .Int("fixed_frames", &O::fixed_frames, "frames", 0, 30, 1,
           "Frames that left the window keep constraining its points this long, with their "
           "poses held fixed, so the window's drift does not restart at every slide.")
      .Double("min_parallax", &O::min_parallax, "", 0, 1, 0.005,
              "A frame stays in the window when the camera moved this fraction of its points' "
              "median depth since the previous one that stayed (0 = every frame stays); otherwise "
              "the next frame replaces it.")
      .Double("min_rotation_deg", &O::min_rotation_deg, "deg", 0, 180, 0.5,
              "... or when it turned at least this much.")
      .Int("max_iterations", &O::max_iterations, "", 1, 100, 1,
           "Levenberg-Marquardt iterations per frame.")
      .Double("huber_px", &O::huber_px, "px", 0.01, 100, 0.05,
              "Huber threshold of the robust weight of an observation's reprojection error.")
      .Double("max_error_px", &O::max_error_px, "px", 0.1, 100, 0.1,
              "Observations reprojecting worse than this are dropped from the window.")
      .Bool("center_weighting", &O::center_weighting,
            "Weight observations by 1 / (|u - cx| / cx + 0.05) (libviso2), favouring the centre, "
            "as the two-frame refinement does.")
      .Double("min_disparity_px", &O::min_disparity_px, "px", 0, 100, 0.1,
              "Observations with a smaller disparity (no usable depth) are left out.");
}

namespace {

// One usable observation of an adjusted point.
struct Edge {
  int frame;                 // Window index.
  int point;                 // Adjusted point index.
  Eigen::Vector3d measured;  // left u, v, right u.
  int observation;           // Index into the frame's observations.
  double weight;             // Of the squared error, before the robust weight.
};

using Matrix36 = Eigen::Matrix<double, 3, 6>;
using Matrix63 = Eigen::Matrix<double, 6, 3>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

// Predicted (left u, v, right u) of camera point x, and its Jacobian with respect to x.
// False when the point is not in front of the camera.
bool Project(const RectifiedStereoCamera& c, const Eigen::Vector3d& x, Eigen::Vector3d* p,
             Eigen::Matrix3d* J) {
  if (x.z() < 1e-3) return false;
  const double iz = 1.0 / x.z();
  const double fx = c.f * iz;
  (*p) << c.f * x.x() * iz + c.cx, c.f * x.y() * iz + c.cy,
      c.f * (x.x() - c.baseline_m) * iz + c.cx;
  if (J) {
    *J << fx, 0, -fx * x.x() * iz,  //
        0, fx, -fx * x.y() * iz,    //
        fx, 0, -fx * (x.x() - c.baseline_m) * iz;
  }
  return true;
}

double HuberWeight(double error, double k) { return error <= k ? 1.0 : k / error; }
double HuberCost(double error, double k) {
  return error <= k ? error * error : 2 * k * error - k * k;
}

// T <- Exp(delta) * T with delta = (rotation vector, translation).
Eigen::Isometry3d Update(const Eigen::Isometry3d& t, const Vector6& delta) {
  const Eigen::Vector3d w = delta.head<3>();
  const double angle = w.norm();
  Eigen::Isometry3d d = Eigen::Isometry3d::Identity();
  if (angle > 0) d.linear() = Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
  d.translation() = delta.tail<3>();
  return d * t;
}

}  // namespace

bool WindowBundleAdjuster::EnoughMotion(const RectifiedStereoCamera& camera, const Frame& from,
                                        const Frame& to) const {
  const Eigen::Isometry3d motion = to.camera_from_world * from.camera_from_world.inverse();
  if (Eigen::AngleAxisd(motion.rotation()).angle() * 180.0 / M_PI >= options_.min_rotation_deg) {
    return true;
  }
  std::vector<double> depths;
  depths.reserve(to.observations.size());
  for (size_t i = 0; i < to.observations.size(); ++i) {
    const TrackObservation& o = to.observations[i];
    if (to.usable[i]) depths.push_back(camera.f * camera.baseline_m / (o.left_u - o.right_u));
  }
  if (depths.empty()) return true;
  std::nth_element(depths.begin(), depths.begin() + depths.size() / 2, depths.end());
  return motion.translation().norm() >= options_.min_parallax * depths[depths.size() / 2];
}

Eigen::Isometry3d WindowBundleAdjuster::Add(const RectifiedStereoCamera& camera,
                                            const Eigen::Isometry3d& world_from_camera,
                                            std::vector<TrackObservation> observations,
                                            WindowBundleSummary* summary,
                                            double disparity_offset_px) {
  WindowBundleSummary local;
  WindowBundleSummary& s = summary ? *summary : local;
  s = WindowBundleSummary();
  Frame frame;
  frame.camera_from_world = world_from_camera.inverse();
  frame.usable.resize(observations.size());
  for (size_t i = 0; i < observations.size(); ++i) {
    const TrackObservation& o = observations[i];
    frame.usable[i] = std::isfinite(o.left_u) && std::isfinite(o.v) && std::isfinite(o.right_u) &&
                      o.left_u - o.right_u >= options_.min_disparity_px;
  }
  frame.observations = std::move(observations);
  if (!frames_.empty() && !frames_.back().keep) frames_.pop_back();
  frames_.push_back(std::move(frame));
  while (static_cast<int>(frames_.size()) > options_.frames + options_.fixed_frames) {
    frames_.pop_front();
  }
  const int n = static_cast<int>(frames_.size());
  // Frames [0, fixed) hold the gauge; the newest options_.frames - 1 are adjusted.
  const int fixed = std::max(1, n - (options_.frames - 1));
  s.frames = std::min(n, options_.frames);
  s.fixed_frames = n - s.frames;
  frames_.back().keep =
      n < 2 || EnoughMotion(camera, frames_[static_cast<size_t>(n - 2)], frames_.back());
  if (n < 2) return world_from_camera;

  // Points: tracks with at least two usable observations, one of them in an adjusted frame.
  struct Seen {
    int count = 0;
    bool adjusted = false;  // In a frame whose pose is adjusted.
  };
  std::unordered_map<int64_t, Seen> seen;
  for (int fi = 0; fi < n; ++fi) {
    const Frame& f = frames_[static_cast<size_t>(fi)];
    for (size_t i = 0; i < f.observations.size(); ++i) {
      if (!f.usable[i]) continue;
      Seen& t = seen[f.observations[i].track_id];
      ++t.count;
      t.adjusted = t.adjusted || fi >= fixed;
    }
  }
  std::unordered_map<int64_t, int> point_of;
  std::vector<Eigen::Vector3d> points;
  std::vector<double> best_disparity;
  std::vector<Edge> edges;
  for (int fi = 0; fi < n; ++fi) {
    const Frame& f = frames_[static_cast<size_t>(fi)];
    for (size_t i = 0; i < f.observations.size(); ++i) {
      const TrackObservation& o = f.observations[i];
      if (!f.usable[i]) continue;
      const Seen& t = seen[o.track_id];
      if (t.count < 2 || !t.adjusted) continue;
      const double right_u = o.right_u - disparity_offset_px;
      const double disparity = o.left_u - right_u;
      if (!(disparity > 0)) continue;
      auto [it, inserted] = point_of.emplace(o.track_id, static_cast<int>(points.size()));
      // Each point starts where its largest-disparity observation (best depth) puts it.
      const Eigen::Vector3d world =
          f.camera_from_world.inverse() * camera.Triangulate(o.left_u, o.v, disparity);
      if (inserted) {
        points.push_back(world);
        best_disparity.push_back(disparity);
      } else if (disparity > best_disparity[static_cast<size_t>(it->second)]) {
        points[static_cast<size_t>(it->second)] = world;
        best_disparity[static_cast<size_t>(it->second)] = disparity;
      }
      const double weight = options_.center_weighting ? CenterWeight(camera, o.left_u) : 1.0;
      edges.push_back(
          {fi, it->second, Eigen::Vector3d(o.left_u, o.v, right_u), static_cast<int>(i), weight});
    }
  }
  s.points = static_cast<int>(points.size());
  s.observations = static_cast<int>(edges.size());
  // Enough to constrain the free poses (6 each) many times over.
  if (points.size() < 20) return world_from_camera;

  // Edges grouped by point, for the Schur complement.
  std::vector<std::vector<int>> edges_of(points.size());
  for (size_t e = 0; e < edges.size(); ++e)
    edges_of[static_cast<size_t>(edges[e].point)].push_back(static_cast<int>(e));

  std::vector<Eigen::Isometry3d> poses;
  for (const Frame& f : frames_) poses.push_back(f.camera_from_world);
  std::vector<unsigned char> active(edges.size(), 1);
  const double k = options_.huber_px;

  // Reprojection error of edge e at poses T and points X [px]; false behind the camera.
  auto edge_error = [&](const std::vector<Eigen::Isometry3d>& T,
                        const std::vector<Eigen::Vector3d>& X, size_t e, double* error) {
    const Edge& edge = edges[e];
    Eigen::Vector3d p;
    if (!Project(camera, T[static_cast<size_t>(edge.frame)] * X[static_cast<size_t>(edge.point)],
                 &p, nullptr)) {
      return false;
    }
    *error = (p - edge.measured).norm();
    return true;
  };
  auto total_cost = [&](const std::vector<Eigen::Isometry3d>& T,
                        const std::vector<Eigen::Vector3d>& X, double* rms) {
    double cost = 0, squared = 0;
    int used = 0;
    for (size_t e = 0; e < edges.size(); ++e) {
      if (!active[e]) continue;
      const Edge& edge = edges[e];
      double err = 0;
      if (!edge_error(T, X, e, &err)) {
        cost += edge.weight * 2 * k * 1e3;  // Behind the camera: a large, finite penalty.
        continue;
      }
      cost += edge.weight * HuberCost(err, k);
      squared += err * err;
      ++used;
    }
    if (rms) *rms = used ? std::sqrt(squared / used) : 0;
    return cost;
  };

  const int free_frames = n - fixed;
  const int dim = 6 * free_frames;
  double lambda = 1e-4;
  double cost = total_cost(poses, points, &s.initial_rms_px);
  const int drop_after = std::max(1, options_.max_iterations / 2);
  for (int iteration = 0; iteration < options_.max_iterations; ++iteration) {
    if (iteration == drop_after) {
      // Observations that still disagree (a track slid along an edge, a walking person).
      for (size_t e = 0; e < edges.size(); ++e) {
        if (!active[e]) continue;
        double err = 0;
        if (!edge_error(poses, points, e, &err) || err > options_.max_error_px) {
          active[e] = 0;
          ++s.dropped;
        }
      }
      cost = total_cost(poses, points, nullptr);
    }
    ++s.iterations;
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(dim, dim);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(dim);
    std::vector<Eigen::Matrix3d> point_hessian(points.size());
    std::vector<Eigen::Vector3d> point_gradient(points.size());
    std::vector<Matrix63> coupling(edges.size(), Matrix63::Zero());  // J_pose^T W J_point.
    for (size_t pi = 0; pi < points.size(); ++pi) {
      Eigen::Matrix3d Hll = Eigen::Matrix3d::Zero();
      Eigen::Vector3d bl = Eigen::Vector3d::Zero();
      for (int e : edges_of[pi]) {
        if (!active[static_cast<size_t>(e)]) continue;
        const Edge& edge = edges[static_cast<size_t>(e)];
        const Eigen::Isometry3d& T = poses[static_cast<size_t>(edge.frame)];
        const Eigen::Vector3d xc = T * points[pi];
        Eigen::Vector3d p;
        Eigen::Matrix3d Jproj;
        if (!Project(camera, xc, &p, &Jproj)) continue;
        const Eigen::Vector3d r = p - edge.measured;
        const double w = edge.weight * HuberWeight(r.norm(), k);
        const Eigen::Matrix3d Jl = Jproj * T.linear();
        const Eigen::Matrix3d JlW = w * Jl.transpose();
        Hll.noalias() += JlW * Jl;
        bl.noalias() -= JlW * r;
        if (edge.frame < fixed) continue;
        Matrix36 Jp;
        Jp.leftCols<3>().noalias() = -Jproj * Skew(xc);
        Jp.rightCols<3>() = Jproj;
        const Matrix63 JpW = w * Jp.transpose();
        const int o = 6 * (edge.frame - fixed);
        const Eigen::Matrix<double, 6, 6> Hpp = JpW * Jp;
        H.block<6, 6>(o, o) += Hpp;
        b.segment<6>(o).noalias() -= JpW * r;
        coupling[static_cast<size_t>(e)].noalias() = JpW * Jl;
      }
      point_hessian[pi] = Hll;
      point_gradient[pi] = bl;
    }

    // Try steps with growing damping until the cost falls.
    bool improved = false;
    for (int attempt = 0; attempt < 6 && !improved; ++attempt) {
      Eigen::MatrixXd S = H;
      for (int d = 0; d < dim; ++d) S(d, d) += lambda * std::max(H(d, d), 1e-6);
      Eigen::VectorXd rhs = b;
      std::vector<Eigen::Matrix3d> inverse(points.size());
      for (size_t pi = 0; pi < points.size(); ++pi) {
        Eigen::Matrix3d Hll = point_hessian[pi];
        for (int d = 0; d < 3; ++d) Hll(d, d) += lambda * std::max(Hll(d, d), 1e-6) + 1e-9;
        inverse[pi] = Hll.inverse();
        const Eigen::Vector3d v = inverse[pi] * point_gradient[pi];
        const std::vector<int>& es = edges_of[pi];
        for (size_t a = 0; a < es.size(); ++a) {
          const Edge& ea = edges[static_cast<size_t>(es[a])];
          if (!active[static_cast<size_t>(es[a])] || ea.frame < fixed) continue;
          const Matrix63& Wa = coupling[static_cast<size_t>(es[a])];
          const Matrix63 WaInv = (Wa * inverse[pi]).eval();
          const int oa = 6 * (ea.frame - fixed);
          rhs.segment<6>(oa).noalias() -= Wa * v;
          // S is symmetric: the blocks at and above the diagonal, mirrored below.
          for (size_t c = a; c < es.size(); ++c) {
            const Edge& ec = edges[static_cast<size_t>(es[c])];
            if (!active[static_cast<size_t>(es[c])] || ec.frame < fixed) continue;
            const int oc = 6 * (ec.frame - fixed);
            const Eigen::Matrix<double, 6, 6> block =
                WaInv * coupling[static_cast<size_t>(es[c])].transpose();
            S.block<6, 6>(oa, oc) -= block;
            if (oc != oa) S.block<6, 6>(oc, oa) -= block.transpose();
          }
        }
      }
      const Eigen::VectorXd dp = S.ldlt().solve(rhs);
      if (!dp.allFinite()) {
        lambda *= 10;
        continue;
      }
      std::vector<Eigen::Isometry3d> new_poses = poses;
      for (int fi = fixed; fi < n; ++fi) {
        new_poses[static_cast<size_t>(fi)] =
            Update(poses[static_cast<size_t>(fi)], dp.segment<6>(6 * (fi - fixed)));
      }
      std::vector<Eigen::Vector3d> new_points = points;
      for (size_t pi = 0; pi < points.size(); ++pi) {
        Eigen::Vector3d g = point_gradient[pi];
        for (int e : edges_of[pi]) {
          const Edge& edge = edges[static_cast<size_t>(e)];
          if (!active[static_cast<size_t>(e)] || edge.frame < fixed) continue;
          g.noalias() -= coupling[static_cast<size_t>(e)].transpose() *
                         dp.segment<6>(6 * (edge.frame - fixed));
        }
        new_points[pi] += inverse[pi] * g;
      }
      const double new_cost = total_cost(new_poses, new_points, nullptr);
      if (new_cost < cost) {
        improved = true;
        const double step = dp.norm();
        poses = std::move(new_poses);
        points = std::move(new_points);
        cost = new_cost;
        lambda = std::max(lambda / 3, 1e-7);
        if (step < 1e-8) iteration = options_.max_iterations;  // Converged.
      } else {
        lambda *= 5;
      }
    }
    if (!improved) break;
  }
  total_cost(poses, points, &s.final_rms_px);

  // Keep the refined poses and forget dropped observations for the frames to come.
  for (int fi = 0; fi < n; ++fi)
    frames_[static_cast<size_t>(fi)].camera_from_world = poses[static_cast<size_t>(fi)];
  for (size_t e = 0; e < edges.size(); ++e) {
    if (!active[e]) {
      frames_[static_cast<size_t>(edges[e].frame)]
          .usable[static_cast<size_t>(edges[e].observation)] = 0;
    }
  }
  s.adjusted = true;
  frames_.back().keep = EnoughMotion(camera, frames_[static_cast<size_t>(n - 2)], frames_.back());
  return poses.back().inverse();
}

}  // namespace sightline
