#include "core/common/text_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/test_data.h"

namespace sightline {
namespace {

TEST(TextFile, SkipsCommentsBlankLinesAndBom) {
  const std::string path = testing::TempDir("text") + "/a.txt";
  std::ofstream(path) << "\xEF\xBB\xBF# comment\n\n  1 2 3\r\n#x\n4,5,6\n";
  auto lines = ReadDataLines(path);
  ASSERT_TRUE(lines.ok());
  ASSERT_EQ(lines->size(), 2u);
  EXPECT_EQ((*lines)[0].number, 3);
  EXPECT_EQ((*lines)[1].number, 5);
  auto numbers = ParseNumbers((*lines)[1], 3, path);
  ASSERT_TRUE(numbers.ok());
  EXPECT_EQ(*numbers, (std::vector<double>{4, 5, 6}));
}

TEST(TextFile, NonNumberNamesFieldAndLine) {
  auto r = ParseNumbers({7, "1 2 x3"}, 3, "f.txt");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().message(), "f.txt line 7: field 3 'x3' is not a number");
}

TEST(TextFile, InfinityIsRejected) { EXPECT_FALSE(ParseNumbers({1, "1 inf"}, 2, "f").ok()); }

TEST(TextFile, ADeviceOrFolderGivenAsAListSaysWhatItIs) {
  // /dev/zero was read line by line: one endless line, gigabytes, no answer.
  StatusOr<std::vector<DataLine>> device = ReadDataLines("/dev/zero");
  ASSERT_FALSE(device.ok());
  EXPECT_EQ(device.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(device.status().message().find("/dev/zero is not a regular file"), std::string::npos)
      << device.status().message();
  const std::string dir = testing::TempDir("text_file_folder");
  StatusOr<std::vector<DataLine>> folder = ReadDataLines(dir);
  ASSERT_FALSE(folder.ok());
  EXPECT_NE(folder.status().message().find(dir + " is a folder, not a file"), std::string::npos)
      << folder.status().message();
  StatusOr<std::vector<DataLine>> missing = ReadDataLines(dir + "/none.txt");
  EXPECT_EQ(missing.status().code(), StatusCode::kNotFound);
}

TEST(TextFile, TimesMustIncreaseStrictly) {
  EXPECT_TRUE(CheckTimeIncreases(1.0, 1.1, "t.txt", 3).ok());
  const Status equal = CheckTimeIncreases(1.5, 1.5, "t.txt", 3);
  EXPECT_EQ(equal.code(), StatusCode::kParseError);
  EXPECT_NE(equal.message().find("t.txt line 3: timestamp 1.5 is equal to the previous one"),
            std::string::npos)
      << equal.message();
  const Status back = CheckTimeIncreases(2, 1, "t.txt", 9);
  EXPECT_NE(back.message().find("t.txt line 9: timestamp 1 is before the previous one (2)"),
            std::string::npos)
      << back.message();
}

}  // namespace
}  // namespace sightline
