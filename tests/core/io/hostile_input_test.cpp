// Hostile dataset input: files written by each test into a temporary folder (and copies of the
// real data) that once gave a silent wrong result or a misleading message. Each must now be an
// error naming the file, the line or field, and the actual cause.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "core/io/euroc_source.h"
#include "core/io/image_folder_source.h"
#include "core/io/image_loading.h"
#include "core/io/kitti_source.h"
#include "core/io/timed_file_list.h"
#include "core/io/tum_rgbd_source.h"
#include "tests/core/io/io_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::testing::HasSubstr;
using testing::LinkTo;
using testing::ReadLines;
using testing::TempDir;
using testing::WriteLines;
using testing::WriteText;

void WriteGrey(const std::string& path, int width, int height, int value = 128) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  ASSERT_TRUE(cv::imwrite(path, cv::Mat(height, width, CV_8UC1, cv::Scalar(value))));
}

void WriteDepth(const std::string& path, int width, int height) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  ASSERT_TRUE(cv::imwrite(path, cv::Mat(height, width, CV_16UC1, cv::Scalar(5000))));
}

// An image folder of `sizes.size()` grey frames with "time file" lines in times.txt.
std::string MakeImageFolder(const std::string& name, const std::vector<cv::Size>& sizes) {
  const std::string dir = TempDir(name);
  std::vector<std::string> times;
  for (size_t i = 0; i < sizes.size(); ++i) {
    const std::string file = "00000" + std::to_string(i) + ".png";
    WriteGrey(dir + "/" + file, sizes[i].width, sizes[i].height);
    times.push_back(std::to_string(0.1 * static_cast<double>(i)) + " " + file);
  }
  WriteLines(dir + "/times.txt", times);
  return dir;
}

// A TUM RGB-D folder of three 8x6 pairs listed in associations.txt.
std::string MakeTumFolder(const std::string& name) {
  const std::string dir = TempDir(name);
  std::vector<std::string> lines;
  for (int i = 0; i < 3; ++i) {
    const std::string t = std::to_string(1.0 + 0.1 * i);
    WriteGrey(dir + "/rgb/" + std::to_string(i) + ".png", 8, 6);
    WriteDepth(dir + "/depth/" + std::to_string(i) + ".png", 8, 6);
    lines.push_back(t + " rgb/" + std::to_string(i) + ".png " + t + " depth/" + std::to_string(i) +
                    ".png");
  }
  WriteLines(dir + "/associations.txt", lines);
  return dir;
}

// A KITTI folder with the real images linked and calib.txt copied.
std::string CopyKitti(const std::string& data, const std::string& name) {
  const std::string dir = TempDir(name);
  LinkTo(data + "/image_l", dir + "/image_l");
  LinkTo(data + "/image_r", dir + "/image_r");
  testing::CopyFileTo(data + "/calib.txt", dir + "/calib.txt");
  return dir;
}

// 51 KITTI times, 0.1 s apart, as lines.
std::vector<std::string> KittiTimes() {
  std::vector<std::string> times;
  for (int i = 0; i < 51; ++i) times.push_back(std::to_string(0.1 * i));
  return times;
}

// --- Timestamps -----------------------------------------------------------------------------

TEST(HostileInput, KittiTimesGoingBackwardsOrRepeatingNameFileAndLine) {
  SIGHTLINE_REQUIRE_DATA(data, "kitti_clip1");
  const std::string dir = CopyKitti(data, "hostile_kitti_times");
  std::vector<std::string> times = KittiTimes();
  times[3] = times[2];  // Line 4 repeats line 3.
  WriteLines(dir + "/times.txt", times);
  Status status = KittiSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("times.txt line 4"));
  EXPECT_THAT(status.message(), HasSubstr("equal to the previous"));

  times = KittiTimes();
  times[10] = "0.5";  // Line 11 goes back.
  WriteLines(dir + "/times.txt", times);
  status = KittiSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("times.txt line 11"));
  EXPECT_THAT(status.message(), HasSubstr("before the previous"));

  WriteLines(dir + "/times.txt", KittiTimes());
  EXPECT_TRUE(KittiSource(dir).Open().ok());
}

