// The stereo calibration file: written rigs read back exactly (and OpenCV reads them), files
// written by cv::FileStorage and the real reference calibration read, and every check rejects a
// bad value naming the file, the line and the key.
#include "core/io/stereo_calibration_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <map>
#include <opencv2/core.hpp>
#include <opencv2/core/eigen.hpp>
#include <opencv2/core/persistence.hpp>

#include "core/io/dataset.h"
#include "tests/core/io/io_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;
using testing::WriteText;

StereoRig TestRig() {
  StereoRig rig;
  rig.left.width = rig.right.width = 752;
  rig.left.height = rig.right.height = 480;
  rig.left.fx = 458.654;
  rig.left.fy = 457.296;
  rig.left.cx = 367.215;
  rig.left.cy = 248.375;
  rig.left.distortion = {-0.28340811, 0.07395907, 0.00019359, 1.76187114e-05, 0};
  rig.right = rig.left;
  rig.right.fx = 457.587;
  rig.right.cx = 379.999;
  rig.right.distortion = {-0.28368365, 0.07451284, -0.00010473, -3.55590700e-05, 0.01};
  rig.right_from_left = Eigen::Translation3d(-0.110073808, 0.000399121, -0.000853702) *
                        Eigen::AngleAxisd(0.0123, Eigen::Vector3d(0.2, 1, -0.1).normalized());
  return rig;
}

void ExpectSameRig(const StereoRig& a, const StereoRig& b) {
  for (const auto& [x, y] : {std::pair{&a.left, &b.left}, std::pair{&a.right, &b.right}}) {
    EXPECT_EQ(x->width, y->width);
    EXPECT_EQ(x->height, y->height);
    EXPECT_EQ(x->fx, y->fx);
    EXPECT_EQ(x->fy, y->fy);
    EXPECT_EQ(x->cx, y->cx);
    EXPECT_EQ(x->cy, y->cy);
    EXPECT_EQ(x->distortion, y->distortion);
  }
  EXPECT_TRUE(a.right_from_left.isApprox(b.right_from_left, 1e-15));
}

TEST(StereoCalibrationFile, WritesAndReadsBackWithExtrasThatOpenCvReads) {
  const std::string path = TempDir("stereo_round_trip") + "/rig.yaml";
  StereoFileExtras extras;
  extras.matrices = {{"Q", Eigen::Matrix4d::Identity()}};
  extras.numbers = {{"rms_stereo", 0.447}, {"board_width", 9}};
  extras.comments = {{"a header"}, {"a footer"}};
  ASSERT_TRUE(WriteStereoCalibration(TestRig(), path, extras).ok());
  auto read = ReadStereoCalibration(path);
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  ExpectSameRig(*read, TestRig());
  EXPECT_FALSE(read->rectified);

  cv::FileStorage fs(path, cv::FileStorage::READ);
  ASSERT_TRUE(fs.isOpened());
  cv::Mat m1, t, q;
  fs["M1"] >> m1;
  fs["T"] >> t;
  fs["Q"] >> q;
  EXPECT_EQ(static_cast<int>(fs["image_width"]), 752);
  EXPECT_DOUBLE_EQ(m1.at<double>(0, 2), 367.215);
  EXPECT_DOUBLE_EQ(t.at<double>(0), -0.110073808);
  EXPECT_EQ(q.rows, 4);
  EXPECT_TRUE(fs["board_width"].isInt());
  EXPECT_DOUBLE_EQ(static_cast<double>(fs["rms_stereo"]), 0.447);
}

TEST(StereoCalibrationFile, ReadsWhatCvFileStorageWrites) {
  const StereoRig rig = TestRig();
  const std::string path = TempDir("stereo_opencv") + "/rig.yml";
  {
    cv::FileStorage fs(path, cv::FileStorage::WRITE);
    fs << "image_width" << rig.left.width << "image_height" << rig.left.height;
    cv::Mat k1, k2, r, t;
    cv::eigen2cv(Eigen::Matrix3d(rig.left.K()), k1);
    cv::eigen2cv(Eigen::Matrix3d(rig.right.K()), k2);
    cv::eigen2cv(Eigen::Matrix3d(rig.right_from_left.linear()), r);
    cv::eigen2cv(Eigen::Vector3d(rig.right_from_left.translation()), t);
    fs << "M1" << k1 << "D1" << cv::Mat(rig.left.distortion).reshape(1, 1);
    fs << "M2" << k2 << "D2" << cv::Mat(rig.right.distortion).reshape(1, 1);
    fs << "R" << r << "T" << t << "rms_stereo" << 0.4;
  }
  auto read = ReadStereoCalibration(path);
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  ExpectSameRig(*read, rig);
}

