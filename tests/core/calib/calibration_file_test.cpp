// Saving calibrations: what is saved loads back through core/io's camera.yaml reader and the
// image-folder source, and the stereo file through core/io's ReadStereoCalibration.
#include "core/calib/calibration_file.h"

#include <gtest/gtest.h>

#include <opencv2/core/persistence.hpp>
#include <opencv2/imgcodecs.hpp>

#include "board_renderer.h"
#include "core/io/camera_yaml.h"
#include "core/io/dataset.h"
#include "core/io/stereo_calibration_file.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::sightline::testing::BoardFromCameraLookingAt;
using ::sightline::testing::RenderBoardView;

PinholeCamera TrueCamera() {
  PinholeCamera c;
  c.width = 640;
  c.height = 480;
  c.fx = 520;
  c.fy = 522;
  c.cx = 322;
  c.cy = 236;
  return c;
}

// Rendered views of the default board from 12 directions; right views through `rig` if given.
void RenderViews(const StereoRig* rig, std::vector<BoardView>* left, std::vector<BoardView>* right,
                 std::vector<cv::Mat>* images = nullptr) {
  const ChessboardOptions board;
  for (int i = 0; i < 12; ++i) {
    const Eigen::Isometry3d board_from_camera = BoardFromCameraLookingAt(
        board, 0.45 + 0.1 * (i % 3), 10 + 10 * (i % 3), 30 * i, 5 * (i % 4));
    const Eigen::Isometry3d camera_from_board = board_from_camera.inverse();
    const PinholeCamera camera = rig ? rig->left : TrueCamera();
    cv::Mat image = RenderBoardView(camera, camera_from_board, board, 1.5, i);
    BoardView view{"view" + std::to_string(i) + ".png", image.size(), {}};
    ASSERT_TRUE(FindChessboard(image, board, &view.corners)) << i;
    left->push_back(view);
    if (images) images->push_back(image);
    if (rig) {
      cv::Mat r =
          RenderBoardView(rig->right, rig->right_from_left * camera_from_board, board, 1.5, 50 + i);
      BoardView rv{"right" + std::to_string(i) + ".png", r.size(), {}};
      ASSERT_TRUE(FindChessboard(r, board, &rv.corners)) << "right " << i;
      right->push_back(rv);
    }
  }
}

TEST(CalibrationFile, MonoCalibrationOfRenderedViewsIsAccurateAndLoadsBack) {
  std::vector<BoardView> views, unused;
  std::vector<cv::Mat> images;
  RenderViews(nullptr, &views, &unused, &images);
  MonoCalibrationOptions options;
  options.fix_k3 = true;
  auto calibration = CalibrateMono(views, ChessboardOptions{}, options);
  ASSERT_TRUE(calibration.ok()) << calibration.status().ToString();
  EXPECT_LT(calibration->rms_px, 0.3);
  EXPECT_NEAR(calibration->camera.fx, 520, 520 * 0.005);
  EXPECT_NEAR(calibration->camera.fy, 522, 522 * 0.005);
  EXPECT_NEAR(calibration->camera.cx, 322, 2.0);
  EXPECT_NEAR(calibration->camera.cy, 236, 2.0);

  // camera.yaml in an image folder: the reader and the source accept it as written.
  const std::string dir = ::sightline::testing::TempDir("calib_mono_roundtrip");
  const std::string yaml = dir + "/camera.yaml";
  ASSERT_TRUE(SaveMonoCalibration(*calibration, ChessboardOptions{}, yaml).ok());
  auto read = ReadCameraYaml(yaml);
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  const PinholeCamera& c = calibration->camera;
  EXPECT_NEAR(read->camera.fx, c.fx, 1e-9);
  EXPECT_NEAR(read->camera.cy, c.cy, 1e-9);
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(read->camera.distortion[i], c.distortion[i], 1e-12);
  for (int i = 0; i < 2; ++i) cv::imwrite(dir + "/" + std::to_string(i) + ".png", images[i]);
  auto source = OpenDataset(dir);
  ASSERT_TRUE(source.ok()) << source.status().ToString();
  ASSERT_TRUE((*source)->info().camera.has_value());
  EXPECT_NEAR((*source)->info().camera->fx, c.fx, 1e-9);
  EXPECT_NEAR((*source)->info().camera->distortion[0], c.distortion[0], 1e-12);

  // OpenCV reads it too.
  cv::FileStorage fs(yaml, cv::FileStorage::READ);
  ASSERT_TRUE(fs.isOpened());
  EXPECT_NEAR(static_cast<double>(fs["fx"]), c.fx, 1e-9);
  EXPECT_EQ(static_cast<std::string>(fs["model"]), "pinhole");
}

TEST(CalibrationFile, StereoCalibrationOfARenderedRigLoadsBack) {
  StereoRig rig;
  rig.left = rig.right = TrueCamera();
  rig.right.cx = 318;
  rig.right_from_left =
      Eigen::Translation3d(-0.12, 0.002, 0.001) * Eigen::AngleAxisd(0.02, Eigen::Vector3d::UnitY());
  std::vector<BoardView> left, right;
  RenderViews(&rig, &left, &right);
  MonoCalibrationOptions mono;
  mono.fix_k3 = true;
  auto calibration = CalibrateStereo(left, right, ChessboardOptions{}, mono);
  ASSERT_TRUE(calibration.ok()) << calibration.status().ToString();
  EXPECT_NEAR(calibration->BaselineM(), rig.BaselineM(), rig.BaselineM() * 0.01);
  EXPECT_LT(calibration->rms_px, 0.3);

  const std::string path = ::sightline::testing::TempDir("calib_stereo_roundtrip") + "/rig.yaml";
  ASSERT_TRUE(SaveStereoCalibration(*calibration, ChessboardOptions{}, path).ok());
  auto read = ReadStereoCalibration(path);
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  EXPECT_TRUE(read->right_from_left.isApprox(calibration->rig.right_from_left, 1e-9));
  EXPECT_NEAR(read->left.fx, calibration->rig.left.fx, 1e-9);
  EXPECT_NEAR(read->right.distortion[1], calibration->rig.right.distortion[1], 1e-12);
  for (const char* side : {"left", "right"}) {
    auto camera = ReadCameraYaml(StereoCameraFilePath(path, side));
    ASSERT_TRUE(camera.ok()) << side << ": " << camera.status().ToString();
  }
  EXPECT_EQ(StereoCameraFilePath(path, "left"), path.substr(0, path.size() - 5) + "_left.yaml");
}

}  // namespace
}  // namespace sightline