TEST(HostileInput, RepeatedTimesInEveryListAreRejected) {
  const std::string dir = TempDir("hostile_lists");
  WriteText(dir + "/rgb.txt", "# rgb\n1.0 rgb/a.png\n1.0 rgb/b.png\n");
  StatusOr<std::vector<TimedFile>> list = ReadTimedFileList(dir + "/rgb.txt");
  ASSERT_FALSE(list.ok());
  EXPECT_THAT(list.status().message(), HasSubstr("rgb.txt line 3"));

  const std::string folder = MakeImageFolder("hostile_folder_times", {{8, 6}, {8, 6}, {8, 6}});
  WriteLines(folder + "/times.txt", {"0.0 000000.png", "0.2 000001.png", "0.1 000002.png"});
  const Status status = ImageFolderSource(folder).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("times.txt line 3"));

  const std::string tum = MakeTumFolder("hostile_tum_times");
  std::vector<std::string> lines = ReadLines(tum + "/associations.txt");
  lines[2] = "1.1 rgb/2.png 1.1 depth/2.png";  // Repeats line 2's time.
  WriteLines(tum + "/associations.txt", lines);
  const Status tum_status = TumRgbdSource(tum).Open();
  EXPECT_EQ(tum_status.code(), StatusCode::kParseError);
  EXPECT_THAT(tum_status.message(), HasSubstr("associations.txt line 3"));
}

TEST(HostileInput, RepeatedGroundTruthTimesAreRejectedNamingFileAndLine) {
  const std::string tum = MakeTumFolder("hostile_tum_gt");
  WriteText(tum + "/groundtruth.txt",
            "# t tx ty tz qx qy qz qw\n1.0 0 0 0 0 0 0 1\n1.1 0 0 0 0 0 0 1\n"
            "1.1 0.1 0 0 0 0 0 1\n");
  const Status tum_status = TumRgbdSource(tum).Open();
  EXPECT_EQ(tum_status.code(), StatusCode::kParseError);
  EXPECT_THAT(tum_status.message(), HasSubstr("groundtruth.txt line 4"));
  EXPECT_THAT(tum_status.message(), HasSubstr("equal to the previous one"));

  SIGHTLINE_REQUIRE_DATA(data, "euroc_v1_01_static");
  const std::string euroc = TempDir("hostile_euroc_gt");
  const std::string mav0 = euroc + "/mav0";
  for (const char* part : {"body.yaml", "cam0", "cam1"}) {
    LinkTo(data + "/mav0/" + part, mav0 + "/" + part);
  }
  std::vector<std::string> tum_rows =
      ReadLines(data + "/mav0/state_groundtruth_estimate0/groundtruth_tum.txt");
  ASSERT_GT(tum_rows.size(), 4u);
  tum_rows[3] = tum_rows[2];  // The second pose's time again.
  WriteLines(mav0 + "/state_groundtruth_estimate0/groundtruth_tum.txt", tum_rows);
  Status status = EurocSource(euroc).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("groundtruth_tum.txt line 4"));

  // EuRoC's own data.csv (nanoseconds), read when there is no groundtruth_tum.txt.
  std::filesystem::remove(mav0 + "/state_groundtruth_estimate0/groundtruth_tum.txt");
  WriteText(mav0 + "/state_groundtruth_estimate0/data.csv",
            "#timestamp, p_x, p_y, p_z, q_w, q_x, q_y, q_z\n"
            "1403715273262142976,0,0,0,1,0,0,0\n1403715273262142976,0,0,0,1,0,0,0\n");
  status = EurocSource(euroc).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("data.csv line 3"));
}

// --- Paths in index files -------------------------------------------------------------------