// A stereo file with plain lists, one key per line (line numbers 1 to 8), with `changed` keys
// replaced (an empty value drops the key).
std::string StereoText(const std::map<std::string, std::string>& changed = {}) {
  const std::vector<std::pair<std::string, std::string>> keys = {
      {"image_width", "640"},
      {"image_height", "480"},
      {"M1", "[500, 0, 320, 0, 500, 240, 0, 0, 1]"},
      {"D1", "[0.1, -0.2, 0, 0, 0]"},
      {"M2", "[500, 0, 321, 0, 500, 240, 0, 0, 1]"},
      {"D2", "[0.1, -0.2, 0, 0]"},
      {"R", "[1, 0, 0, 0, 1, 0, 0, 0, 1]"},
      {"T", "[-0.12, 0, 0]"}};
  std::string text;
  for (const auto& [key, value] : keys) {
    const auto it = changed.find(key);
    const std::string v = it == changed.end() ? value : it->second;
    if (!v.empty()) text += key + ": " + v + "\n";
  }
  return text;
}

TEST(StereoCalibrationFile, EachRuleRejectsNamingFileLineAndKey) {
  const std::string dir = TempDir("stereo_rules");
  WriteText(dir + "/good.yaml", StereoText());
  ASSERT_TRUE(ReadStereoCalibration(dir + "/good.yaml").ok());
  struct Case {
    std::map<std::string, std::string> changed;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {{{"image_width", "0"}}, "line 1: key 'image_width': image width 0 must be positive"},
      {{{"image_height", "480.5"}}, "line 2: key 'image_height': 480.5 is not a whole number"},
      {{{"M1", "[-500, 0, 320, 0, 500, 240, 0, 0, 1]"}},
       "line 3: key 'M1': focal length fx = -500 must be positive and finite"},
      {{{"M1", "[500, 0, 320, 0, 500, 520, 0, 0, 1]"}},
       "line 3: key 'M1': principal point cy = 520 must lie inside the image [0, 480]"},
      {{{"M2", "[500, 3, 320, 0, 500, 240, 0, 0, 1]"}}, "line 5: key 'M2': must be an intrinsic"},
      {{{"M2", "[500, 0, 320, 0, 500]"}}, "line 5: key 'M2': expected 9 numbers, found 5"},
      {{{"D1", "[0.1, 5000, 0, 0, 0]"}},
       "line 4: key 'D1': distortion k2 = 5000 must be finite with magnitude below 1000"},
      {{{"D2", "[0.1, .nan, 0, 0]"}}, "line 6: key 'D2': .nan is not finite"},
      {{{"R", "[1.001, 0, 0, 0, 1, 0, 0, 0, 1]"}},
       "line 7: key 'R': is not a rotation: R^T R differs from the identity by 0.002001"},
      {{{"R", "[1, 0, 0, 0, 1, 0, 0, 0, -1]"}},
       "line 7: key 'R': is not a rotation: its determinant is -1, not +1 (a reflection)"},
      {{{"T", "[0, 0, 0]"}}, "line 8: key 'T': baseline 0 m: the cameras must be at least"},
      {{{"T", "[-0.12, .inf, 0]"}}, "line 8: key 'T': .inf is not finite"},
      {{{"T", ""}}, ": key 'T': missing"},
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    const std::string path = dir + "/case" + std::to_string(i) + ".yaml";
    WriteText(path, StereoText(cases[i].changed));
    const Status status = ReadStereoCalibration(path).status();
    EXPECT_EQ(status.code(), StatusCode::kParseError) << path;
    EXPECT_THAT(status.message(),
                HasSubstr(path + (cases[i].expected[0] == ':' ? "" : " ") + cases[i].expected));
  }
}

