// Radial outlines on drawn images: a thin or broken ring, a faint disc and a 3:1 bar are found
// where they are, a texture and a flat wall give nothing, moving the image moves the outline,
// and bad input gives no outline rather than a crash.
#include "core/button/radial_outline.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace sightline {
namespace {

// Mid-grey with Gaussian noise of `sigma` grey levels (fixed seed).
cv::Mat NoisyWall(double sigma, int seed = 1) {
  cv::Mat noise(240, 240, CV_32F);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::NORMAL, 0, sigma);
  cv::Mat wall;
  noise += 128;
  noise.convertTo(wall, CV_8U);
  return wall;
}

struct Shape {
  cv::Point2d centre;  // Of the outline's polygon.
  cv::Rect2d box;
};

Shape Describe(const RadialOutline& outline) {
  const cv::Moments m = cv::moments(outline.points);
  return {{m.m10 / m.m00, m.m01 / m.m00}, cv::boundingRect(outline.points)};
}

// Fraction of the outline's points within `tolerance` px of the true shape's boundary, drawn
// by `draw` into a mask of the image's size.
template <typename Draw>
double OnBoundary(const RadialOutline& outline, cv::Size size, Draw draw, double tolerance) {
  cv::Mat boundary(size, CV_8U, cv::Scalar(255));
  draw(boundary);  // Draws the boundary in 0.
  cv::Mat distance;
  cv::distanceTransform(boundary, distance, cv::DIST_L2, 3);
  int near = 0;
  for (const cv::Point& p : outline.points) {
    near += p.inside(cv::Rect(cv::Point(), size)) && distance.at<float>(p) <= tolerance;
  }
  return double(near) / outline.points.size();
}

// The outline whose box is nearest `box` (corner distances), as the detector would pick one
// band's among the others.
const RadialOutline* Nearest(const std::vector<RadialOutline>& outlines, const cv::Rect2d& box) {
  const RadialOutline* best = nullptr;
  double best_d = 1e9;
  for (const RadialOutline& o : outlines) {
    const cv::Rect2d b = Describe(o).box;
    const double d = cv::norm(b.tl() - box.tl()) + cv::norm(b.br() - box.br());
    if (d < best_d) best_d = d, best = &o;
  }
  return best;
}

TEST(RadialOutline, AThinRingIsFoundWhereItIs) {
  cv::Mat image = NoisyWall(3);
  cv::circle(image, {120, 118}, 25, cv::Scalar(80), 1, cv::LINE_AA);
  const auto outlines = RadialOutlines(image, {123, 116}, RadialOutlineOptions());
  const RadialOutline* ring = Nearest(outlines, cv::Rect2d(95, 93, 50, 50));
  ASSERT_NE(ring, nullptr);
  // A one-pixel ring has an edge on either side (1.5 px in and out after the blur); the
  // outline runs along one or the other, ray by ray.
  EXPECT_LT(cv::norm(Describe(*ring).centre - cv::Point2d(120, 118)), 2.0);
  const auto circle = [](cv::Mat& m) { cv::circle(m, {120, 118}, 25, cv::Scalar(0), 1); };
  EXPECT_GE(OnBoundary(*ring, image.size(), circle, 2.5), 0.95);
  EXPECT_GE(ring->support, 0.9);
}

TEST(RadialOutline, ARingWithAFifthOfItMissingStillCloses) {
  cv::Mat image = NoisyWall(3);
  cv::ellipse(image, {120, 120}, {30, 30}, 0, 20, 56, cv::Scalar(70), 1, cv::LINE_AA);
  cv::ellipse(image, {120, 120}, {30, 30}, 0, 92, 200, cv::Scalar(70), 1, cv::LINE_AA);
  cv::ellipse(image, {120, 120}, {30, 30}, 0, 236, 380, cv::Scalar(70), 1, cv::LINE_AA);
  const auto outlines = RadialOutlines(image, {120, 120}, RadialOutlineOptions());
  const RadialOutline* ring = Nearest(outlines, cv::Rect2d(90, 90, 60, 60));
  ASSERT_NE(ring, nullptr);
  EXPECT_LT(cv::norm(Describe(*ring).centre - cv::Point2d(120, 120)), 1.5);
  const auto circle = [](cv::Mat& m) { cv::circle(m, {120, 120}, 30, cv::Scalar(0), 1); };
  EXPECT_GE(OnBoundary(*ring, image.size(), circle, 2.0), 0.9);
}

TEST(RadialOutline, AFaintDiscIsFound) {
  cv::Mat image = NoisyWall(1.5);
  cv::Mat disc(image.size(), CV_8U, cv::Scalar(0));
  cv::circle(disc, {118, 122}, 20, cv::Scalar(20), cv::FILLED, cv::LINE_AA);
  image += disc;  // 20 grey levels brighter.
  const auto outlines = RadialOutlines(image, {118, 122}, RadialOutlineOptions());
  const RadialOutline* found = Nearest(outlines, cv::Rect2d(98, 102, 40, 40));
  ASSERT_NE(found, nullptr);
  EXPECT_LT(cv::norm(Describe(*found).centre - cv::Point2d(118, 122)), 1.0);
  const auto circle = [](cv::Mat& m) { cv::circle(m, {118, 122}, 20, cv::Scalar(0), 1); };
  EXPECT_GE(OnBoundary(*found, image.size(), circle, 1.5), 0.95);
}

