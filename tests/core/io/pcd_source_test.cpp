#include "core/io/pcd_source.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>

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

TEST(PcdSourceTest, TruncatedCompressedDataIsParseErrorWhenOpening) {
  SIGHTLINE_REQUIRE_DATA(office, "pcl_clouds/office1.pcd");
  const std::string dir = TempDir("pcd_truncated");
  std::ifstream in(office, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 100000u);
  WriteText(dir + "/cut.pcd", bytes.substr(0, bytes.size() / 3));
  // The compressed block's size, in front of it, no longer fits the file: refused at once.
  const Status status = PcdSource(dir + "/cut.pcd").Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("cut.pcd"));
  EXPECT_THAT(status.message(), HasSubstr("does not fit in the file"));
  EXPECT_EQ(ReadPcdFile(dir + "/cut.pcd").status().code(), StatusCode::kParseError);
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

// Hostile PCD files: each is refused when opening and when reading, naming the file and what is
// wrong, before anything the header declares is allocated.
class HostilePcd : public ::testing::Test {
 protected:
  // Expects both entry points to refuse `name` with a message holding `why`.
  static void ExpectRefused(const std::string& path, const std::string& why) {
    auto cloud = ReadPcdFile(path);
    EXPECT_EQ(cloud.status().code(), StatusCode::kParseError) << cloud.status().ToString();
    EXPECT_THAT(cloud.status().message(), HasSubstr(path));
    EXPECT_THAT(cloud.status().message(), HasSubstr(why));
    const Status opened = PcdSource(path).Open();
    EXPECT_EQ(opened.code(), StatusCode::kParseError) << opened.ToString();
    EXPECT_THAT(opened.message(), HasSubstr(why));
  }
  static std::string Header(const std::string& size, const std::string& type, int width, int height,
                            long long points, const std::string& data) {
    return "VERSION 0.7\nFIELDS x y z\nSIZE " + size + "\nTYPE " + type + "\nCOUNT 1 1 1\nWIDTH " +
           std::to_string(width) + "\nHEIGHT " + std::to_string(height) +
           "\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + std::to_string(points) + "\nDATA " + data + "\n";
  }
  // A real compressed cloud's bytes, with `edit` applied.
  static std::string RealCompressed() {
    const std::string path = testing::DataPath("pcl_clouds/milk_cartoon_all_small_clorox.pcd");
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }
  const std::string dir_ = TempDir("pcd_hostile");
};

TEST_F(HostilePcd, CompressedHeaderWithAZeroBodyIsRefused) {
  const std::string text =
      "VERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\nWIDTH 64\n"
      "HEIGHT 48\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3072\nDATA binary_compressed\n";
  WriteText(dir_ + "/zeros.pcd", text + std::string(308, '\0'));
  ExpectRefused(dir_ + "/zeros.pcd", "cannot fit in 308 bytes");
  // A body long enough to pass the size bound still declares an empty block.
  WriteText(dir_ + "/zeros_long.pcd", text + std::string(400, '\0'));
  ExpectRefused(dir_ + "/zeros_long.pcd", "binary_compressed block of 0 bytes");
}

TEST_F(HostilePcd, RealCompressedCloudWithTenTimesThePointsIsRefused) {
  SIGHTLINE_REQUIRE_DATA(milk, "pcl_clouds/milk_cartoon_all_small_clorox.pcd");
  std::string bytes = RealCompressed();
  const size_t width = bytes.find("WIDTH 640\n"), points = bytes.find("POINTS 307200\n");
  ASSERT_NE(width, std::string::npos);
  ASSERT_NE(points, std::string::npos);
  bytes.replace(points, 14, "POINTS 3072000\n");
  bytes.replace(width, 10, "WIDTH 6400\n");
  WriteText(dir_ + "/ten_times.pcd", bytes);
  ExpectRefused(dir_ + "/ten_times.pcd", "expands to");
}

TEST_F(HostilePcd, CompressedSizeOfNearlyFourGigabytesIsRefused) {
  SIGHTLINE_REQUIRE_DATA(milk, "pcl_clouds/milk_cartoon_all_small_clorox.pcd");
  std::string bytes = RealCompressed();
  const size_t data = bytes.find("DATA binary_compressed\n");
  ASSERT_NE(data, std::string::npos);
  const uint32_t huge = 0xFFFFFFF0u;
  bytes.replace(data + 23 + 4, 4, reinterpret_cast<const char*>(&huge), 4);
  WriteText(dir_ + "/huge.pcd", bytes);
  ExpectRefused(dir_ + "/huge.pcd", "expands to 4294967280 bytes");
}

TEST_F(HostilePcd, HeadersThatLieAboutTheirSizeAreRefusedBeforeAllocating) {
  WriteText(dir_ + "/ascii.pcd",
            Header("4 4 4", "F F F", 250000000, 1, 250000000, "ascii") + "1 2 3\n");
  ExpectRefused(dir_ + "/ascii.pcd", "at most 50000000");
  WriteText(dir_ + "/ascii_small.pcd",
            Header("4 4 4", "F F F", 2000000, 1, 2000000, "ascii") + std::string(86000, '1'));
  ExpectRefused(dir_ + "/ascii_small.pcd", "cannot fit");
  WriteText(dir_ + "/binary.pcd",
            Header("4 4 4", "F F F", 2000000, 1, 2000000, "binary") + std::string(1200, '\0'));
  ExpectRefused(dir_ + "/binary.pcd", "truncated");
  // The cap + 1.
  WriteText(dir_ + "/cap.pcd",
            Header("4 4 4", "F F F", 50000001, 1, 50000001, "binary") + std::string(12, '\0'));
  ExpectRefused(dir_ + "/cap.pcd", "50000001 points; at most 50000000");
}