TEST(HostileInput, ListedPathsMustStayInsideTheDataset) {
  EXPECT_TRUE(CheckListedPath("rgb/1.png", "l.txt", 1).ok());
  EXPECT_TRUE(CheckListedPath("rgb/../rgb/1.png", "l.txt", 1).ok());
  EXPECT_TRUE(CheckListedPath("./1.png", "l.txt", 1).ok());
  for (const char* bad : {"../1.png", "rgb/../../1.png", "/etc/passwd", "a/./../.."}) {
    const Status status = CheckListedPath(bad, "dir/l.txt", 7);
    EXPECT_EQ(status.code(), StatusCode::kParseError) << bad;
    EXPECT_THAT(status.message(), HasSubstr("dir/l.txt line 7")) << bad;
    EXPECT_THAT(status.message(), HasSubstr(bad)) << bad;
  }
}

TEST(HostileInput, DotDotOrAbsolutePathsInIndexFilesNameFileAndLine) {
  const std::string outside = TempDir("hostile_outside");
  WriteGrey(outside + "/secret.png", 8, 6);

  const std::string tum = MakeTumFolder("hostile_tum_paths");
  std::vector<std::string> lines = ReadLines(tum + "/associations.txt");
  lines[1] = "1.1 ../" + std::filesystem::path(outside).filename().string() +
             "/secret.png 1.1 depth/1.png";
  WriteLines(tum + "/associations.txt", lines);
  Status status = TumRgbdSource(tum).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("associations.txt line 2"));
  EXPECT_THAT(status.message(), HasSubstr("leaves the dataset folder"));

  lines = ReadLines(tum + "/associations.txt");
  lines[1] = "1.1 rgb/1.png 1.1 " + outside + "/secret.png";
  WriteLines(tum + "/associations.txt", lines);
  status = TumRgbdSource(tum).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("associations.txt line 2"));
  EXPECT_THAT(status.message(), HasSubstr("absolute path"));

  const std::string folder = MakeImageFolder("hostile_folder_paths", {{8, 6}, {8, 6}});
  WriteLines(folder + "/times.txt", {"0.0 000000.png", "0.1 ../000001.png"});
  status = ImageFolderSource(folder).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("times.txt line 2"));
}

TEST(HostileInput, DotDotInEurocDataCsvNamesLine) {
  SIGHTLINE_REQUIRE_DATA(data, "euroc_v1_01_static");
  const std::string dir = TempDir("hostile_euroc_paths");
  for (const char* part : {"cam1", "state_groundtruth_estimate0", "body.yaml"}) {
    LinkTo(data + "/mav0/" + std::string(part), dir + "/mav0/" + part);
  }
  LinkTo(data + "/mav0/cam0/data", dir + "/mav0/cam0/data");
  LinkTo(data + "/mav0/cam0/sensor.yaml", dir + "/mav0/cam0/sensor.yaml");
  std::vector<std::string> lines = ReadLines(data + "/mav0/cam0/data.csv");
  const size_t comma = lines[3].find(',');
  lines[3] = lines[3].substr(0, comma) + ",../../cam1/data/" + lines[3].substr(comma + 1);
  WriteLines(dir + "/mav0/cam0/data.csv", lines);
  const Status status = EurocSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("cam0/data.csv line 4"));
  EXPECT_THAT(status.message(), HasSubstr("leaves the dataset folder"));
}

// --- Frame size mid-sequence ----------------------------------------------------------------

TEST(HostileInput, AFrameOfAnotherSizeMidSequenceNamesTheFile) {
  const std::string dir = MakeImageFolder("hostile_size", {{8, 6}, {8, 6}, {10, 6}});
  ImageFolderSource source(dir);
  ASSERT_TRUE(source.Open().ok());
  for (int i = 0; i < 2; ++i) {
    ASSERT_TRUE(source.Grab().ok());
    EXPECT_TRUE(source.Retrieve().ok()) << i;
  }
  ASSERT_TRUE(source.Grab().ok());
  StatusOr<Frame> third = source.Retrieve();
  ASSERT_FALSE(third.ok());
  EXPECT_EQ(third.status().code(), StatusCode::kParseError);
  EXPECT_THAT(third.status().message(), HasSubstr("000002.png"));
  EXPECT_THAT(third.status().message(), HasSubstr("image is 10x6"));
  EXPECT_THAT(third.status().message(), HasSubstr("8x6"));
}

