// Bad calibration input gives a Status that says what is wrong, never a crash.
#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "core/calib/board_detection.h"
#include "core/calib/stereo_calibration.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

bool Contains(const Status& s, const std::string& text) {
  return s.message().find(text) != std::string::npos;
}

TEST(CalibrationInput, AFolderWithoutBoardsSaysSo) {
  const std::string dir = ::sightline::testing::TempDir("calib_no_boards");
  for (int i = 0; i < 3; ++i) {
    cv::Mat image(240, 320, CV_8UC1, cv::Scalar(40 * i + 50));
    cv::imwrite(dir + "/img" + std::to_string(i) + ".png", image);
  }
  auto files = ListCalibrationImages(dir);
  ASSERT_TRUE(files.ok());
  auto detections = DetectBoardsInFiles(*files, ChessboardOptions{});
  ASSERT_FALSE(detections.ok());
  EXPECT_EQ(detections.status().code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(Contains(detections.status(), "no 9x6 chessboard found in any of 3 images"))
      << detections.status().message();
}

TEST(CalibrationInput, TheRealFolderWithoutBoardsSaysSo) {
  SIGHTLINE_REQUIRE_DATA(dir, "calib_chessboard/middlebury_aloe");
  auto files = ListCalibrationImages(dir, "aloeL.jpg");
  ASSERT_TRUE(files.ok()) << files.status().ToString();
  auto detections = DetectBoardsInFiles(*files, ChessboardOptions{});
  ASSERT_FALSE(detections.ok());
  EXPECT_TRUE(Contains(detections.status(), "no 9x6 chessboard found in any of 1 images"));
}

TEST(CalibrationInput, AWrongBoardSizeFindsNothingAndSaysToCheckIt) {
  SIGHTLINE_REQUIRE_DATA(dir, "calib_chessboard");
  auto files = ListCalibrationImages(dir, "left0[1-3].jpg");
  ASSERT_TRUE(files.ok()) << files.status().ToString();
  ASSERT_EQ(files->size(), 3u);
  ChessboardOptions board;
  board.rows = 7;
  auto detections = DetectBoardsInFiles(*files, board);
  ASSERT_FALSE(detections.ok());
  EXPECT_TRUE(Contains(detections.status(), "no 9x7 chessboard"));
  EXPECT_TRUE(Contains(detections.status(), "check the board size"));
}

TEST(CalibrationInput, TooFewViewsAreRefused) {
  SIGHTLINE_REQUIRE_DATA(dir, "calib_chessboard");
  auto files = ListCalibrationImages(dir, "left0[1-3].jpg");
  ASSERT_TRUE(files.ok());
  auto detections = DetectBoardsInFiles(*files, ChessboardOptions{});
  ASSERT_TRUE(detections.ok()) << detections.status().ToString();
  auto calibration = CalibrateMono(detections->views, ChessboardOptions{});
  ASSERT_FALSE(calibration.ok());
  EXPECT_TRUE(Contains(calibration.status(), "3 views with a 9x6 board, at least 5 needed"))
      << calibration.status().message();
}

TEST(CalibrationInput, MismatchedLeftAndRightCountsAreRefused) {
  auto paired = PairImageLists({"a.png", "b.png", "c.png"}, {"d.png", "e.png"});
  ASSERT_FALSE(paired.ok());
  EXPECT_TRUE(Contains(paired.status(), "3 left images but 2 right images"));

  std::vector<BoardView> left(6, BoardView{"l", {640, 480}, {}});
  std::vector<BoardView> right(5, BoardView{"r", {640, 480}, {}});
  auto calibration = CalibrateStereo(left, right, ChessboardOptions{});
  ASSERT_FALSE(calibration.ok());
  EXPECT_TRUE(Contains(calibration.status(), "6 left views but 5 right views"));

  const std::string dir = ::sightline::testing::TempDir("calib_unpaired");
  cv::Mat image(48, 64, CV_8UC1, cv::Scalar(0));
  for (const char* name : {"left01.png", "left02.png", "right01.png"}) {
    cv::imwrite(dir + "/" + name, image);
  }
  auto files = FindStereoImages(dir);
  ASSERT_FALSE(files.ok());
  EXPECT_TRUE(Contains(files.status(), "left02.png has no partner right02.png"))
      << files.status().message();
}

TEST(CalibrationInput, MissingFoldersAndMixedSizesAreNamed) {
  EXPECT_EQ(ListCalibrationImages("/nonexistent/calib").status().code(), StatusCode::kNotFound);
  EXPECT_EQ(FindStereoImages("/nonexistent/calib").status().code(), StatusCode::kNotFound);
  std::vector<BoardView> views(5, BoardView{"a.png", {640, 480}, std::vector<cv::Point2f>(54)});
  views[3] = BoardView{"small.png", {320, 240}, std::vector<cv::Point2f>(54)};
  auto calibration = CalibrateMono(views, ChessboardOptions{});
  ASSERT_FALSE(calibration.ok());
  EXPECT_TRUE(Contains(calibration.status(), "view 'small.png' is 320x240"));
  MonoCalibrationOptions options;
  options.min_views = 1;
  std::string error;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("calib.mono.min_views"), std::string::npos);
}

TEST(CalibrationInput, FindsTheStereoPairsOfCalibChessboard) {
  SIGHTLINE_REQUIRE_DATA(dir, "calib_chessboard");
  auto files = FindStereoImages(dir);
  ASSERT_TRUE(files.ok()) << files.status().ToString();
  ASSERT_EQ(files->left.size(), 13u);
  EXPECT_NE(files->left[9].find("left11.jpg"), std::string::npos);
  EXPECT_NE(files->right[9].find("right11.jpg"), std::string::npos);
}

}  // namespace
}  // namespace sightline