TEST(StereoCalibrationFile, MatrixShapeAndDuplicateKeysAreChecked) {
  const std::string dir = TempDir("stereo_shape");
  WriteText(dir + "/shape.yaml", StereoText({{"T",
                                              "!!opencv-matrix\n   rows: 2\n   cols: 1\n   dt: d\n"
                                              "   data: [-0.12, 0, 0]"}}));
  EXPECT_THAT(ReadStereoCalibration(dir + "/shape.yaml").status().message(),
              HasSubstr("shape.yaml line 8: key 'T': 2 x 1 matrix but 3 numbers in data"));
  WriteText(dir + "/twice.yaml", StereoText() + "R: [1, 0, 0, 0, 1, 0, 0, 0, 1]\n");
  EXPECT_THAT(ReadStereoCalibration(dir + "/twice.yaml").status().message(),
              HasSubstr("twice.yaml line 9: key 'R': given twice (first on line 7)"));
  WriteText(dir + "/garbage.yaml", "this: [is not: closed\n");
  const Status garbage = ReadStereoCalibration(dir + "/garbage.yaml").status();
  EXPECT_EQ(garbage.code(), StatusCode::kParseError);
  EXPECT_THAT(garbage.message(), HasSubstr("garbage.yaml line"));
}

TEST(StereoCalibrationFile, WriterRefusesWhatTheReaderWouldReject) {
  const std::string path = TempDir("stereo_refuse") + "/rig.yaml";
  StereoRig rig = TestRig();
  rig.right_from_left.translation().setZero();
  EXPECT_THAT(WriteStereoCalibration(rig, path).message(), HasSubstr("baseline"));
  StereoFileExtras extras;
  extras.numbers = {{"T", 1}};
  EXPECT_THAT(WriteStereoCalibration(TestRig(), path, extras).message(),
              HasSubstr("key 'T' twice"));
  rig = TestRig();
  rig.right.height = 500;
  EXPECT_THAT(WriteStereoCalibration(rig, path).message(), HasSubstr("one image size"));
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(StereoCalibrationFile, ReadsTheReferenceCalibrationOfCalibChessboard) {
  SIGHTLINE_REQUIRE_DATA(dir, "calib_chessboard");
  // The reference keeps intrinsics and extrinsics in two files; join them as one stereo file.
  const std::string joined = TempDir("stereo_reference") + "/stereo.yaml";
  {
    std::ofstream out(joined);
    std::ifstream a(dir + "/reference_calibration/intrinsics.yml");
    std::ifstream b(dir + "/reference_calibration/extrinsics.yml");
    std::string line;
    while (std::getline(a, line)) out << line << "\n";
    std::getline(b, line);  // %YAML:1.0
    std::getline(b, line);  // ---
    while (std::getline(b, line)) out << line << "\n";
  }
  auto rig = ReadStereoCalibration(joined);
  ASSERT_TRUE(rig.ok()) << rig.status().ToString();
  EXPECT_NEAR(rig->BaselineM(), 0.0836, 0.0001);
  EXPECT_NEAR(rig->left.fx, 536.06, 0.01);
  EXPECT_NEAR(rig->right.distortion[0], -0.2806, 0.0001);
}

// A real dataset's stereo rig passes the checks and survives a round trip.
void RoundTripDatasetRig(const std::string& dir, const std::string& name) {
  auto source = OpenDataset(dir, SourceKind::kStereo);
  ASSERT_TRUE(source.ok()) << source.status().ToString();
  ASSERT_TRUE((*source)->info().stereo.has_value());
  const StereoRig rig = *(*source)->info().stereo;
  const std::string path = TempDir("stereo_" + name) + "/rig.yaml";
  ASSERT_TRUE(WriteStereoCalibration(rig, path).ok());
  auto read = ReadStereoCalibration(path);
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  ExpectSameRig(*read, rig);
}

TEST(StereoCalibrationFile, KittiRigRoundTrips) {
  SIGHTLINE_REQUIRE_DATA(dir, "kitti_clip1");
  RoundTripDatasetRig(dir, "kitti");
}

TEST(StereoCalibrationFile, EurocRigRoundTrips) {
  SIGHTLINE_REQUIRE_DATA(dir, "euroc_v1_01_static");
  RoundTripDatasetRig(dir, "euroc");
}

}  // namespace
}  // namespace sightline
