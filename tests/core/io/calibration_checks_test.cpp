// The checks shared by the calibration file readers: what is wrong with the path itself (a
// folder, a device, an empty or unreadable file) gets its own message from every reader, a key
// given twice is rejected, and CheckCameraValues / CheckRotation name the field.
#include "core/io/calibration_checks.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>

#include "core/io/camera_yaml.h"
#include "core/io/floor_file.h"
#include "core/io/hand_eye_file.h"
#include "core/io/stereo_calibration_file.h"
#include "tests/core/io/io_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;
using testing::WriteText;

struct Reader {
  const char* kind;
  std::function<Status(const std::string&)> read;
};

std::vector<Reader> Readers() {
  return {{"camera.yaml", [](const std::string& p) { return ReadCameraYaml(p).status(); }},
          {"stereo", [](const std::string& p) { return ReadStereoCalibration(p).status(); }},
          {"hand_eye", [](const std::string& p) { return ReadHandEyeFile(p).status(); }},
          {"floor", [](const std::string& p) { return ReadFloorCalibration(p).status(); }}};
}

// The message of `read(path)` in a child process without root's right to read any file; "" when
// privileges cannot be dropped.
std::string MessageWithoutRoot(const Reader& reader, const std::string& path) {
  int fds[2];
  if (pipe(fds) != 0) return "";
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    std::string message = "cannot drop privileges";
    if (geteuid() != 0 || (setgid(65534) == 0 && setuid(65534) == 0)) {
      message = reader.read(path).message();
    }
    const ssize_t ignored = write(fds[1], message.data(), message.size());
    (void)ignored;
    _exit(0);
  }
  close(fds[1]);
  std::string message;
  char buffer[512];
  for (ssize_t n; (n = read(fds[0], buffer, sizeof(buffer))) > 0;) message.append(buffer, n);
  close(fds[0]);
  waitpid(pid, nullptr, 0);
  return message == "cannot drop privileges" ? "" : message;
}

TEST(CalibrationChecks, EveryReaderSaysWhatIsWrongWithThePath) {
  const std::string dir = TempDir("calibration_paths");
  WriteText(dir + "/empty.yaml", "");
  for (const Reader& reader : Readers()) {
    SCOPED_TRACE(reader.kind);
    const Status missing = reader.read(dir + "/absent.yaml");
    EXPECT_EQ(missing.code(), StatusCode::kNotFound);
    EXPECT_THAT(missing.message(), HasSubstr(dir + "/absent.yaml: no such file"));
    const Status folder = reader.read(dir);
    EXPECT_EQ(folder.code(), StatusCode::kInvalidArgument);
    EXPECT_THAT(folder.message(), HasSubstr(dir + " is a folder"));
    const Status device = reader.read("/dev/zero");
    EXPECT_EQ(device.code(), StatusCode::kInvalidArgument);
    EXPECT_THAT(device.message(), HasSubstr("/dev/zero is not a regular file"));
    const Status empty = reader.read(dir + "/empty.yaml");
    EXPECT_EQ(empty.code(), StatusCode::kParseError);
    EXPECT_THAT(empty.message(), HasSubstr(dir + "/empty.yaml is empty"));
  }
}

TEST(CalibrationChecks, AFileOfOnlyCommentsIsEmpty) {
  const std::string path = TempDir("calibration_comments") + "/camera.yaml";
  WriteText(path, "# nothing here\n\n");
  EXPECT_THAT(ReadCameraYaml(path).status().message(), HasSubstr(path + " is empty"));
}

TEST(CalibrationChecks, AnUnreadableFileSaysPermissionDenied) {
  const std::string path = TempDir("calibration_unreadable") + "/locked.yaml";
  WriteText(path, "a: 0\nb: -1\nc: 0\nd: 1\n");
  ASSERT_EQ(chmod(path.c_str(), 0), 0);
  for (const Reader& reader : Readers()) {
    SCOPED_TRACE(reader.kind);
    const std::string message = MessageWithoutRoot(reader, path);
    if (message.empty()) GTEST_SKIP() << "running as root and cannot switch to user 65534";
    EXPECT_THAT(message, HasSubstr(path + " cannot be read: permission denied"));
  }
}

