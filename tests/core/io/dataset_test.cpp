#include "core/io/dataset.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cctype>
#include <filesystem>

#include "tests/core/io/io_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::testing::HasSubstr;
using testing::LinkTo;
using testing::TempDir;

struct FormatCase {
  const char* relative;
  DatasetFormat format;
  SourceKind kind;
  int64_t frames;
  const char* frames_text;
};

// Names the case by its data path in test output.
void PrintTo(const FormatCase& c, std::ostream* os) { *os << c.relative; }

class DetectTest : public ::testing::TestWithParam<FormatCase> {};

TEST_P(DetectTest, DetectsOpensAndDescribes) {
  const FormatCase& c = GetParam();
  SIGHTLINE_REQUIRE_DATA(path, c.relative);
  const std::optional<DetectedDataset> detected = DetectDataset(path);
  ASSERT_TRUE(detected.has_value());
  EXPECT_EQ(detected->format, c.format);
  EXPECT_EQ(detected->kind, c.kind);
  auto source = OpenDataset(path);
  ASSERT_TRUE(source.ok()) << source.status().ToString();
  EXPECT_EQ((*source)->info().format, DatasetFormatName(c.format));
  EXPECT_EQ((*source)->info().kind, c.kind);
  EXPECT_EQ((*source)->info().frame_count, c.frames);
  EXPECT_EQ(DescribeFrameCount((*source)->info()), c.frames_text);
  EXPECT_THAT(DescribeSourceText(**source),
              HasSubstr(std::string("frames: ") + c.frames_text + "\n"));
  // Asking for the kind it is works too.
  EXPECT_TRUE(OpenDataset(path, c.kind).ok());
}

INSTANTIATE_TEST_SUITE_P(
    RecordedData, DetectTest,
    ::testing::Values(FormatCase{"tum_fr1_desk", DatasetFormat::kTumRgbd, SourceKind::kRgbd, 9,
                                 "9 RGB-D frames"},
                      FormatCase{"euroc_v1_01_static", DatasetFormat::kEuroc, SourceKind::kStereo,
                                 20, "20 stereo pairs"},
                      FormatCase{"euroc_v1_01_static/mav0", DatasetFormat::kEuroc,
                                 SourceKind::kStereo, 20, "20 stereo pairs"},
                      FormatCase{"kitti_clip1", DatasetFormat::kKitti, SourceKind::kStereo, 51,
                                 "51 stereo pairs"},
                      FormatCase{"pcl_clouds/office1.pcd", DatasetFormat::kPcd, SourceKind::kCloud,
                                 1, "1 point cloud"},
                      FormatCase{"pcl_clouds/grabber_sequences/pcd", DatasetFormat::kPcd,
                                 SourceKind::kCloud, 3, "3 point clouds"},
                      FormatCase{"kitti_clip1/image_r", DatasetFormat::kImageFolder,
                                 SourceKind::kMono, 51, "51 images"}),
    [](const ::testing::TestParamInfo<FormatCase>& info) {
      std::string name = info.param.relative;
      for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      }
      return name;
    });

TEST(DatasetTest, DescribesKittiAsText) {
  SIGHTLINE_REQUIRE_DATA(path, "kitti_clip1");
  auto source = OpenDataset(path);
  ASSERT_TRUE(source.ok());
  const std::string text = DescribeSourceText(**source);
  EXPECT_THAT(text, HasSubstr("format: KITTI odometry\n"));
  EXPECT_THAT(text, HasSubstr("kind: stereo\n"));
  EXPECT_THAT(text, HasSubstr("frames: 51 stereo pairs\n"));
  EXPECT_THAT(text, HasSubstr("resolution: 1226x370\n"));
  EXPECT_THAT(text, HasSubstr("rate: 10 Hz\n"));
  EXPECT_THAT(text, HasSubstr("duration: 5.000 s\n"));
  EXPECT_THAT(text, HasSubstr("left camera: fx=707.091 fy=707.091 cx=601.887 cy=183.11"));
  EXPECT_THAT(text, HasSubstr("stereo baseline: 0.5372 m (rectified)\n"));
  EXPECT_THAT(text, HasSubstr("ground truth: yes (51 poses, path length 59.8"));
  EXPECT_THAT(text, HasSubstr("synthesized at 10 Hz"));
}

