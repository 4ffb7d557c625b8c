#include "core/calib/coverage.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "board_renderer.h"

namespace sightline {
namespace {

// A view whose corners form an axis-aligned grid between (x0, y0) and (x1, y1) pixels.
BoardView GridView(float x0, float y0, float x1, float y1) {
  BoardView v{"v", {640, 480}, {}};
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 9; ++c) {
      v.corners.emplace_back(x0 + (x1 - x0) * c / 8, y0 + (y1 - y0) * r / 5);
    }
  }
  return v;
}

TEST(Coverage, OneCentredViewCoversTheCentreOnlyAndSaysWhatIsMissing) {
  const Coverage c = ComputeCoverage({GridView(240, 180, 400, 300)}, {640, 480});
  EXPECT_EQ(c.views, 1);
  EXPECT_EQ(c.grid_columns, 8);
  EXPECT_EQ(c.grid_rows, 6);
  EXPECT_NEAR(c.x_min, 0.375, 1e-6);
  EXPECT_NEAR(c.x_max, 0.625, 1e-6);
  EXPECT_EQ(c.CellViews(0, 0), 0);
  EXPECT_EQ(c.CellViews(4, 3), 1);
  EXPECT_LT(c.cells_covered, 0.3);
  const auto hints = c.Hints();
  for (const char* expected : {"left edge", "right edge", "top edge", "bottom edge"}) {
    EXPECT_TRUE(std::any_of(hints.begin(), hints.end(), [&](const std::string& h) {
      return h.find(expected) != std::string::npos;
    })) << expected;
  }
  EXPECT_EQ(c.tilt_max_deg, -1);  // Unknown without poses.
}

TEST(Coverage, ViewsInTheFourCornersAndTheCentreCoverTheImage) {
  const std::vector<BoardView> views = {GridView(0, 0, 330, 250), GridView(310, 0, 639, 250),
                                        GridView(0, 230, 330, 479), GridView(310, 230, 639, 479),
                                        GridView(200, 150, 440, 330)};
  const Coverage c = ComputeCoverage(views, {640, 480});
  EXPECT_DOUBLE_EQ(c.cells_covered, 1.0);
  EXPECT_EQ(c.CellViews(3, 2), 5);  // Every view touches a centre cell.
  EXPECT_NEAR(c.x_min, 0, 1e-9);
  EXPECT_NEAR(c.y_max, 479.0 / 480, 1e-9);
  EXPECT_LT(c.scale_min, c.scale_max);
  EXPECT_NE(c.Summary().find("cells 48/48 (100 %)"), std::string::npos) << c.Summary();
}

TEST(Coverage, TiltsComeFromTheBoardRotations) {
  Coverage c = ComputeCoverage({GridView(240, 180, 400, 300)}, {640, 480});
  SetCoverageTilts({cv::Vec3d(0, 0, 0.3), cv::Vec3d(0.5236, 0, 0)}, &c);  // 0 and 30 deg.
  EXPECT_NEAR(c.tilt_min_deg, 0, 1e-6);
  EXPECT_NEAR(c.tilt_max_deg, 30, 0.01);
  EXPECT_NE(c.Summary().find("tilt 0-30 deg"), std::string::npos) << c.Summary();
}

TEST(Coverage, OptionsAreChecked) {
  CoverageOptions options;
  options.grid_columns = 0;
  std::string error;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("calib.coverage.grid_columns"), std::string::npos);
}

}  // namespace
}  // namespace sightline
