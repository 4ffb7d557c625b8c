#include "core/io/file_listing.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "tests/core/io/io_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

TEST(FileListingTest, NaturalOrderComparesDigitRunsAsNumbers) {
  std::vector<std::string> names = {"img10.png", "img2.png",   "img1.png",  "a.png",
                                    "img02.png", "000050.png", "000001.png"};
  std::sort(names.begin(), names.end(), NaturalLess);
  EXPECT_EQ(names, (std::vector<std::string>{"000001.png", "000050.png", "a.png", "img1.png",
                                             "img2.png", "img02.png", "img10.png"}));
  EXPECT_FALSE(NaturalLess("x", "x"));
}

TEST(FileListingTest, ListsFilesByExtensionCaseInsensitively) {
  const std::string dir = testing::TempDir("listing");
  for (const char* name : {"b.PNG", "a.jpg", "c.txt", ".hidden.png"}) {
    testing::WriteText(dir + "/" + name, "x");
  }
  testing::WriteText(dir + "/sub/d.png", "x");
  auto names = ListFiles(dir, ImageExtensions());
  ASSERT_TRUE(names.ok());
  EXPECT_EQ(*names, (std::vector<std::string>{"a.jpg", "b.PNG"}));
  EXPECT_EQ(ListSubfolders(dir), std::vector<std::string>{"sub"});
  EXPECT_EQ(ListFiles(dir + "/nope", {".png"}).status().code(), StatusCode::kNotFound);
  EXPECT_EQ(BaseName("/a/b/c/"), "c");
  EXPECT_EQ(BaseName("rec/rgbd"), "rgbd");
}

}  // namespace
}  // namespace sightline
