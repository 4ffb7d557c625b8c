// sightline-cli record as a user runs it, with real faults: the process killed (SIGKILL) half
// way through 300 frames, stopped with SIGTERM, and a disk that fills up (a small tmpfs in a
// private mount namespace). Every frame the recorder acknowledged must read back exactly.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "core/common/text_file.h"
#include "tests/app/process.h"
#include "tests/core/record/record_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

const std::string kCli = std::string(SIGHTLINE_BIN_DIR) + "/sightline-cli";

// A simulated 300-frame RGB-D corridor (320x240), made once.
const std::string& Corridor() {
  static const std::string dir = [] {
    const std::string path = testing::TempDir("record_cli") + "/corridor";
    const auto r = testing::RunProcess(kCli + " simulate corridor --out " + path +
                                       " --frames 300 --sensors rgbd --quiet"
                                       " --set sim.rgbd.resolution=320x240");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    return path + "/rgbd";
  }();
  return dir;
}

// sightline-cli run with its stdout on a pipe that the test reads line by line.
class CliChild {
 public:
  explicit CliChild(const std::vector<std::string>& args) {
    int fds[2];
    if (pipe(fds) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      dup2(fds[1], STDOUT_FILENO);
      close(fds[0]);
      close(fds[1]);
      std::vector<char*> argv;
      argv.push_back(const_cast<char*>(kCli.c_str()));
      for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
      argv.push_back(nullptr);
      execv(kCli.c_str(), argv.data());
      _exit(127);
    }
    close(fds[1]);
    out_ = fdopen(fds[0], "r");
  }
  ~CliChild() {
    if (pid_ > 0 && !reaped_) {
      kill(pid_, SIGKILL);
      Wait();
    }
    if (out_) fclose(out_);
  }
  bool started() const { return pid_ > 0 && out_ != nullptr; }
  // The next line of stdout without its newline; false at the end.
  bool ReadLine(std::string* line) {
    char buffer[4096];
    if (!fgets(buffer, sizeof(buffer), out_)) return false;
    *line = buffer;
    if (!line->empty() && line->back() == '\n') line->pop_back();
    return true;
  }
  void Signal(int sig) { kill(pid_, sig); }
  // The wait status.
  int Wait() {
    int status = 0;
    waitpid(pid_, &status, 0);
    reaped_ = true;
    return status;
  }

 private:
  pid_t pid_ = -1;
  FILE* out_ = nullptr;
  bool reaped_ = false;
};

bool IsAck(const std::string& line) { return line.rfind("written ", 0) == 0; }

TEST(RecordCli, KilledHalfWayKeepsEveryAcknowledgedFrameReadable) {
  const std::string out = testing::TempDir("record_cli_kill") + "/rec";
  CliChild child({"record", "replay://" + Corridor() + "?fps=100", "--out", out, "--ack", "--set",
                  "record.queue_capacity=512"});
  ASSERT_TRUE(child.started());
  int acknowledged = 0;
  std::string line;
  while (acknowledged < 150 && child.ReadLine(&line)) acknowledged += IsAck(line);
  ASSERT_EQ(acknowledged, 150) << "the recorder acknowledged fewer frames than expected";
  child.Signal(SIGKILL);
  while (child.ReadLine(&line)) acknowledged += IsAck(line);  // Lines already in the pipe.
  const int status = child.Wait();
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "it did not get to finish";
  ASSERT_LT(acknowledged, 300);

  // Readable with the normal reader; every listed frame is complete and exact. The frame being
  // written at the kill may be listed without its acknowledgement having been printed.
  const std::vector<Frame> recorded = testing::ReadAllFrames(out);
  EXPECT_GE(static_cast<int>(recorded.size()), acknowledged);
  EXPECT_LE(static_cast<int>(recorded.size()), acknowledged + 1);
  const std::vector<Frame> original = testing::ReadAllFrames(Corridor());
  EXPECT_EQ(testing::ExpectRecordedFramesMatch(original, recorded),
            static_cast<int>(recorded.size()));
}

