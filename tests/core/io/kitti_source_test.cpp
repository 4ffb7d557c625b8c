#include "core/io/kitti_source.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/core/io/io_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::testing::HasSubstr;
using testing::LinkTo;
using testing::ReadLines;
using testing::TempDir;
using testing::WriteLines;

// A KITTI folder with the images linked and calib.txt / poses.txt copied (so tests may edit).
std::string CopyKitti(const std::string& data, const std::string& name,
                      const char* left = "image_l", const char* right = "image_r") {
  const std::string dir = TempDir(name);
  LinkTo(data + "/image_l", dir + "/" + left);
  LinkTo(data + "/image_r", dir + "/" + right);
  testing::CopyFileTo(data + "/calib.txt", dir + "/calib.txt");
  testing::CopyFileTo(data + "/poses.txt", dir + "/poses.txt");
  return dir;
}

bool HasNote(const SourceInfo& info, const std::string& part) {
  return std::any_of(info.notes.begin(), info.notes.end(),
                     [&](const std::string& n) { return n.find(part) != std::string::npos; });
}

TEST(KittiSourceTest, OpensFiftyOneRectifiedPairsWithGroundTruth) {
  SIGHTLINE_REQUIRE_DATA(data, "kitti_clip1");
  KittiSource source(data);
  ASSERT_TRUE(source.Open().ok());
  const SourceInfo& info = source.info();
  EXPECT_EQ(info.format, "KITTI odometry");
  EXPECT_EQ(info.kind, SourceKind::kStereo);
  EXPECT_EQ(info.frame_count, 51);
  EXPECT_EQ(info.width, 1226);
  EXPECT_EQ(info.height, 370);
  ASSERT_TRUE(info.stereo.has_value());
  EXPECT_TRUE(info.stereo->rectified);
  EXPECT_NEAR(info.stereo->BaselineM(), 0.54, 0.01);
  EXPECT_NEAR(info.stereo->BaselineM(), 379.8145 / 707.0912, 1e-6);
  EXPECT_NEAR(info.stereo->right_from_left.translation().x(), -0.5371, 1e-3);
  EXPECT_DOUBLE_EQ(info.stereo->left.fx, 707.0912);
  EXPECT_DOUBLE_EQ(info.stereo->left.cx, 601.8873);
  EXPECT_DOUBLE_EQ(info.stereo->left.cy, 183.1104);
  EXPECT_FALSE(info.stereo->left.HasDistortion());
  EXPECT_EQ(info.stereo->left.width, 1226);
  // No times.txt: 10 Hz synthesized, and said so.
  EXPECT_DOUBLE_EQ(info.rate_hz, 10);
  EXPECT_NEAR(info.duration_s, 5.0, 1e-9);
  EXPECT_TRUE(HasNote(info, "synthesized at 10 Hz"));
  const Trajectory* gt = source.ground_truth();
  ASSERT_NE(gt, nullptr);
  EXPECT_EQ(gt->size(), 51u);
  EXPECT_NEAR(gt->LengthM(), 59.9, 0.5);
  EXPECT_NEAR(gt->poses()[10].time_s, 1.0, 1e-9);
  EXPECT_TRUE(gt->poses()[0].world_from_sensor.isApprox(Eigen::Isometry3d::Identity(), 1e-6));
}

TEST(KittiSourceTest, RetrievesGreyPairsInOrder) {
  SIGHTLINE_REQUIRE_DATA(data, "kitti_clip1");
  KittiSource source(data);
  ASSERT_TRUE(source.Open().ok());
  ASSERT_TRUE(source.Seek(50).ok());
  ASSERT_TRUE(source.Grab().ok());
  auto frame = source.Retrieve();
  ASSERT_TRUE(frame.ok());
  const auto& stereo = std::get<StereoFrame>(*frame);
  EXPECT_EQ(stereo.stamp.sequence_id, 50);
  EXPECT_NEAR(stereo.stamp.sensor_time_s, 5.0, 1e-9);
  EXPECT_EQ(stereo.left.type(), CV_8UC1);
  EXPECT_EQ(stereo.left.size(), cv::Size(1226, 370));
  EXPECT_EQ(stereo.right.size(), stereo.left.size());
  EXPECT_EQ(source.Grab().code(), StatusCode::kOutOfRange);
}

