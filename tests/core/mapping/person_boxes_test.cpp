#include "core/mapping/person_boxes.h"

#include <gtest/gtest.h>

#include <fstream>
#include <limits>

#include "core/sim/observations.h"
#include "core/sim/simulator.h"
#include "tests/core/mapping/corridor_run.h"
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

// The simulator's corridor (people made of legs, torso, arms and head, 320 x 240): every person
// seen whole, 1000+ pixels, is scored as a person, and the same box moved sideways onto the
// corridor is not.
TEST(HogPersonDetector, ScoresTheSimulatedPeopleAboveTheCorridorBesideThem) {
  sim::SimulationOptions options = testing::CorridorSimulation(40.0, 5.0, 1.0, 2.0, 1);
  StatusOr<sim::Simulator> simulator = sim::Simulator::Create(options);
  ASSERT_TRUE(simulator.ok()) << simulator.status().ToString();
  HogPersonDetector detector;
  PersonDetectorOptions defaults;
  sim::SimulatedRgbd frame;
  int people = 0, scored = 0, empty_scored = 0, empty = 0;
  for (int k = 0; k < simulator->frames(); ++k) {
    ASSERT_TRUE(simulator->RenderRgbd(k, &frame).ok());
    for (const sim::PersonObservation& p : sim::ObservePeople(simulator->scene(), frame.view, k)) {
      const cv::Rect2d box(p.u0, p.v0, p.u1 - p.u0 + 1, p.v1 - p.v0 + 1);
      if (p.pixels < 1000 || box.x < 4 || box.y < 4 || box.br().x > frame.color.cols - 4 ||
          box.br().y > frame.color.rows - 4) {
        continue;  // Small, or cut by the border.
      }
      ++people;
      const double score = detector.Score(frame.color, box);
      if (score >= defaults.depth_hog_min_score) ++scored;
      // Two box widths to the side, away from every person in view.
      for (double side : {-2.0, 2.0}) {
        const cv::Rect2d moved(box.x + side * box.width, box.y, box.width, box.height);
        if ((moved & cv::Rect2d(0, 0, frame.color.cols, frame.color.rows)) != moved) continue;
        bool clear = true;
        for (const sim::PersonObservation& q :
             sim::ObservePeople(simulator->scene(), frame.view, k)) {
          const cv::Rect2d other(q.u0, q.v0, q.u1 - q.u0 + 1, q.v1 - q.v0 + 1);
          clear &= q.pixels == 0 || (moved & other).area() == 0;
        }
        if (!clear) continue;
        ++empty;
        if (detector.Score(frame.color, moved) >= defaults.depth_hog_min_score) ++empty_scored;
      }
    }
  }
  std::printf("[ hog ] %d of %d whole people scored as people; %d of %d boxes beside them\n",
              scored, people, empty_scored, empty);
  ASSERT_GE(people, 5);
  ASSERT_GE(empty, 5);
  EXPECT_GE(scored, 0.8 * people);
  EXPECT_LE(empty_scored, 0.2 * empty);
  EXPECT_EQ(detector.Score(cv::Mat(), cv::Rect2d(0, 0, 10, 10)),
            -std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace sightline
