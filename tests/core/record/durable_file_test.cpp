// Crash-safe files: atomic whole files and index files that only ever hold complete lines,
// also when the kernel refuses a write (file size limit, as on a full disk).
#include "core/record/durable_file.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>
#include <fstream>
#include <sstream>

#include "core/common/text_file.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

std::string ReadAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Lowers RLIMIT_FSIZE for this process (SIGXFSZ ignored, so writes fail with EFBIG) and
// restores it on destruction.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &saved_);
    previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit = saved_;
    limit.rlim_cur = bytes;
    ok_ = setrlimit(RLIMIT_FSIZE, &limit) == 0;
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previous_handler_);
  }
  bool ok() const { return ok_; }

 private:
  rlimit saved_{};
  void (*previous_handler_)(int) = nullptr;
  bool ok_ = false;
};

TEST(DurableFile, WritesWholeFilesAndLeavesNoPartFile) {
  const std::string dir = testing::TempDir("durable");
  const std::string path = JoinPath(dir, "a.bin");
  ASSERT_TRUE(WriteFileAtomically(path, {1, 2, 3}).ok());
  EXPECT_EQ(ReadAll(path), std::string("\x01\x02\x03"));
  EXPECT_FALSE(FileExists(path + ".part"));
  const Status missing = WriteFileAtomically(JoinPath(dir, "no/such/folder/b.bin"), {1});
  EXPECT_EQ(missing.code(), StatusCode::kUnavailable);
  EXPECT_NE(missing.message().find("no/such/folder/b.bin"), std::string::npos) << missing.message();
}

TEST(DurableFile, AppendsCompleteLines) {
  const std::string path = JoinPath(testing::TempDir("durable"), "times.txt");
  AppendOnlyFile index;
  ASSERT_TRUE(index.Open(path, "# header\n").ok());
  ASSERT_TRUE(index.AppendLine("1.0 a.png").ok());
  ASSERT_TRUE(index.AppendLine("2.0 b.png").ok());
  EXPECT_EQ(ReadAll(path), "# header\n1.0 a.png\n2.0 b.png\n");
  EXPECT_EQ(index.size(), 29);
}

TEST(DurableFile, FileSizeLimitCutsBackToTheLastCompleteLineAndSaysSo) {
  const std::string path = JoinPath(testing::TempDir("durable"), "index.txt");
  AppendOnlyFile index;
  ASSERT_TRUE(index.Open(path, "").ok());
  const std::string line(30, 'x');  // 31 bytes with the newline.
  Status failed;
  int appended = 0;
  {
    FileSizeLimit limit(100);
    ASSERT_TRUE(limit.ok());
    for (int i = 0; i < 10 && failed.ok(); ++i) {
      failed = index.AppendLine(line);
      if (failed.ok()) ++appended;
    }
  }
  EXPECT_EQ(appended, 3);  // 93 bytes fit, the fourth line would end at 124.
  ASSERT_FALSE(failed.ok());
  EXPECT_EQ(failed.code(), StatusCode::kUnavailable);
  EXPECT_NE(failed.message().find(path), std::string::npos) << failed.message();
  EXPECT_NE(failed.message().find("file size limit"), std::string::npos) << failed.message();
  const std::string content = ReadAll(path);
  EXPECT_EQ(content.size(), 93u) << "the partial fourth line was cut back";
  EXPECT_EQ(content.back(), '\n');
}

}  // namespace
}  // namespace sightline
