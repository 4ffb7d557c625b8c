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

// One adjustment: the window's poses, the points and their observations.
struct Problem {
  const RectifiedStereoCamera* camera = nullptr;
  int fixed = 1;        // Frames [0, fixed) hold the gauge; the others are adjusted.
  double huber_px = 0;  // Robust weight threshold.
  std::vector<Eigen::Isometry3d> poses;    // camera_from_world of each window frame.
  std::vector<Eigen::Vector3d> points;     // World points.
  std::vector<Edge> edges;                 // Usable observations of the points.
  std::vector<std::vector<int>> edges_of;  // Edges grouped by point, for the Schur complement.
  std::vector<unsigned char> active;       // Per edge: not dropped as an outlier.
};

// The Gauss-Newton system of one iteration: the free poses' block, each point's block, and
// the pose-point coupling of every edge.
struct NormalEquations {
  Eigen::MatrixXd H;
  Eigen::VectorXd b;
  std::vector<Eigen::Matrix3d> point_hessian;
  std::vector<Eigen::Vector3d> point_gradient;
  std::vector<Matrix63> coupling;  // J_pose^T W J_point per edge.
};

// Reprojection error of edge e at poses T and points X [px]; false behind the camera.
bool EdgeError(const Problem& p, const std::vector<Eigen::Isometry3d>& T,
               const std::vector<Eigen::Vector3d>& X, size_t e, double* error) {
  const Edge& edge = p.edges[e];
  Eigen::Vector3d q;
  if (!Project(*p.camera, T[static_cast<size_t>(edge.frame)] * X[static_cast<size_t>(edge.point)],
               &q, nullptr)) {
    return false;
  }
  *error = (q - edge.measured).norm();
  return true;
}

// Robust cost of the active edges at poses T and points X; *rms (optional) gets their RMS error.
double TotalCost(const Problem& p, const std::vector<Eigen::Isometry3d>& T,
                 const std::vector<Eigen::Vector3d>& X, double* rms) {
  const double k = p.huber_px;
  double cost = 0, squared = 0;
  int used = 0;
  for (size_t e = 0; e < p.edges.size(); ++e) {
    if (!p.active[e]) continue;
    const Edge& edge = p.edges[e];
    double err = 0;
    if (!EdgeError(p, T, X, e, &err)) {
      cost += edge.weight * 2 * k * 1e3;  // Behind the camera: a large, finite penalty.
      continue;
    }
    cost += edge.weight * HuberCost(err, k);
    squared += err * err;
    ++used;
  }
  if (rms) *rms = used ? std::sqrt(squared / used) : 0;
  return cost;
}

// Deactivates the observations that still disagree (a track slid along an edge, a walking
// person); returns how many.
int DropOutliers(double max_error_px, Problem* p) {
  int dropped = 0;
  for (size_t e = 0; e < p->edges.size(); ++e) {
    if (!p->active[e]) continue;
    double err = 0;
    if (!EdgeError(*p, p->poses, p->points, e, &err) || err > max_error_px) {
      p->active[e] = 0;
      ++dropped;
    }
  }
  return dropped;
}