TEST(DatasetTest, DescribesTumAndEurocAsText) {
  SIGHTLINE_REQUIRE_DATA(tum, "tum_fr1_desk");
  SIGHTLINE_REQUIRE_DATA(euroc, "euroc_v1_01_static");
  auto source = OpenDataset(tum);
  ASSERT_TRUE(source.ok());
  std::string text = DescribeSourceText(**source);
  EXPECT_THAT(text, HasSubstr("camera: fx=517.3 fy=516.5 cx=318.6 cy=255.3, distortion"));
  EXPECT_THAT(text, HasSubstr("depth scale: 5000 units per metre"));
  EXPECT_THAT(text, HasSubstr("ground truth: yes"));
  source = OpenDataset(euroc);
  ASSERT_TRUE(source.ok());
  text = DescribeSourceText(**source);
  EXPECT_THAT(text, HasSubstr("stereo baseline: 0.110"));
  EXPECT_THAT(text, HasSubstr("(not rectified)"));
}

TEST(DatasetTest, DescribesKittiAsJson) {
  SIGHTLINE_REQUIRE_DATA(path, "kitti_clip1");
  auto source = OpenDataset(path);
  ASSERT_TRUE(source.ok());
  const std::string json = DescribeSourceJson(**source);
  YAML::Node root;  // JSON is YAML, so yaml-cpp checks that the document is well formed.
  ASSERT_NO_THROW(root = YAML::Load(json)) << json;
  EXPECT_EQ(root["format"].as<std::string>(), "KITTI odometry");
  EXPECT_EQ(root["kind"].as<std::string>(), "stereo");
  EXPECT_EQ(root["frames"].as<int>(), 51);
  EXPECT_EQ(root["frames_text"].as<std::string>(), "51 stereo pairs");
  EXPECT_EQ(root["width"].as<int>(), 1226);
  EXPECT_NEAR(root["stereo"]["baseline_m"].as<double>(), 0.537, 0.001);
  EXPECT_TRUE(root["stereo"]["rectified"].as<bool>());
  EXPECT_NEAR(root["camera"]["fx"].as<double>(), 707.0912, 1e-6);
  EXPECT_EQ(root["camera"]["distortion"].size(), 5u);
  EXPECT_TRUE(root["ground_truth"]["present"].as<bool>());
  EXPECT_EQ(root["ground_truth"]["poses"].as<int>(), 51);
  EXPECT_NEAR(root["ground_truth"]["path_length_m"].as<double>(), 59.9, 0.5);
  EXPECT_TRUE(root["depth_scale"].IsNull());
  EXPECT_GE(root["notes"].size(), 1u);
}

TEST(DatasetTest, OpensSensorSubFolderOfARecording) {
  SIGHTLINE_REQUIRE_DATA(tum, "tum_fr1_desk");
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  SIGHTLINE_REQUIRE_DATA(clouds, "pcl_clouds/grabber_sequences/pcd");
  const std::string rec = TempDir("recording");
  LinkTo(tum, rec + "/rgbd");
  LinkTo(kitti, rec + "/stereo");
  LinkTo(kitti + "/image_l", rec + "/mono");
  LinkTo(clouds, rec + "/cloud");
  testing::WriteText(rec + "/recording.yaml", "sensors: 4\n");
  testing::WriteText(rec + "/logs/readme.txt", "not a sensor\n");

  EXPECT_FALSE(DetectDataset(rec).has_value());
  const std::vector<std::string> sensors = ListRecordingSensors(rec);
  ASSERT_EQ(sensors.size(), 4u);
  EXPECT_EQ(sensors[0], rec + "/cloud");
  EXPECT_EQ(sensors[1], rec + "/mono");
  EXPECT_EQ(sensors[2], rec + "/rgbd");
  EXPECT_EQ(sensors[3], rec + "/stereo");

  auto stereo = OpenDataset(rec, SourceKind::kStereo);
  ASSERT_TRUE(stereo.ok()) << stereo.status().ToString();
  EXPECT_EQ((*stereo)->info().format, "KITTI odometry");
  EXPECT_EQ((*stereo)->info().path, rec + "/stereo");
  auto rgbd = OpenDataset(rec, SourceKind::kRgbd);
  ASSERT_TRUE(rgbd.ok());
  EXPECT_EQ((*rgbd)->info().frame_count, 9);
  auto mono = OpenDataset(rec, SourceKind::kMono);
  ASSERT_TRUE(mono.ok());
  EXPECT_EQ((*mono)->info().format, "image folder");
  auto richest = OpenDataset(rec);  // No wish: RGB-D before stereo, mono and clouds.
  ASSERT_TRUE(richest.ok());
  EXPECT_EQ((*richest)->info().kind, SourceKind::kRgbd);
  std::filesystem::remove(rec + "/rgbd");
  std::filesystem::remove(rec + "/stereo");
  std::filesystem::remove(rec + "/mono");
  auto only_cloud = OpenDataset(rec);
  ASSERT_TRUE(only_cloud.ok());
  EXPECT_EQ((*only_cloud)->info().kind, SourceKind::kCloud);
}

