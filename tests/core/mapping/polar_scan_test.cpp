#include "core/mapping/polar_scan.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/mapping/pose2d.h"

namespace sightline {
namespace {

OccupancyImage EmptyImage(int size = 400, double cell = 0.02) {
  OccupancyImage image;
  image.cell_size_m = cell;
  image.cells = cv::Mat(size, size, CV_8UC1, cv::Scalar(static_cast<int>(OccupancyCell::kFree)));
  return image;
}

void MarkRow(OccupancyImage* image, int row, OccupancyCell label) {
  image->cells.row(row).setTo(static_cast<int>(label));
}

TEST(PolarScan, RaysOnlyInsideTheFieldOfView) {
  PolarScanner scanner;
  ASSERT_TRUE(scanner.Configure(400, 400, 0.02, DegToRad(-30), DegToRad(30)).ok());
  // -30 .. 30 deg at 0.2 deg: 301 rays, not the seed's 900 over 180 deg.
  EXPECT_EQ(scanner.rays(), 301);
  OccupancyImage image = EmptyImage();
  MarkRow(&image, 250, OccupancyCell::kOccupied);  // A wall 3 m ahead.
  StatusOr<PolarScan> scan = scanner.Scan(image);
  ASSERT_TRUE(scan.ok());
  EXPECT_EQ(scan->rays_cast, 301);
  EXPECT_EQ(scan->points.size(), 301u);
  for (const ScanPoint& p : scan->points) {
    EXPECT_NEAR(p.xy.x(), 3.0, 0.011);
    // The hit lies on the ray: its bearing matches within one cell at 3 m.
    EXPECT_NEAR(std::atan2(p.xy.y(), p.xy.x()), p.bearing_rad, 0.02 / 3.0 + 1e-9);
  }
  // Right to left.
  EXPECT_LT(scan->points.front().bearing_rad, scan->points.back().bearing_rad);
  EXPECT_NE(scan->Describe().find("301 of 900 rays"), std::string::npos) << scan->Describe();
}

TEST(PolarScan, NearestOccupiedCellWins) {
  PolarScanner scanner;
  ASSERT_TRUE(scanner.Configure(400, 400, 0.02, DegToRad(-10), DegToRad(10)).ok());
  OccupancyImage image = EmptyImage();
  MarkRow(&image, 250, OccupancyCell::kOccupied);
  image.cells(cv::Rect(190, 300, 20, 1)).setTo(static_cast<int>(OccupancyCell::kOccupied));
  StatusOr<PolarScan> scan = scanner.Scan(image);
  ASSERT_TRUE(scan.ok());
  int near_hits = 0;
  for (const ScanPoint& p : scan->points) near_hits += p.range_m < 2.1 ? 1 : 0;
  EXPECT_GT(near_hits, 5);
}

TEST(PolarScan, PeopleAreSkipped) {
  PolarScanner scanner;
  ASSERT_TRUE(scanner.Configure(400, 400, 0.02, DegToRad(-30), DegToRad(30)).ok());
  OccupancyImage image = EmptyImage();
  MarkRow(&image, 250, OccupancyCell::kOccupied);
  // A person 1.5 m ahead: its cells are labelled, and an occupied cell inside its footprint
  // (an arm outside the image box) is skipped too.
  image.cells(cv::Rect(190, 320, 20, 10)).setTo(static_cast<int>(OccupancyCell::kPerson));
  image.cells.at<uint8_t>(325, 212) = static_cast<uint8_t>(OccupancyCell::kOccupied);
  PersonFootprint footprint;
  footprint.cells = cv::Rect(188, 318, 26, 14);
  image.people.push_back(footprint);
  StatusOr<PolarScan> scan = scanner.Scan(image);
  ASSERT_TRUE(scan.ok());
  for (const ScanPoint& p : scan->points) EXPECT_NEAR(p.xy.x(), 3.0, 0.011);
  EXPECT_GT(scan->rays_blocked_by_people, 0);
}

TEST(PolarScan, MinimumRangeAndEmptyImages) {
  PolarScanOptions options;
  options.min_range_m = 1.0;
  PolarScanner scanner(options);
  ASSERT_TRUE(scanner.Configure(400, 400, 0.02, DegToRad(-30), DegToRad(30)).ok());
  OccupancyImage image = EmptyImage();
  MarkRow(&image, 390, OccupancyCell::kOccupied);  // 0.2 m ahead: ignored.
  StatusOr<PolarScan> scan = scanner.Scan(image);
  ASSERT_TRUE(scan.ok());
  EXPECT_TRUE(scan->points.empty());
  OccupancyImage wrong = EmptyImage(100);
  EXPECT_EQ(scanner.Scan(wrong).status().code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(PolarScanner().Scan(image).status().code(), StatusCode::kFailedPrecondition);
}

}  // namespace
}  // namespace sightline
