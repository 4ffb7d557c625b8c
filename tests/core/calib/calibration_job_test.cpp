// RunCalibration as the GUI runs it: image folders, and frames of a source (the image-folder
// reader here, standing in for a recording or a camera) with view selection.
#include "core/calib/calibration_job.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "board_renderer.h"
#include "core/io/camera_yaml.h"
#include "core/io/dataset.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::sightline::testing::BoardFromCameraLookingAt;

// Eight rendered views of the default board, written to `dir` as frame_N.png with times.txt.
std::string WriteViews(std::string dir = "") {
  if (dir.empty()) dir = ::sightline::testing::TempDir("calib_job_views");
  std::filesystem::create_directories(dir);
  PinholeCamera camera;
  camera.width = 640;
  camera.height = 480;
  camera.fx = camera.fy = 500;
  camera.cx = 320;
  camera.cy = 240;
  std::ofstream times(dir + "/times.txt");
  for (int i = 0; i < 8; ++i) {
    const Eigen::Isometry3d board_from_camera =
        BoardFromCameraLookingAt(ChessboardOptions{}, 0.5, 15 + 5 * (i % 3), 45 * i, 0);
    const std::string name = "frame_" + std::to_string(i) + ".png";
    cv::imwrite(dir + "/" + name,
                ::sightline::testing::RenderBoardView(camera, board_from_camera.inverse(),
                                                      ChessboardOptions{}, 1, i));
    times << 0.1 * i << " " << name << "\n";
  }
  return dir;
}

TEST(CalibrationJob, CalibratesAnImageFolderAndSavesACameraYaml) {
  CalibrationRequest request;
  request.input = WriteViews();
  request.settings.mono.fix_k3 = true;
  auto outcome = RunCalibration(request, nullptr);
  ASSERT_TRUE(outcome.ok()) << outcome.status().ToString();
  ASSERT_TRUE(outcome->mono.has_value());
  EXPECT_EQ(outcome->detections.views.size(), 8u);
  EXPECT_FALSE(outcome->detections.views[0].path.empty());
  EXPECT_NEAR(outcome->mono->camera.fx, 500, 5);
  EXPECT_NE(outcome->report.find("RMS "), std::string::npos);
  const std::string path = request.input + "/out.yaml";
  ASSERT_TRUE(SaveCalibration(*outcome, path).ok());
  EXPECT_TRUE(ReadCameraYaml(path).ok());
}

TEST(CalibrationJob, ReadsFramesOfASourceWhenTheInputIsNoImageFolder) {
  const std::string recording = ::sightline::testing::TempDir("calib_job_recording");
  WriteViews(recording + "/mono");  // A recording with one sensor folder: no images at the top.
  int opened = 0;
  const SourceOpener open = [&opened](const std::string& path) {
    ++opened;
    return OpenDataset(path);
  };
  CalibrationRequest request;
  request.settings.mono.fix_k3 = true;
  // A pattern matching nothing is an error, never a silent switch to reading the folder.
  request.input = recording + "/mono";
  request.pattern = "no_such_image*";
  auto typo = RunCalibration(request, open);
  ASSERT_FALSE(typo.ok());
  EXPECT_NE(typo.status().message().find("matches 'no_such_image*'"), std::string::npos)
      << typo.status().message();
  EXPECT_EQ(opened, 0);
  request.input = recording;
  request.pattern = "*";
  auto outcome = RunCalibration(request, open);
  ASSERT_TRUE(outcome.ok()) << outcome.status().ToString();
  EXPECT_EQ(opened, 1);
  ASSERT_EQ(outcome->detections.views.size(), 8u);
  EXPECT_NEAR(outcome->detections.views[3].time_s, 0.3, 1e-9);
  EXPECT_NEAR(outcome->mono->camera.fx, 500, 5);

  // Without an opener the same input is refused with a reason.
  auto refused = RunCalibration(request, nullptr);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.status().message().find("not an image folder"), std::string::npos);
  // A stereo request on a mono source says so.
  request.stereo = true;
  auto stereo = RunCalibration(request, open);
  ASSERT_FALSE(stereo.ok());
  EXPECT_NE(stereo.status().message().find("not a stereo source"), std::string::npos)
      << stereo.status().message();
}