TEST(KittiSourceTest, ReadsLabelledCalibAndKittiFolderNamesAndTimes) {
  SIGHTLINE_REQUIRE_DATA(data, "kitti_clip1");
  const std::string dir = CopyKitti(data, "kitti_labelled", "image_0", "image_1");
  const std::vector<std::string> calib = ReadLines(data + "/calib.txt");
  ASSERT_EQ(calib.size(), 2u);
  const std::string p2 =
      "7.070912e+02 0 6.018873e+02 4.688783e+01 0 7.070912e+02 1.831104e+02 1.178601e-01 0 0 1 "
      "6.203223e-03";
  // KITTI's own layout: labelled, and P2/P3/Tr lines around the two that matter.
  WriteLines(dir + "/calib.txt", {"P2: " + p2, "P0: " + calib[0], "P1: " + calib[1], "P3: " + p2,
                                  "Tr: 1 0 0 0 0 1 0 0 0 0 1 0"});
  std::vector<std::string> times;
  for (int i = 0; i < 51; ++i) times.push_back(std::to_string(0.103 * i));
  WriteLines(dir + "/times.txt", times);
  KittiSource source(dir);
  ASSERT_TRUE(source.Open().ok()) << source.Open().ToString();
  EXPECT_EQ(source.info().frame_count, 51);
  EXPECT_NEAR(source.info().stereo->BaselineM(), 0.5371, 1e-3);
  EXPECT_DOUBLE_EQ(source.info().stereo->left.fx, 707.0912);
  EXPECT_FALSE(HasNote(source.info(), "synthesized"));
  EXPECT_NEAR(source.info().duration_s, 5.15, 1e-6);
  EXPECT_NEAR(source.ground_truth()->poses()[50].time_s, 5.15, 1e-6);
}

TEST(KittiSourceTest, CalibLineWithSevenNumbersIsParseErrorNamingLine) {
  SIGHTLINE_REQUIRE_DATA(data, "kitti_clip1");
  const std::string dir = CopyKitti(data, "kitti_calib7");
  const std::vector<std::string> calib = ReadLines(data + "/calib.txt");
  WriteLines(dir + "/calib.txt",
             {calib[0], "7.070912e+02 0 6.018873e+02 -3.798145e+02 0 7.070912e+02 1.831104e+02"});
  const Status status = KittiSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("calib.txt line 2"));
  EXPECT_THAT(status.message(), HasSubstr("expected 12 numbers, found 7"));
}

TEST(KittiSourceTest, CalibWithOneMatrixIsParseError) {
  SIGHTLINE_REQUIRE_DATA(data, "kitti_clip1");
  const std::string dir = CopyKitti(data, "kitti_calib1");
  WriteLines(dir + "/calib.txt", {ReadLines(data + "/calib.txt")[0]});
  const Status status = KittiSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("calib.txt"));
  EXPECT_THAT(status.message(), HasSubstr("P1"));
}

TEST(KittiSourceTest, NanInPosesIsParseErrorNamingLine) {
  SIGHTLINE_REQUIRE_DATA(data, "kitti_clip1");
  const std::string dir = CopyKitti(data, "kitti_nan");
  std::vector<std::string> poses = ReadLines(dir + "/poses.txt");
  poses[2] = "1 0 0 0 0 1 0 nan 0 0 1 2.4";
  WriteLines(dir + "/poses.txt", poses);
  const Status status = KittiSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("poses.txt line 3"));
  EXPECT_THAT(status.message(), HasSubstr("not finite"));
}

TEST(KittiSourceTest, PoseCountMismatchIsParseError) {
  SIGHTLINE_REQUIRE_DATA(data, "kitti_clip1");
  const std::string dir = CopyKitti(data, "kitti_poses50");
  std::vector<std::string> poses = ReadLines(dir + "/poses.txt");
  poses.pop_back();
  WriteLines(dir + "/poses.txt", poses);
  const Status status = KittiSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("50 poses for 51 image pairs"));
}

TEST(KittiSourceTest, MissingRightImageIsNotFoundNamingTheFile) {
  SIGHTLINE_REQUIRE_DATA(data, "kitti_clip1");
  const std::string dir = TempDir("kitti_missing");
  LinkTo(data + "/image_l", dir + "/image_l");
  testing::LinkFolderFiles(data + "/image_r", dir + "/image_r", {"000017.png"});
  testing::CopyFileTo(data + "/calib.txt", dir + "/calib.txt");
  const Status status = KittiSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_THAT(status.message(), HasSubstr("image_r/000017.png"));
}

TEST(KittiSourceTest, MissingCalibAndImagesAreNotFound) {
  SIGHTLINE_REQUIRE_DATA(data, "kitti_clip1");
  const std::string dir = TempDir("kitti_nocalib");
  LinkTo(data + "/image_l", dir + "/image_l");
  LinkTo(data + "/image_r", dir + "/image_r");
  Status status = KittiSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_THAT(status.message(), HasSubstr("calib.txt"));
  status = KittiSource(TempDir("kitti_empty")).Open();
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_THAT(status.message(), HasSubstr("image_0"));
}

}  // namespace
}  // namespace sightline
