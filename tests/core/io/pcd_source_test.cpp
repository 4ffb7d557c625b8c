#include "core/io/pcd_source.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "tests/core/io/io_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;
using testing::WriteText;

struct CloudStats {
  size_t invalid = 0;
  size_t coloured = 0;
};

CloudStats Stats(const PointCloud& cloud) {
  CloudStats s;
  for (size_t i = 0; i < cloud.size(); ++i) {
    if (!std::isfinite(cloud.points[i].z())) ++s.invalid;
    if (cloud.has_colors() && cloud.colors[i].cast<int>().sum() > 0) ++s.coloured;
  }
  return s;
}

class PcdFileTest : public ::testing::TestWithParam<const char*> {};

TEST_P(PcdFileTest, OpensAsOneOrganizedColouredCloud) {
  SIGHTLINE_REQUIRE_DATA(path, std::string("pcl_clouds/") + GetParam());
  PcdSource source(path);
  ASSERT_TRUE(source.Open().ok()) << source.Open().ToString();
  EXPECT_EQ(source.info().format, "PCD");
  EXPECT_EQ(source.info().kind, SourceKind::kCloud);
  EXPECT_EQ(source.info().frame_count, 1);
  EXPECT_EQ(source.info().width, 640);
  EXPECT_EQ(source.info().height, 480);
  ASSERT_TRUE(source.Grab().ok());
  auto frame = source.Retrieve();
  ASSERT_TRUE(frame.ok()) << frame.status().ToString();
  const PointCloud& cloud = *std::get<CloudFrame>(*frame).cloud;
  EXPECT_TRUE(cloud.organized());
  EXPECT_EQ(cloud.width, 640);
  EXPECT_EQ(cloud.height, 480);
  EXPECT_EQ(cloud.size(), 640u * 480u);
  EXPECT_TRUE(cloud.has_colors());
  const CloudStats stats = Stats(cloud);
  // Kinect-class clouds: holes kept as NaN (11-32 % here), almost every point coloured.
  EXPECT_GT(stats.invalid, cloud.size() / 10);
  EXPECT_LT(stats.invalid, cloud.size() / 2);
  EXPECT_GT(stats.coloured, cloud.size() * 99 / 100);
  // Valid points lie in front of the sensor at Kinect range.
  size_t plausible = 0, valid = 0;
  for (const Eigen::Vector3f& p : cloud.points) {
    if (!std::isfinite(p.z())) continue;
    ++valid;
    plausible += (p.z() > 0.2f && p.z() < 10.f) ? 1 : 0;
  }
  EXPECT_GT(plausible, valid * 95 / 100);
  EXPECT_EQ(source.Grab().code(), StatusCode::kOutOfRange);
}

INSTANTIATE_TEST_SUITE_P(PclClouds, PcdFileTest,
                         ::testing::Values("office1.pcd", "milk_cartoon_all_small_clorox.pcd",
                                           "table_scene_mug_stereo_textured.pcd"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           std::string name = info.param;
                           return name.substr(0, name.find('.'));
                         });

TEST(PcdSourceTest, FolderOfThreeFramesWithTimesFromNames) {
  SIGHTLINE_REQUIRE_DATA(dir, "pcl_clouds/grabber_sequences/pcd");
  PcdSource source(dir);
  ASSERT_TRUE(source.Open().ok());
  const SourceInfo& info = source.info();
  EXPECT_EQ(info.frame_count, 3);
  EXPECT_EQ(info.width, 640);
  EXPECT_EQ(info.height, 480);
  EXPECT_NEAR(info.duration_s, 56.332395 - 55.814212, 1e-5);
  int count = 0;
  double previous = 0;
  while (source.Grab().ok()) {
    auto frame = source.Retrieve();
    ASSERT_TRUE(frame.ok());
    const CloudFrame& cloud = std::get<CloudFrame>(*frame);
    EXPECT_EQ(cloud.stamp.sequence_id, count);
    EXPECT_TRUE(cloud.cloud->organized());
    if (count > 0) EXPECT_NEAR(cloud.stamp.sensor_time_s - previous, 0.25, 0.02);
    previous = cloud.stamp.sensor_time_s;
    ++count;
  }
  EXPECT_EQ(count, 3);
}