TEST(HostileInput, AKittiPairOfAnotherSizeNamesTheFile) {
  SIGHTLINE_REQUIRE_DATA(data, "kitti_clip1");
  const std::string dir = TempDir("hostile_kitti_size");
  testing::LinkFolderFiles(data + "/image_l", dir + "/image_l", {"000002.png"});
  testing::LinkFolderFiles(data + "/image_r", dir + "/image_r", {"000002.png"});
  testing::CopyFileTo(data + "/calib.txt", dir + "/calib.txt");
  WriteGrey(dir + "/image_l/000002.png", 320, 100);
  WriteGrey(dir + "/image_r/000002.png", 320, 100);
  KittiSource source(dir);
  ASSERT_TRUE(source.Open().ok());
  ASSERT_TRUE(source.Seek(2).ok());
  ASSERT_TRUE(source.Grab().ok());
  StatusOr<Frame> frame = source.Retrieve();
  ASSERT_FALSE(frame.ok());
  EXPECT_THAT(frame.status().message(), HasSubstr("image_l/000002.png"));
  EXPECT_THAT(frame.status().message(), HasSubstr("changes size"));
}

// --- Absurd intrinsics and distortion -------------------------------------------------------

// A copy of the EuRoC tree whose cam0/sensor.yaml has `key` set to `value`.
std::string EurocWith(const std::string& data, const std::string& name, const std::string& key,
                      const std::string& value) {
  const std::string dir = TempDir(name);
  for (const char* part : {"cam1", "state_groundtruth_estimate0", "body.yaml"}) {
    LinkTo(data + "/mav0/" + std::string(part), dir + "/mav0/" + part);
  }
  LinkTo(data + "/mav0/cam0/data", dir + "/mav0/cam0/data");
  LinkTo(data + "/mav0/cam0/data.csv", dir + "/mav0/cam0/data.csv");
  std::vector<std::string> lines = ReadLines(data + "/mav0/cam0/sensor.yaml");
  bool replaced = false;
  for (std::string& line : lines) {
    if (line.rfind(key + ":", 0) == 0) line = key + ": " + value, replaced = true;
  }
  EXPECT_TRUE(replaced) << key;
  WriteLines(dir + "/mav0/cam0/sensor.yaml", lines);
  return dir;
}

TEST(HostileInput, AbsurdEurocDistortionAndFocalLengthAreRejectedNamingTheKey) {
  SIGHTLINE_REQUIRE_DATA(data, "euroc_v1_01_static");
  struct Case {
    const char* key;
    const char* value;
    const char* says;
  };
  for (const Case& c : {
           Case{"distortion_coefficients", "[-1e10, 0.07, 0.0002, 0.00002]", "k1 = -1e+10"},
           Case{"distortion_coefficients", "[-0.28, 1e30, 0.0002, 0.00002]", "k2 = 1e+30"},
           Case{"intrinsics", "[1e-300, 456.134, 379.999, 255.238]", "fx = 1e-300"},
           Case{"intrinsics", "[-458.654, 457.296, 367.215, 248.375]", "fx = -458.654"},
       }) {
    const Status status = EurocSource(EurocWith(data, "hostile_euroc", c.key, c.value)).Open();
    EXPECT_EQ(status.code(), StatusCode::kParseError) << c.value;
    EXPECT_THAT(status.message(), HasSubstr("cam0/sensor.yaml")) << c.value;
    EXPECT_THAT(status.message(), HasSubstr(std::string("'") + c.key + "'")) << c.value;
    EXPECT_THAT(status.message(), HasSubstr(c.says)) << status.message();
  }
}

