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

}  // namespace
}  // namespace sightline