// Linearises every active edge at the current poses and points.
NormalEquations BuildNormalEquations(const Problem& p) {
  const int fixed = p.fixed;
  const int dim = 6 * (static_cast<int>(p.poses.size()) - fixed);
  const double k = p.huber_px;
  NormalEquations eq;
  eq.H = Eigen::MatrixXd::Zero(dim, dim);
  eq.b = Eigen::VectorXd::Zero(dim);
  eq.point_hessian.resize(p.points.size());
  eq.point_gradient.resize(p.points.size());
  eq.coupling.assign(p.edges.size(), Matrix63::Zero());
  for (size_t pi = 0; pi < p.points.size(); ++pi) {
    Eigen::Matrix3d Hll = Eigen::Matrix3d::Zero();
    Eigen::Vector3d bl = Eigen::Vector3d::Zero();
    for (int e : p.edges_of[pi]) {
      if (!p.active[static_cast<size_t>(e)]) continue;
      const Edge& edge = p.edges[static_cast<size_t>(e)];
      const Eigen::Isometry3d& T = p.poses[static_cast<size_t>(edge.frame)];
      const Eigen::Vector3d xc = T * p.points[pi];
      Eigen::Vector3d q;
      Eigen::Matrix3d Jproj;
      if (!Project(*p.camera, xc, &q, &Jproj)) continue;
      const Eigen::Vector3d r = q - edge.measured;
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
      eq.H.block<6, 6>(o, o) += Hpp;
      eq.b.segment<6>(o).noalias() -= JpW * r;
      eq.coupling[static_cast<size_t>(e)].noalias() = JpW * Jl;
    }
    eq.point_hessian[pi] = Hll;
    eq.point_gradient[pi] = bl;
  }
  return eq;
}

// The damped system reduced to the poses (Schur complement of the points): *S (its lower
// triangle; the upper one is not kept up to date) and *rhs, and
// each point's inverted damped block.
void ReducedSystem(const Problem& p, const NormalEquations& eq, double lambda, Eigen::MatrixXd* S,
                   Eigen::VectorXd* rhs, std::vector<Eigen::Matrix3d>* inverse) {
  const int fixed = p.fixed;
  const int dim = static_cast<int>(eq.H.rows());
  *S = eq.H;
  for (int d = 0; d < dim; ++d) (*S)(d, d) += lambda * std::max(eq.H(d, d), 1e-6);
  *rhs = eq.b;
  inverse->resize(p.points.size());
  for (size_t pi = 0; pi < p.points.size(); ++pi) {
    Eigen::Matrix3d Hll = eq.point_hessian[pi];
    for (int d = 0; d < 3; ++d) Hll(d, d) += lambda * std::max(Hll(d, d), 1e-6) + 1e-9;
    (*inverse)[pi] = Hll.inverse();
    const Eigen::Vector3d v = (*inverse)[pi] * eq.point_gradient[pi];
    const std::vector<int>& es = p.edges_of[pi];
    for (size_t a = 0; a < es.size(); ++a) {
      const Edge& ea = p.edges[static_cast<size_t>(es[a])];
      if (!p.active[static_cast<size_t>(es[a])] || ea.frame < fixed) continue;
      const Matrix63& Wa = eq.coupling[static_cast<size_t>(es[a])];
      const Matrix63 WaInv = (Wa * (*inverse)[pi]).eval();
      const int oa = 6 * (ea.frame - fixed);
      rhs->segment<6>(oa).noalias() -= Wa * v;
      // S is symmetric and its LDLT reads only the lower triangle: each pair's block is
      // subtracted there (transposed when it lies above the diagonal), the upper one is left.
      for (size_t c = a; c < es.size(); ++c) {
        const Edge& ec = p.edges[static_cast<size_t>(es[c])];
        if (!p.active[static_cast<size_t>(es[c])] || ec.frame < fixed) continue;
        const int oc = 6 * (ec.frame - fixed);
        const Matrix63& Wc = eq.coupling[static_cast<size_t>(es[c])];
        if (oc > oa) {
          S->block<6, 6>(oc, oa).noalias() -= Wc * WaInv.transpose();
        } else {
          S->block<6, 6>(oa, oc).noalias() -= WaInv * Wc.transpose();
        }
      }
    }
  }
}