TEST(CalibrationChecks, AKeyGivenTwiceIsRejectedWithBothLines) {
  const std::string dir = TempDir("calibration_duplicates");
  WriteText(dir + "/camera.yaml",
            "width: 64\nheight: 48\nfx: 50\nfy: 50\ncx: 32\ncy: 24\nfx: 60\n");
  EXPECT_THAT(ReadCameraYaml(dir + "/camera.yaml").status().message(),
              HasSubstr(dir + "/camera.yaml line 7: key 'fx': given twice (first on line 3)"));
  WriteText(dir + "/hand_eye.yaml",
            "end_effector_from_camera:\n  translation: [0, 0, 0]\n  translation: [1, 0, 0]\n"
            "  quaternion_xyzw: [0, 0, 0, 1]\n");
  EXPECT_THAT(ReadHandEyeFile(dir + "/hand_eye.yaml").status().message(),
              HasSubstr("line 3: key 'end_effector_from_camera.translation': given twice"));
  WriteText(dir + "/floor.yaml", "a: 0\nb: -1\nc: 0\nd: 1\nd: 2\n");
  EXPECT_THAT(ReadFloorCalibration(dir + "/floor.yaml").status().message(),
              HasSubstr("floor.yaml line 5: key 'd': given twice (first on line 4)"));
}

PinholeCamera GoodCamera() {
  PinholeCamera c;
  c.width = 640;
  c.height = 480;
  c.fx = c.fy = 500;
  c.cx = 320;
  c.cy = 240;
  return c;
}

TEST(CalibrationChecks, CameraValuesNameTheField) {
  EXPECT_FALSE(CheckCameraValues(GoodCamera(), CameraKeys{}).has_value());
  struct Case {
    std::function<void(PinholeCamera*)> change;
    const char* key;
    const char* text;
  };
  const std::vector<Case> cases = {
      {[](PinholeCamera* c) { c->width = 0; }, "width", "must be positive"},
      {[](PinholeCamera* c) { c->height = -2; }, "height", "must be positive"},
      {[](PinholeCamera* c) { c->fx = 0; }, "fx", "fx = 0 must be positive and finite"},
      {[](PinholeCamera* c) { c->fy = NAN; }, "fy", "must be positive and finite"},
      {[](PinholeCamera* c) { c->cx = 700; }, "cx", "inside the image [0, 640]"},
      {[](PinholeCamera* c) { c->cy = -1; }, "cy", "inside the image [0, 480]"},
      {[](PinholeCamera* c) { c->distortion[4] = 1500; }, "distortion",
       "k3 = 1500 must be finite with magnitude below 1000"},
      {[](PinholeCamera* c) { c->distortion[2] = INFINITY; }, "distortion", "p1 = inf"},
  };
  for (const Case& test : cases) {
    PinholeCamera camera = GoodCamera();
    test.change(&camera);
    const auto problem = CheckCameraValues(camera, CameraKeys{});
    ASSERT_TRUE(problem.has_value()) << test.key;
    EXPECT_EQ(problem->key, test.key);
    EXPECT_THAT(problem->what, HasSubstr(test.text));
  }
}

TEST(CalibrationChecks, ARotationMustBeOrthonormalWithDeterminantOne) {
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  EXPECT_FALSE(CheckRotation(r).has_value());
  EXPECT_FALSE(CheckRotation(r + Eigen::Matrix3d::Constant(1e-8)).has_value());
  const auto scaled = CheckRotation(r * 1.001);
  ASSERT_TRUE(scaled.has_value());
  EXPECT_THAT(*scaled, HasSubstr("R^T R differs from the identity"));
  Eigen::Matrix3d mirror = r;
  mirror.col(2) *= -1;
  const auto reflection = CheckRotation(mirror);
  ASSERT_TRUE(reflection.has_value());
  EXPECT_THAT(*reflection, HasSubstr("determinant is -1, not +1 (a reflection)"));
  EXPECT_TRUE(CheckRotation(r + Eigen::Matrix3d::Constant(1e-4)).has_value());
}

}  // namespace
}  // namespace sightline
