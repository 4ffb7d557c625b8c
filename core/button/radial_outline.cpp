#include "core/button/radial_outline.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace sightline {
namespace {

// Radial edge strength E(k, j) = |P(k, j + 1) - P(k, j - 1)| / 2 of the polar image P: one row
// per ray, one column per pixel of radius from min_radius - 1.
cv::Mat RadialEdges(const cv::Mat& grey, cv::Point2d centre, const RadialOutlineOptions& o) {
  // Only the disc the rays reach (and the blur's support) is blurred.
  const int reach = int(std::ceil(o.max_radius_px + 3 * o.blur_sigma_px)) + 2;
  const cv::Rect roi = cv::Rect(int(std::floor(centre.x)) - reach,
                                int(std::floor(centre.y)) - reach, 2 * reach + 1, 2 * reach + 1) &
                       cv::Rect(0, 0, grey.cols, grey.rows);
  centre -= cv::Point2d(roi.tl());
  cv::Mat smooth;
  if (o.blur_sigma_px > 0) {
    cv::GaussianBlur(grey(roi), smooth, cv::Size(0, 0), o.blur_sigma_px);
  } else {
    smooth = grey(roi);
  }
  const int steps = int(std::ceil(o.max_radius_px - o.min_radius_px)) + 3;
  cv::Mat map_x(o.rays, steps, CV_32F), map_y(o.rays, steps, CV_32F);
  for (int k = 0; k < o.rays; ++k) {
    const double a = 2 * M_PI * k / o.rays, c = std::cos(a), s = std::sin(a);
    for (int j = 0; j < steps; ++j) {
      const double r = o.min_radius_px - 1 + j;
      map_x.at<float>(k, j) = float(centre.x + r * c);
      map_y.at<float>(k, j) = float(centre.y + r * s);
    }
  }
  cv::Mat polar;
  cv::remap(smooth, polar, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  polar.convertTo(polar, CV_32F);
  cv::Mat edges(o.rays, steps, CV_32F, cv::Scalar(0));
  for (int k = 0; k < o.rays; ++k) {
    const float* p = polar.ptr<float>(k);
    float* e = edges.ptr<float>(k);
    for (int j = 1; j + 1 < steps; ++j) e[j] = 0.5f * std::abs(p[j + 1] - p[j - 1]);
  }
  return edges;
}

// The closed path of strongest edges with every ray's radius index in [lo, hi]: two laps of
// the dynamic programme around the rays, the second lap's path read back (it no longer
// depends on where the first lap started). Returns the radius index per ray.
std::vector<int> StrongestPath(const cv::Mat& edges, int lo, int hi, double min_radius) {
  const int rays = edges.rows, width = hi - lo + 1;
  constexpr double kJumpCost = 0.1;  // Per pixel of radius change between neighbouring rays.
  std::vector<float> score(width, 0.f), next(width);
  std::vector<int> from(size_t(2 * rays) * width, 0);
  std::vector<int> reach(width);
  for (int j = 0; j < width; ++j) {
    // A ray may move by up to 0.3 radii at 64 rays: the corners of a 3:1 bar.
    reach[j] = std::max(1, int(std::ceil(0.3 * (min_radius - 1 + lo + j) * 64 / rays)));
  }
  for (int k = 0; k < 2 * rays; ++k) {
    const float* e = edges.ptr<float>(k % rays);
    for (int j = 0; j < width; ++j) {
      float best = -1e30f;
      int arg = j;
      for (int d = std::max(0, j - reach[j]); d <= std::min(width - 1, j + reach[j]); ++d) {
        const float v = score[d] - float(kJumpCost * std::abs(d - j));
        if (v > best) best = v, arg = d;
      }
      next[j] = best + e[lo + j];
      from[size_t(k) * width + j] = arg;
    }
    score.swap(next);
  }
  int j = int(std::max_element(score.begin(), score.end()) - score.begin());
  std::vector<int> path(rays);
  for (int k = 2 * rays - 1; k >= rays; --k) {
    path[k - rays] = lo + j;
    j = from[size_t(k) * width + j];
  }
  return path;
}

}  // namespace

std::vector<RadialOutline> RadialOutlines(const cv::Mat& grey, cv::Point2d centre,
                                          const RadialOutlineOptions& o) {
  std::vector<RadialOutline> out;
  if (grey.empty() || grey.type() != CV_8UC1 || o.rays < 8 ||
      !(o.max_radius_px > o.min_radius_px && o.min_radius_px >= 1) ||
      !(centre.x >= 0 && centre.y >= 0 && centre.x < grey.cols && centre.y < grey.rows)) {
    return out;
  }
  const cv::Mat edges = RadialEdges(grey, centre, o);
  const int last = edges.cols - 2;
  std::vector<float> values;
  for (double a = o.min_radius_px; a < o.max_radius_px; a *= 1.6) {
    const int lo = std::max(1, int(std::lround(a - o.min_radius_px)) + 1);
    const int hi = std::min(last, int(std::lround(a * o.band_ratio - o.min_radius_px)) + 1);
    if (hi - lo < 2) continue;
    const std::vector<int> path = StrongestPath(edges, lo, hi, o.min_radius_px);
    values.resize(hi - lo + 1);
    int on_edge = 0;
    for (int k = 0; k < o.rays; ++k) {
      const float* row = edges.ptr<float>(k);
      std::copy(row + lo, row + hi + 1, values.begin());
      std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
      const float e = row[path[k]];
      on_edge += e >= std::max(o.min_edge, o.min_contrast * values[values.size() / 2]);
    }
    RadialOutline outline;
    outline.support = double(on_edge) / o.rays;
    if (outline.support < o.min_support) continue;
    outline.points.resize(o.rays);
    for (int k = 0; k < o.rays; ++k) {
      const double angle = 2 * M_PI * k / o.rays, r = o.min_radius_px - 1 + path[k];
      outline.points[k] = cv::Point(int(std::lround(centre.x + r * std::cos(angle))),
                                    int(std::lround(centre.y + r * std::sin(angle))));
    }
    out.push_back(std::move(outline));
  }
  return out;
}

}  // namespace sightline