// One Levenberg-Marquardt step with damping `lambda`: the moved poses and points and the step's
// length. False when the solution is not finite.
bool DampedStep(const Problem& p, const NormalEquations& eq, double lambda,
                std::vector<Eigen::Isometry3d>* new_poses, std::vector<Eigen::Vector3d>* new_points,
                double* step) {
  const int fixed = p.fixed;
  Eigen::MatrixXd S;
  Eigen::VectorXd rhs;
  std::vector<Eigen::Matrix3d> inverse;
  ReducedSystem(p, eq, lambda, &S, &rhs, &inverse);
  const Eigen::VectorXd dp = S.ldlt().solve(rhs);  // Reads S's lower triangle only.
  if (!dp.allFinite()) return false;
  *new_poses = p.poses;
  for (int fi = fixed; fi < static_cast<int>(p.poses.size()); ++fi) {
    (*new_poses)[static_cast<size_t>(fi)] =
        Update(p.poses[static_cast<size_t>(fi)], dp.segment<6>(6 * (fi - fixed)));
  }
  *new_points = p.points;
  for (size_t pi = 0; pi < p.points.size(); ++pi) {
    Eigen::Vector3d g = eq.point_gradient[pi];
    for (int e : p.edges_of[pi]) {
      const Edge& edge = p.edges[static_cast<size_t>(e)];
      if (!p.active[static_cast<size_t>(e)] || edge.frame < fixed) continue;
      g.noalias() -=
          eq.coupling[static_cast<size_t>(e)].transpose() * dp.segment<6>(6 * (edge.frame - fixed));
    }
    (*new_points)[pi] += inverse[pi] * g;
  }
  *step = dp.norm();
  return true;
}

// Levenberg-Marquardt over the free poses and the points; drops outliers halfway.
void Optimize(const WindowBundleOptions& options, Problem* p, WindowBundleSummary* s) {
  double lambda = 1e-4;
  double cost = TotalCost(*p, p->poses, p->points, &s->initial_rms_px);
  const int drop_after = std::max(1, options.max_iterations / 2);
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    if (iteration == drop_after) {
      s->dropped += DropOutliers(options.max_error_px, p);
      cost = TotalCost(*p, p->poses, p->points, nullptr);
    }
    ++s->iterations;
    const NormalEquations eq = BuildNormalEquations(*p);
    // Try steps with growing damping until the cost falls.
    bool improved = false;
    for (int attempt = 0; attempt < 6 && !improved; ++attempt) {
      std::vector<Eigen::Isometry3d> new_poses;
      std::vector<Eigen::Vector3d> new_points;
      double step = 0;
      if (!DampedStep(*p, eq, lambda, &new_poses, &new_points, &step)) {
        lambda *= 10;
        continue;
      }
      const double new_cost = TotalCost(*p, new_poses, new_points, nullptr);
      if (new_cost < cost) {
        improved = true;
        p->poses = std::move(new_poses);
        p->points = std::move(new_points);
        cost = new_cost;
        lambda = std::max(lambda / 3, 1e-7);
        if (step < 1e-8) iteration = options.max_iterations;  // Converged.
      } else {
        lambda *= 5;
      }
    }
    if (!improved) break;
  }
  TotalCost(*p, p->poses, p->points, &s->final_rms_px);
}

// How often a track is seen usable in the window.
struct Seen {
  int count = 0;
  bool adjusted = false;  // In a frame whose pose is adjusted.
};

// Usable sightings of every track in the window's frames (WindowBundleAdjuster::Frame).
template <typename Frames>
std::unordered_map<int64_t, Seen> CountSightings(const Frames& frames, int fixed) {
  std::unordered_map<int64_t, Seen> seen;
  for (int fi = 0; fi < static_cast<int>(frames.size()); ++fi) {
    const auto& f = frames[static_cast<size_t>(fi)];
    for (size_t i = 0; i < f.observations.size(); ++i) {
      if (!f.usable[i]) continue;
      Seen& t = seen[f.observations[i].track_id];
      ++t.count;
      t.adjusted = t.adjusted || fi >= fixed;
    }
  }
  return seen;
}

