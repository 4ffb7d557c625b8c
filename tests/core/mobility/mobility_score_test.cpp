#include "core/mobility/mobility_score.h"

#include <gtest/gtest.h>

namespace sightline {
namespace {

TEST(RuleScore, ReproducesTableOne) {
  // Rows of Table I (roughness bands), columns slope 0-10 ... > 40.
  const double table[7][5] = {
      {1, 0.75, 0.5, 0.25, 0}, {0.75, 0.5, 0.25, 0, 0}, {0.5, 0.25, 0, 0, 0}, {0.25, 0, 0, 0, 0},
      {0, 0, 0, 0, 0},         {0, 0, 0, 0, 0},         {0, 0, 0, 0, 0}};
  for (int r = 0; r < 7; ++r) {
    for (int s = 0; s < 5; ++s) {
      EXPECT_DOUBLE_EQ(RuleScore(5 + 10 * s, 1.1 + 0.2 * r), table[r][s]) << r << " " << s;
    }
  }
}

TEST(RuleScore, LowerBandEdgeIsInclusive) {
  EXPECT_DOUBLE_EQ(RuleScore(0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(RuleScore(10, 1.0), 0.75);    // 10 deg belongs to 10-20.
  EXPECT_DOUBLE_EQ(RuleScore(9.99, 1.2), 0.75);  // 1.2 belongs to 1.2-1.4.
  EXPECT_DOUBLE_EQ(RuleScore(90, 1.0), 0.0);
}

TEST(GprScore, AgreesWithRuleOnCellCentres) {
  const GprScore gpr = GprScore::TrainOnTable();
  std::vector<Eigen::Vector2d> inputs;
  std::vector<double> scores;
  TableCellCentres(&inputs, &scores);
  ASSERT_EQ(inputs.size(), 35u);
  for (size_t i = 0; i < inputs.size(); ++i) {
    EXPECT_NEAR(gpr.Predict(inputs[i].x(), inputs[i].y()), scores[i], 0.15)
        << "slope " << inputs[i].x() << " roughness " << inputs[i].y();
  }
  EXPECT_GT(gpr.length_scale(), 0.1);  // Hyper-parameters moved from the grid's edge.
  EXPECT_LT(gpr.length_scale(), 10.0);
}

TEST(GprScore, IsSmoothAndClamped) {
  const GprScore gpr = GprScore::TrainOnTable();
  EXPECT_GE(gpr.Predict(0, 1.0), 0.9);
  for (double slope = 0; slope <= 90; slope += 3) {
    for (double rough = 1.0; rough <= 3.0; rough += 0.05) {
      const double s = gpr.Predict(slope, rough);
      EXPECT_GE(s, 0.0);
      EXPECT_LE(s, 1.0);
    }
  }
  // Between cells the GPR interpolates where the rule jumps.
  const double mid = gpr.Predict(10, 1.1);
  EXPECT_GT(mid, 0.75);
  EXPECT_LT(mid, 1.0);
}

}  // namespace
}  // namespace sightline
