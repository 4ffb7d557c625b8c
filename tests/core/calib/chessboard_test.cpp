#include "core/calib/chessboard.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "board_renderer.h"
#include "tests/support/test_camera.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

TEST(Chessboard, ParsesBoardSizes) {
  ChessboardOptions board;
  ASSERT_TRUE(ParseBoardSize("7x5", &board).ok());
  EXPECT_EQ(board.columns, 7);
  EXPECT_EQ(board.rows, 5);
  EXPECT_EQ(board.SizeText(), "7x5");
  for (const char* bad : {"9x", "2x6", "abc", "9x6x", "9 6", "101x6"}) {
    Status s = ParseBoardSize(bad, &board);
    EXPECT_EQ(s.code(), StatusCode::kInvalidArgument) << bad;
    EXPECT_NE(s.message().find(std::string("'") + bad + "'"), std::string::npos) << s.message();
  }
}

TEST(Chessboard, ObjectPointsRowByRowInMetres) {
  const std::vector<cv::Point3f> points = ChessboardOptions{}.ObjectPoints();
  ASSERT_EQ(points.size(), 54u);
  EXPECT_FLOAT_EQ(points[1].x, 0.025f);
  EXPECT_FLOAT_EQ(points[9].y, 0.025f);
  EXPECT_NEAR(points[53].x, 0.2, 1e-6);
  EXPECT_NEAR(points[53].y, 0.125, 1e-6);
}

TEST(Chessboard, OptionsCheckEveryFieldAndDescribeThem) {
  std::string error;
  EXPECT_TRUE(ChessboardOptions{}.IsValid(&error));
  ChessboardOptions bad;
  bad.square_size_m = 0;
  EXPECT_FALSE(bad.IsValid(&error));
  EXPECT_NE(error.find("calib.board.square_size_m"), std::string::npos);
  EXPECT_EQ(ChessboardOptions::Describe().Specs().size(), 5u);
}

TEST(Chessboard, FindsRenderedCornersWithSubPixelAccuracy) {
  const ChessboardOptions board;
  const Eigen::Isometry3d board_from_camera =
      ::sightline::testing::BoardFromCameraLookingAt(board, 0.5, 25, 40, 10);
  PinholeCamera camera = testing::VgaCamera();
  cv::Mat image =
      ::sightline::testing::RenderBoardView(camera, board_from_camera.inverse(), board, 2, 1);
  auto truth = ::sightline::testing::ProjectBoard(camera, board_from_camera.inverse(), board);
  for (bool sector_based : {false, true}) {
    if (sector_based) {  // Slower: a smaller image of the same view.
      camera = camera.Scaled(320, 240);
      image =
          ::sightline::testing::RenderBoardView(camera, board_from_camera.inverse(), board, 2, 1);
      truth = ::sightline::testing::ProjectBoard(camera, board_from_camera.inverse(), board);
    }
    ChessboardOptions options = board;
    options.sector_based = sector_based;
    std::vector<cv::Point2f> corners;
    ASSERT_TRUE(FindChessboard(image, options, &corners)) << sector_based;
    ASSERT_EQ(corners.size(), truth.size());
    // The sector-based detector may start at the opposite corner of the board.
    double forward = 0, reversed = 0;
    for (size_t i = 0; i < corners.size(); ++i) {
      forward = std::max(forward, cv::norm(corners[i] - truth[i]));
      reversed = std::max(reversed, cv::norm(corners[i] - truth[truth.size() - 1 - i]));
    }
    EXPECT_LT(std::min(forward, reversed), 0.3) << "sector_based " << sector_based;
  }
  ChessboardOptions wrong = board;
  wrong.rows = 7;
  std::vector<cv::Point2f> corners;
  EXPECT_FALSE(FindChessboard(image, wrong, &corners));
  EXPECT_TRUE(corners.empty());
  EXPECT_FALSE(FindChessboard(cv::Mat(), board, &corners));
}

TEST(Chessboard, FindsTheBoardInARealImage) {
  SIGHTLINE_REQUIRE_DATA(dir, "calib_chessboard");
  const cv::Mat image = cv::imread(dir + "/left01.jpg", cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(image.empty());
  std::vector<cv::Point2f> corners;
  ASSERT_TRUE(FindChessboard(image, ChessboardOptions{}, &corners));
  EXPECT_EQ(corners.size(), 54u);
  ChessboardOptions wrong;
  wrong.rows = 7;
  EXPECT_FALSE(FindChessboard(image, wrong, &corners));
}

}  // namespace
}  // namespace sightline