TEST(CalibrationJob, NewViewsMustDifferFromTheAcceptedOnes) {
  BoardView a{"a", {640, 480}, {{100, 100}, {200, 100}, {200, 200}, {100, 200}}};
  BoardView same = a;
  BoardView moved = a;
  for (auto& p : moved.corners) p.x += 100;
  EXPECT_FALSE(IsNewView(same, {a}, 0.05));
  EXPECT_TRUE(IsNewView(moved, {a}, 0.05));
  EXPECT_TRUE(IsNewView(same, {a}, 0.0));
  EXPECT_TRUE(IsNewView(same, {}, 0.05));
}

}  // namespace
}  // namespace sightline

namespace sightline {
namespace {

// A live camera as DetectBoardsInSource sees it: an endless stream in which the board stays
// still for several frames at a time (a source of rendered frames; no device is needed).
class StillBoardCamera : public Source {
 public:
  Status Open() override {
    info_.format = "test camera";
    info_.path = "test://camera";
    info_.live = true;
    info_.frame_count = -1;
    return Status::Ok();
  }
  const SourceInfo& info() const override { return info_; }
  Status Grab() override {
    ++position_;
    return Status::Ok();
  }
  StatusOr<Frame> Retrieve() override {
    const int pose = static_cast<int>(position_ - 1) / 4;  // Four frames per pose.
    PinholeCamera camera;
    camera.width = 640;
    camera.height = 480;
    camera.fx = camera.fy = 500;
    camera.cx = 320;
    camera.cy = 240;
    // Six poses on a 3 x 2 grid, 8 cm / 6 cm apart at 0.5 m (80 / 60 px), tilted 20 deg.
    const Eigen::Isometry3d camera_from_board =
        Eigen::Translation3d(0.08 * (pose % 3 - 1), 0.06 * (pose / 3 % 2 - 0.5), 0) *
        BoardFromCameraLookingAt(ChessboardOptions{}, 0.5, 20, 60 * pose, 0).inverse();
    MonoFrame frame;
    frame.stamp.sequence_id = position_ - 1;
    frame.stamp.sensor_time_s = 0.033 * frame.stamp.sequence_id;
    frame.image = ::sightline::testing::RenderBoardView(camera, camera_from_board,
                                                        ChessboardOptions{}, 1, position_);
    return Frame(frame);
  }
  int64_t Position() const override { return position_; }

 private:
  SourceInfo info_;
  int64_t position_ = 0;
};

TEST(CalibrationJob, ALiveCameraKeepsOnlyViewsThatDiffer) {
  StillBoardCamera camera;
  ASSERT_TRUE(camera.Open().ok());
  SourceDetectionOptions options;
  options.max_frames = 24;  // Six poses, four frames each.
  options.min_change = 0.05;
  auto detections = DetectBoardsInSource(&camera, ChessboardOptions{}, options);
  ASSERT_TRUE(detections.ok()) << detections.status().ToString();
  EXPECT_EQ(detections->inputs, 24);
  EXPECT_EQ(detections->views.size(), 6u);  // One per pose.
  EXPECT_TRUE(detections->without_board.empty());
  EXPECT_EQ(detections->views[1].name, "frame 4");
  options.max_views = 3;
  StillBoardCamera again;
  ASSERT_TRUE(again.Open().ok());
  auto capped = DetectBoardsInSource(&again, ChessboardOptions{}, options);
  ASSERT_TRUE(capped.ok());
  EXPECT_EQ(capped->views.size(), 3u);
  EXPECT_EQ(capped->inputs, 9);  // Stops at the third accepted view (frame 8).
}

}  // namespace
}  // namespace sightline