TEST(PcdSourceTest, TimeFromFileName) {
  ASSERT_TRUE(TimeFromFileName("frame_20121214T142255.814212.pcd").has_value());
  // 2012-12-14 14:22:55.814212 UTC.
  EXPECT_NEAR(*TimeFromFileName("frame_20121214T142255.814212.pcd"), 1355494975.814212, 1e-5);
  EXPECT_NEAR(*TimeFromFileName("1305031453.359684.pcd"), 1305031453.359684, 1e-6);
  EXPECT_FALSE(TimeFromFileName("office1.pcd").has_value());
}

TEST(PcdSourceTest, AsciiXyzCloudWithoutColourIsUnorganized) {
  const std::string dir = TempDir("pcd_ascii");
  WriteText(dir + "/a.pcd",
            "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
            "WIDTH 3\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3\nDATA ascii\n"
            "1 2 3\nnan nan nan\n0.5 0.25 4\n");
  auto cloud = ReadPcdFile(dir + "/a.pcd");
  ASSERT_TRUE(cloud.ok()) << cloud.status().ToString();
  EXPECT_EQ(cloud->size(), 3u);
  EXPECT_FALSE(cloud->organized());
  EXPECT_FALSE(cloud->has_colors());
  EXPECT_EQ(cloud->width, 3);
  EXPECT_FLOAT_EQ(cloud->points[2].y(), 0.25f);
  EXPECT_TRUE(std::isnan(cloud->points[1].x()));
  // Also a one-frame folder.
  PcdSource source(dir);
  ASSERT_TRUE(source.Open().ok());
  EXPECT_EQ(source.info().frame_count, 1);
}

TEST(PcdSourceTest, GarbageFileIsParseErrorNamingTheFile) {
  const std::string dir = TempDir("pcd_garbage");
  std::string garbage;
  for (int i = 0; i < 4096; ++i) garbage.push_back(static_cast<char>((i * 7919 + 13) % 256));
  WriteText(dir + "/broken.pcd", garbage);
  auto cloud = ReadPcdFile(dir + "/broken.pcd");
  EXPECT_EQ(cloud.status().code(), StatusCode::kParseError);
  EXPECT_THAT(cloud.status().message(), HasSubstr("broken.pcd"));
  const Status status = PcdSource(dir).Open();  // Headers are checked when opening.
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("broken.pcd"));
}

TEST(PcdSourceTest, TruncatedDataIsParseErrorAtRetrieve) {
  SIGHTLINE_REQUIRE_DATA(office, "pcl_clouds/office1.pcd");
  const std::string dir = TempDir("pcd_truncated");
  std::ifstream in(office, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 100000u);
  WriteText(dir + "/cut.pcd", bytes.substr(0, bytes.size() / 3));
  PcdSource source(dir + "/cut.pcd");
  ASSERT_TRUE(source.Open().ok());  // The header is intact.
  ASSERT_TRUE(source.Grab().ok());
  const Status status = source.Retrieve().status();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("cut.pcd"));
}

TEST(PcdSourceTest, TruncatedBinaryIsParseErrorWhenOpening) {
  const std::string dir = TempDir("pcd_binary");
  std::string text =
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 4\nHEIGHT 1\n"
      "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4\nDATA binary\n";
  const float xyz[12] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  const std::string full = text + std::string(reinterpret_cast<const char*>(xyz), sizeof(xyz));
  WriteText(dir + "/full.pcd", full);
  auto cloud = ReadPcdFile(dir + "/full.pcd");
  ASSERT_TRUE(cloud.ok()) << cloud.status().ToString();
  EXPECT_FLOAT_EQ(cloud->points[3].z(), 12.f);
  WriteText(dir + "/cut.pcd", full.substr(0, full.size() - 20));
  const Status status = PcdSource(dir + "/cut.pcd").Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("cut.pcd"));
  EXPECT_THAT(status.message(), HasSubstr("truncated"));
}

TEST(PcdSourceTest, MissingAndEmptyAreNotFound) {
  const std::string dir = TempDir("pcd_empty");
  Status status = PcdSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_THAT(status.message(), HasSubstr("no .pcd files"));
  status = PcdSource(dir + "/gone.pcd").Open();
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_THAT(status.message(), HasSubstr("gone.pcd"));
  EXPECT_EQ(ReadPcdFile(dir + "/gone.pcd").status().code(), StatusCode::kNotFound);
}

}  // namespace
}  // namespace sightline