// Points: tracks with at least two usable observations, one of them in an adjusted frame; each
// starts where its largest-disparity observation (best depth) puts it. Fills p->points and
// p->edges.
template <typename Frames>
void CollectPoints(const Frames& frames, const WindowBundleOptions& options,
                   double disparity_offset_px, Problem* p) {
  const RectifiedStereoCamera& camera = *p->camera;
  std::unordered_map<int64_t, Seen> seen = CountSightings(frames, p->fixed);
  std::unordered_map<int64_t, int> point_of;
  std::vector<double> best_disparity;
  for (int fi = 0; fi < static_cast<int>(frames.size()); ++fi) {
    const auto& f = frames[static_cast<size_t>(fi)];
    for (size_t i = 0; i < f.observations.size(); ++i) {
      const TrackObservation& o = f.observations[i];
      if (!f.usable[i]) continue;
      const Seen& t = seen[o.track_id];
      if (t.count < 2 || !t.adjusted) continue;
      const double right_u = o.right_u - disparity_offset_px;
      const double disparity = o.left_u - right_u;
      if (!(disparity > 0)) continue;
      auto [it, inserted] = point_of.emplace(o.track_id, static_cast<int>(p->points.size()));
      const Eigen::Vector3d world =
          f.camera_from_world.inverse() * camera.Triangulate(o.left_u, o.v, disparity);
      if (inserted) {
        p->points.push_back(world);
        best_disparity.push_back(disparity);
      } else if (disparity > best_disparity[static_cast<size_t>(it->second)]) {
        p->points[static_cast<size_t>(it->second)] = world;
        best_disparity[static_cast<size_t>(it->second)] = disparity;
      }
      const double weight = options.center_weighting ? CenterWeight(camera, o.left_u) : 1.0;
      p->edges.push_back(
          {fi, it->second, Eigen::Vector3d(o.left_u, o.v, right_u), static_cast<int>(i), weight});
    }
  }
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
  AppendFrame(world_from_camera, std::move(observations));
  const int n = static_cast<int>(frames_.size());
  // Frames [0, fixed) hold the gauge; the newest options_.frames - 1 are adjusted.
  Problem problem;
  problem.camera = &camera;
  problem.fixed = std::max(1, n - (options_.frames - 1));
  problem.huber_px = options_.huber_px;
  s.frames = std::min(n, options_.frames);
  s.fixed_frames = n - s.frames;
  frames_.back().keep =
      n < 2 || EnoughMotion(camera, frames_[static_cast<size_t>(n - 2)], frames_.back());
  if (n < 2) return world_from_camera;

  CollectPoints(frames_, options_, disparity_offset_px, &problem);
  s.points = static_cast<int>(problem.points.size());
  s.observations = static_cast<int>(problem.edges.size());
  // Enough to constrain the free poses (6 each) many times over.
  if (problem.points.size() < 20) return world_from_camera;

  problem.edges_of.resize(problem.points.size());
  for (size_t e = 0; e < problem.edges.size(); ++e)
    problem.edges_of[static_cast<size_t>(problem.edges[e].point)].push_back(static_cast<int>(e));
  for (const Frame& f : frames_) problem.poses.push_back(f.camera_from_world);
  problem.active.assign(problem.edges.size(), 1);
  Optimize(options_, &problem, &s);

  // Keep the refined poses and forget dropped observations for the frames to come.
  for (int fi = 0; fi < n; ++fi)
    frames_[static_cast<size_t>(fi)].camera_from_world = problem.poses[static_cast<size_t>(fi)];
  for (size_t e = 0; e < problem.edges.size(); ++e) {
    if (!problem.active[e]) {
      frames_[static_cast<size_t>(problem.edges[e].frame)]
          .usable[static_cast<size_t>(problem.edges[e].observation)] = 0;
    }
  }
  s.adjusted = true;
  frames_.back().keep = EnoughMotion(camera, frames_[static_cast<size_t>(n - 2)], frames_.back());
  return problem.poses.back().inverse();
}

void WindowBundleAdjuster::AppendFrame(const Eigen::Isometry3d& world_from_camera,
                                       std::vector<TrackObservation> observations) {
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
}

}  // namespace sightline
