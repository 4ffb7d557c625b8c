#include "core/mapping/person_boxes.h"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/test_data.h"

namespace sightline {
namespace {

TEST(PersonBoxTable, ReadsTheSimulatorsPeopleCsv) {
  const std::string path = testing::TempDir("people") + "/people.csv";
  {
    std::ofstream out(path);
    out << "# frame,person,u0,v0,u1,v1,pixels  (inclusive pixel box in the annotated camera; "
           "pixels = 0 and an empty box when the person is not visible)\n"
        << "0,0,10,20,29,99,1200\n0,1,0,0,-1,-1,0\n2,1,100,50,119,200,900\n";
  }
  StatusOr<PersonBoxTable> table = PersonBoxTable::Read(path);
  ASSERT_TRUE(table.ok()) << table.status().ToString();
  table->SetImageSize(cv::Size(320, 240));
  ASSERT_EQ(table->ForFrame(0).size(), 1u);  // Person 1 is out of view in frame 0.
  const PersonBox& box = table->ForFrame(0)[0];
  EXPECT_EQ(box.id, 0);
  EXPECT_DOUBLE_EQ(box.box.x, 10);
  EXPECT_DOUBLE_EQ(box.box.width, 20);  // Inclusive corners 10 .. 29.
  EXPECT_DOUBLE_EQ(box.box.height, 80);
  EXPECT_EQ(box.image_size, cv::Size(320, 240));
  EXPECT_TRUE(table->ForFrame(1).empty());
  EXPECT_EQ(table->ForFrame(2).size(), 1u);
}

TEST(PersonBoxTable, ErrorsNameFileAndLine) {
  const std::string dir = testing::TempDir("people_bad");
  {
    std::ofstream out(dir + "/people.csv");
    out << "# frame,person,u0,v0,u1,v1,pixels\n0,0,10,20,29,x,5\n";
  }
  StatusOr<PersonBoxTable> bad = PersonBoxTable::Read(dir + "/people.csv");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("line 2"), std::string::npos) << bad.status().message();
  {
    std::ofstream out(dir + "/people.csv");
    out << "# a,b,c\n1,2,3\n";
  }
  EXPECT_EQ(PersonBoxTable::Read(dir + "/people.csv").status().code(), StatusCode::kParseError);
  EXPECT_EQ(PersonBoxTable::Read(dir + "/absent.csv").status().code(), StatusCode::kNotFound);
}

TEST(HogPersonDetector, NoPeopleInAPlainImage) {
  HogPersonDetector detector;
  const cv::Mat plain(240, 320, CV_8UC3, cv::Scalar(120, 130, 140));
  StatusOr<std::vector<PersonBox>> people = detector.Detect(plain);
  ASSERT_TRUE(people.ok()) << people.status().ToString();
  EXPECT_TRUE(people->empty());
  StatusOr<std::vector<PersonBox>> none = detector.Detect(cv::Mat());
  ASSERT_TRUE(none.ok());
  EXPECT_TRUE(none->empty());
  EXPECT_EQ(detector.Detect(cv::Mat(10, 10, CV_32FC1)).status().code(),
            StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace sightline