TEST(DatasetTest, RecordingWithoutTheWantedKindIsNotFoundListingSensors) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  const std::string rec = TempDir("recording_stereo_only");
  LinkTo(kitti, rec + "/stereo");
  auto source = OpenDataset(rec, SourceKind::kRgbd);
  EXPECT_EQ(source.status().code(), StatusCode::kNotFound);
  EXPECT_THAT(source.status().message(), HasSubstr("no RGB-D sensor"));
  EXPECT_THAT(source.status().message(), HasSubstr("stereo (KITTI odometry, stereo)"));
}

TEST(DatasetTest, DatasetOfAnotherKindIsInvalidArgument) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  auto source = OpenDataset(kitti, SourceKind::kRgbd);
  EXPECT_EQ(source.status().code(), StatusCode::kInvalidArgument);
  EXPECT_THAT(source.status().message(), HasSubstr("KITTI odometry dataset (stereo), not RGB-D"));
}

TEST(DatasetTest, EmptyFolderIsInvalidArgumentListingWhatWasLookedFor) {
  const std::string empty = TempDir("dataset_empty");
  auto source = OpenDataset(empty);
  EXPECT_EQ(source.status().code(), StatusCode::kInvalidArgument);
  EXPECT_THAT(source.status().message(), HasSubstr(empty));
  EXPECT_THAT(source.status().message(), HasSubstr("rgb.txt + depth.txt (TUM RGB-D)"));
  EXPECT_THAT(source.status().message(), HasSubstr("mav0/cam0/ (EuRoC)"));
  EXPECT_THAT(source.status().message(), HasSubstr("calib.txt + image_0/ or image_l/ (KITTI)"));
  EXPECT_THAT(source.status().message(), HasSubstr("(PCD)"));
  EXPECT_THAT(source.status().message(), HasSubstr("(image folder)"));
  EXPECT_TRUE(ListRecordingSensors(empty).empty());
}

TEST(DatasetTest, NonexistentPathIsNotFound) {
  const std::string missing = TempDir("dataset_missing") + "/no/such/dataset";
  auto source = OpenDataset(missing);
  EXPECT_EQ(source.status().code(), StatusCode::kNotFound);
  EXPECT_THAT(source.status().message(), HasSubstr(missing));
}

TEST(DatasetTest, OtherFileIsInvalidArgument) {
  const std::string file = TempDir("dataset_file") + "/notes.txt";
  testing::WriteText(file, "hello\n");
  auto source = OpenDataset(file);
  EXPECT_EQ(source.status().code(), StatusCode::kInvalidArgument);
  EXPECT_THAT(source.status().message(), HasSubstr("notes.txt"));
}

TEST(DatasetTest, ReaderErrorsPassThrough) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  const std::string dir = TempDir("dataset_bad_kitti");
  LinkTo(kitti + "/image_l", dir + "/image_l");
  LinkTo(kitti + "/image_r", dir + "/image_r");
  testing::WriteText(dir + "/calib.txt", "1 2 3 4 5 6 7\n");
  auto source = OpenDataset(dir);
  EXPECT_EQ(source.status().code(), StatusCode::kParseError);
  EXPECT_THAT(source.status().message(), HasSubstr("calib.txt line 1"));
}

}  // namespace
}  // namespace sightline