TEST(RecordCli, SigtermFinishesQueuedFramesAndReportsTheCounts) {
  const std::string out = testing::TempDir("record_cli_term") + "/rec";
  // Looping: the source never ends by itself, so only the signal can end this recording.
  CliChild child({"record", "replay://" + Corridor() + "?fps=100&loop=1", "--out", out, "--ack"});
  ASSERT_TRUE(child.started());
  int acknowledged = 0;
  std::string line, summary;
  while (acknowledged < 40 && child.ReadLine(&line)) acknowledged += IsAck(line);
  child.Signal(SIGTERM);
  while (child.ReadLine(&line)) {
    acknowledged += IsAck(line);
    if (line.rfind("recorded ", 0) == 0) summary = line;
  }
  const int status = child.Wait();
  ASSERT_TRUE(WIFEXITED(status)) << "SIGTERM must end the recording cleanly";
  EXPECT_TRUE(WEXITSTATUS(status) == 0 || WEXITSTATUS(status) == 3) << WEXITSTATUS(status);
  EXPECT_NE(summary.find(std::to_string(acknowledged) + " frames written"), std::string::npos)
      << summary << " / acknowledged " << acknowledged;
  EXPECT_NE(summary.find("(stopped)"), std::string::npos) << summary;
  EXPECT_EQ(static_cast<int>(testing::ReadAllFrames(out).size()), acknowledged);
}

// A 3 MB tmpfs mounted in a private mount namespace (unshare -m as root, -rm otherwise) fills
// up during the recording; the partial recording is copied out before the namespace ends.
TEST(RecordCli, FullDiskGivesAClearErrorAndAReadablePartialRecording) {
  if (testing::RunProcess("unshare -rm true").exit_code != 0 &&
      testing::RunProcess("unshare -m true").exit_code != 0) {
    GTEST_SKIP() << "needs a private mount namespace for a small tmpfs (unshare -m / -rm "
                    "failed); the file-size-limit test in record/Recorder covers EFBIG";
  }
  const std::string base = testing::TempDir("record_cli_full");
  const std::string mount = base + "/disk", copy = base + "/copy";
  const std::string flag = getuid() == 0 ? "-m" : "-rm";
  const std::string script = "mkdir -p " + mount + " && mount -t tmpfs -o size=3m tmpfs " + mount +
                             " && " + kCli + " record 'replay://" + Corridor() +
                             "?fps=1000' --out " + mount +
                             "/rec --set record.queue_capacity=512; rc=\\$?; cp -a " + mount +
                             "/rec " + copy + "; exit \\$rc";
  const auto r = testing::RunProcess("unshare " + flag + " sh -c \"" + script + "\"");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("No space left on device"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("the disk is full"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(mount + "/rec/rgbd/"), std::string::npos) << "names the file: " << r.out;
  // The counts line says how many frames made it; exactly those read back.
  const size_t at = r.out.find(" frames written");
  ASSERT_NE(at, std::string::npos) << r.out;
  const size_t begin = r.out.rfind(' ', at - 1) + 1;
  const int written = std::stoi(r.out.substr(begin, at - begin));
  EXPECT_GT(written, 3);
  EXPECT_LT(written, 300);
  const std::vector<Frame> recorded = testing::ReadAllFrames(copy);
  EXPECT_EQ(static_cast<int>(recorded.size()), written);
  EXPECT_EQ(testing::ExpectRecordedFramesMatch(testing::ReadAllFrames(Corridor()), recorded),
            written);
}

TEST(RecordCli, RecordingIntoAFolderThatHoldsFilesIsRefusedUnlessOverwriting) {
  const std::string source = testing::TempDir("record_cli_source");
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(cv::imwrite(source + "/00000" + std::to_string(i) + ".png",
                            cv::Mat(24, 32, CV_8UC1, cv::Scalar(40 * i))));
  }
  const std::string out = testing::TempDir("record_cli_again") + "/rec";
  auto r = testing::RunProcess(kCli + " record " + source + " --out " + out + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string times = testing::ReadAll(out + "/mono/times.txt");
  ASSERT_EQ(testing::ReadAllFrames(out).size(), 4u);

  r = testing::RunProcess(kCli + " record " + source + " --out " + out + " --frames 2 --quiet");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("cannot record into " + out), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--overwrite"), std::string::npos) << r.out;
  EXPECT_EQ(testing::ReadAll(out + "/mono/times.txt"), times);  // Not truncated.
  EXPECT_EQ(testing::ReadAllFrames(out).size(), 4u);

  r = testing::RunProcess(kCli + " record " + source + " --out " + out +
                          " --frames 2 --overwrite --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(testing::ReadAllFrames(out).size(), 2u);
  EXPECT_FALSE(std::filesystem::exists(out + "/mono/000003.png"));  // No orphan image.
}

TEST(RecordCli, HelpAndBadArgumentsFailWithOneLine) {
  auto r = testing::RunProcess(kCli + " record --help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("usage: sightline-cli record"), std::string::npos);
  r = testing::RunProcess(kCli + " record /nonexistent/folder --out /tmp/x");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("/nonexistent/folder"), std::string::npos) << r.out;
  r = testing::RunProcess(kCli + " record 'replay:///any/recording?speed=2' --out /tmp/x");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("unknown key 'speed'"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace sightline