TEST_F(HostilePcd, InconsistentFieldsAreRefused) {
  const float xyz[3] = {1, 2, 3};
  const std::string point(reinterpret_cast<const char*>(xyz), sizeof(xyz));
  WriteText(dir_ + "/size3.pcd", Header("3 3 3", "F F F", 1, 1, 1, "binary") + point);
  ExpectRefused(dir_ + "/size3.pcd", "field 'x'");
  WriteText(dir_ + "/points.pcd", Header("4 4 4", "F F F", 2, 1, 1, "binary") + point + point);
  ExpectRefused(dir_ + "/points.pcd", "is not POINTS");
  // A SIZE beyond int's range is named as written (its message once overflowed an int cast).
  WriteText(dir_ + "/huge_size.pcd", Header("4 4 3297380000", "F F F", 1, 1, 1, "binary") + point);
  ExpectRefused(dir_ + "/huge_size.pcd", "with SIZE 3297380000");
  WriteText(dir_ + "/double.pcd", Header("8 8 8", "F F F", 1, 1, 1, "binary") + point + point);
  ExpectRefused(dir_ + "/double.pcd", "4-byte float");
}

// PCL reads a header line by the prefix of its first word, sizes its buffer at POINTS, and goes
// on reading header lines after DATA: a layout line after POINTS made its ASCII reader write
// past its buffer. Each such header is refused before PCL reads it.
TEST_F(HostilePcd, HeadersPclWouldReadOtherwiseAreRefused) {
  const std::string layout_after_points =
      "VERSION 0.7\nFIELDS x y\nSIZE 4 4\nTYPE F F\nWIDTH 2\nHEIGHT 1\nPOINTS 2\n"
      "FIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F F\nDATA ascii\n4 4 4 4\n4 4 4 4\n";
  WriteText(dir_ + "/late_fields.pcd", layout_after_points);
  ExpectRefused(dir_ + "/late_fields.pcd", "line 8: repeats the FIELDS line");
  const std::string size_after_points =
      "VERSION 0.7\nFIELDS x y z\nTYPE F F F\nWIDTH 2\nHEIGHT 1\nPOINTS 2\nSIZE 4 4 4\n"
      "DATA ascii\n4 4 4\n4 4 4\n";
  WriteText(dir_ + "/late_size.pcd", size_after_points);
  ExpectRefused(dir_ + "/late_size.pcd", "SIZE must come before POINTS");
  WriteText(dir_ + "/prefix.pcd", Header("4 4 4", "F F F", 1, 1, 1, "ascii") + "WIDTHS 9\n1 2 3\n");
  ExpectRefused(dir_ + "/prefix.pcd", "data begins with a header line ('WIDTHS')");
  std::string prefix_key = Header("4 4 4", "F F F", 1, 1, 1, "ascii") + "1 2 3\n";
  prefix_key.replace(prefix_key.find("HEIGHT 1"), 8, "HEIGHTS 1");
  WriteText(dir_ + "/prefix_key.pcd", prefix_key);
  ExpectRefused(dir_ + "/prefix_key.pcd", "'HEIGHTS' is not a header key");
  std::string control = Header("4 4 4", "F F F", 1, 1, 1, "ascii") + "1 2 3\n";
  control.replace(control.find("SIZE 4 4 4"), 10, "SIZE 4\v4 4");
  WriteText(dir_ + "/control.pcd", control);
  ExpectRefused(dir_ + "/control.pcd", "control or non-ASCII bytes");
  std::string unknown = Header("4 4 4", "F F F", 1, 1, 1, "ascii") + "1 2 3\n";
  unknown.insert(unknown.find("WIDTH"), "SCALE 1\n");
  WriteText(dir_ + "/unknown.pcd", unknown);
  ExpectRefused(dir_ + "/unknown.pcd", "unknown key 'SCALE'");
  // PCL's header skips a '#' line after DATA, its ASCII body reads it as a point (z = 0).
  WriteText(dir_ + "/comment.pcd", Header("4 4 4", "F F F", 1, 1, 1, "ascii") + "# a\n1 2 3\n");
  ExpectRefused(dir_ + "/comment.pcd", "data begins with a '#' line");
  // The same cloud without the extra line reads: the checks refuse only what is ambiguous.
  WriteText(dir_ + "/plain.pcd", Header("4 4 4", "F F F", 1, 1, 1, "ascii") + "\n1 2 3\n");
  auto plain = ReadPcdFile(dir_ + "/plain.pcd");
  ASSERT_TRUE(plain.ok()) << plain.status().ToString();
  ASSERT_EQ(plain->size(), 1u);
  EXPECT_FLOAT_EQ(plain->points[0].z(), 3.0f);
}

}  // namespace
}  // namespace sightline