TEST(HostileInput, NegativeFocalLengthInKittiCalibNamesFx) {
  SIGHTLINE_REQUIRE_DATA(data, "kitti_clip1");
  const std::string dir = CopyKitti(data, "hostile_kitti_fx");
  std::vector<std::string> lines = ReadLines(dir + "/calib.txt");
  const size_t colon = lines[0].find(':');
  const std::string body = colon == std::string::npos ? lines[0] : lines[0].substr(colon + 1);
  lines[0] = (colon == std::string::npos ? "" : lines[0].substr(0, colon + 1)) + " -" +
             body.substr(body.find_first_not_of(' '));
  WriteLines(dir + "/calib.txt", lines);
  const Status status = KittiSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("calib.txt"));
  EXPECT_THAT(status.message(), HasSubstr("P0"));
  EXPECT_THAT(status.message(), HasSubstr("focal length fx = -"));
}

// --- What a file is, said rightly ---------------------------------------------------------

TEST(HostileInput, AFolderOrDeviceWhereAnOptionalFileBelongsIsNotIgnored) {
  const std::string dir = MakeImageFolder("hostile_yaml_device", {{8, 6}, {8, 6}});
  std::filesystem::create_symlink("/dev/zero", dir + "/camera.yaml");
  Status status = ImageFolderSource(dir).Open();
  EXPECT_FALSE(status.ok());
  EXPECT_THAT(status.message(), HasSubstr("camera.yaml is not a regular file"));

  std::filesystem::remove(dir + "/camera.yaml");
  std::filesystem::create_directories(dir + "/camera.yaml");
  status = ImageFolderSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_THAT(status.message(), HasSubstr("camera.yaml is a folder"));

  const std::string tum = MakeTumFolder("hostile_tum_folder_image");
  std::filesystem::remove(tum + "/rgb/1.png");
  std::filesystem::create_directories(tum + "/rgb/1.png");
  status = TumRgbdSource(tum).Open();
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_THAT(status.message(), HasSubstr("rgb/1.png is a folder, not a file"));
}

// Runs LoadImage8(path) as an unprivileged user (root reads every file whatever its mode) and
// returns its message; "" when the child could not drop its privileges.
std::string LoadAsNobody(const std::string& path) {
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) return "";
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(pipe_fds[0]);
    std::string message = "(could not drop privileges)";
    if (::setgid(65534) == 0 && ::setuid(65534) == 0) {
      const StatusOr<cv::Mat> image = LoadImage8(path);
      message = image.ok() ? "(read)" : image.status().message();
    }
    (void)!::write(pipe_fds[1], message.data(), message.size());
    ::_exit(0);
  }
  ::close(pipe_fds[1]);
  std::string message;
  char buffer[512];
  for (ssize_t n; (n = ::read(pipe_fds[0], buffer, sizeof(buffer))) > 0;) message.append(buffer, n);
  ::close(pipe_fds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  return message;
}

TEST(HostileInput, AnUnreadableImageSaysPermissionDeniedNotCannotDecode) {
  const std::string dir = TempDir("hostile_unreadable");
  const std::string path = dir + "/000000.png";
  WriteGrey(path, 8, 6);
  ASSERT_EQ(::chmod(path.c_str(), 0), 0);
  std::string message;
  if (::geteuid() == 0) {
    ASSERT_EQ(::chmod(dir.c_str(), 0755), 0);  // The unprivileged child may look inside.
    message = LoadAsNobody(path);
    if (message == "(could not drop privileges)") GTEST_SKIP() << "cannot run as nobody";
  } else {
    const StatusOr<cv::Mat> image = LoadImage8(path);
    ASSERT_FALSE(image.ok());
    message = image.status().message();
  }
  EXPECT_THAT(message, HasSubstr("000000.png cannot be read: permission denied"));
  EXPECT_THAT(message, ::testing::Not(HasSubstr("decode")));
}

}  // namespace
}  // namespace sightline