TEST(RadialOutline, ABarThreeTimesAsWideAsHighIsFollowed) {
  cv::Mat image = NoisyWall(2);
  cv::rectangle(image, cv::Rect(90, 110, 60, 20), cv::Scalar(200), cv::FILLED);
  const auto outlines = RadialOutlines(image, {120, 120}, RadialOutlineOptions());
  const RadialOutline* bar = Nearest(outlines, cv::Rect2d(90, 110, 60, 20));
  ASSERT_NE(bar, nullptr);
  EXPECT_LT(cv::norm(Describe(*bar).centre - cv::Point2d(119.5, 119.5)), 1.5);
  const auto rectangle = [](cv::Mat& m) {
    cv::rectangle(m, cv::Rect(90, 110, 60, 20), cv::Scalar(0), 1);
  };
  EXPECT_GE(OnBoundary(*bar, image.size(), rectangle, 2.0), 0.85);
}

TEST(RadialOutline, TextureAndAFlatWallGiveNone) {
  // A perforated plate: holes 13-33 grey levels darker, 6 px apart, each a little off the grid
  // (with min_contrast 1 instead of 3 the strongest paths through it count as outlines).
  cv::Mat texture = NoisyWall(3, 7);
  cv::RNG rng(11);
  for (int y = 3; y < texture.rows; y += 6) {
    for (int x = 3; x < texture.cols; x += 6) {
      const double dx = rng.uniform(-1.0, 1.0);  // One draw per statement: a fixed order.
      const double dy = rng.uniform(-1.0, 1.0);
      const int grey = rng.uniform(95, 115);
      cv::circle(texture, cv::Point2d(x + dx, y + dy), 2, cv::Scalar(grey), cv::FILLED,
                 cv::LINE_AA);
    }
  }
  for (cv::Point2d centre : {cv::Point2d(120, 120), cv::Point2d(60, 170), cv::Point2d(170, 70)}) {
    EXPECT_TRUE(RadialOutlines(texture, centre, RadialOutlineOptions()).empty()) << centre;
    EXPECT_TRUE(RadialOutlines(NoisyWall(2), centre, RadialOutlineOptions()).empty()) << centre;
  }
}

// Moved by whole pixels, the image gives the outline moved by the same pixels: nothing is
// thresholded that a new pixel grid could make or break.
TEST(RadialOutline, MovingTheImageMovesTheOutline) {
  cv::Mat image = NoisyWall(2);
  cv::circle(image, {120, 120}, 18, cv::Scalar(60), 2, cv::LINE_AA);
  const cv::Rect2d ring_box(102, 102, 36, 36);
  const RadialOutline* base = nullptr;
  const auto outlines = RadialOutlines(image, {121, 119}, RadialOutlineOptions());
  base = Nearest(outlines, ring_box);
  ASSERT_NE(base, nullptr);
  const cv::Point2d c0 = Describe(*base).centre;
  for (cv::Point shift : {cv::Point(1, 0), cv::Point(0, 1), cv::Point(1, 1), cv::Point(-2, 1)}) {
    const cv::Mat m = (cv::Mat_<double>(2, 3) << 1, 0, shift.x, 0, 1, shift.y);
    cv::Mat moved;
    cv::warpAffine(image, moved, m, image.size(), cv::INTER_NEAREST, cv::BORDER_REPLICATE);
    const auto again =
        RadialOutlines(moved, cv::Point2d(121, 119) + cv::Point2d(shift), RadialOutlineOptions());
    const RadialOutline* ring = Nearest(again, ring_box + cv::Point2d(shift));
    ASSERT_NE(ring, nullptr) << shift;
    EXPECT_LT(cv::norm(Describe(*ring).centre - c0 - cv::Point2d(shift)), 0.5) << shift;
  }
}

TEST(RadialOutline, BadInputGivesNoOutline) {
  const cv::Mat image = NoisyWall(2);
  EXPECT_TRUE(RadialOutlines(cv::Mat(), {10, 10}, RadialOutlineOptions()).empty());
  EXPECT_TRUE(RadialOutlines(cv::Mat(50, 50, CV_32F), {10, 10}, RadialOutlineOptions()).empty());
  EXPECT_TRUE(RadialOutlines(image, {-1, 10}, RadialOutlineOptions()).empty());
  EXPECT_TRUE(RadialOutlines(image, {10, 1e9}, RadialOutlineOptions()).empty());
  EXPECT_TRUE(RadialOutlines(image, {NAN, 10}, RadialOutlineOptions()).empty());
  RadialOutlineOptions absurd;
  absurd.rays = 2;
  EXPECT_TRUE(RadialOutlines(image, {120, 120}, absurd).empty());
  absurd = RadialOutlineOptions();
  absurd.max_radius_px = 1;
  EXPECT_TRUE(RadialOutlines(image, {120, 120}, absurd).empty());
  // A ring at the image's corner: the rays leave the image, no crash.
  cv::Mat corner = NoisyWall(2);
  cv::circle(corner, {3, 3}, 20, cv::Scalar(40), 2);
  RadialOutlines(corner, {2, 2}, RadialOutlineOptions());
}

}  // namespace
}  // namespace sightline
