// Mobility scores from slope and roughness: the published Table I rule and a Gaussian process
// regression (squared-exponential kernel) trained on the table.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace sightline {

// Table I. Slope bands 0-10, 10-20, 20-30, 30-40, > 40 deg; roughness bands 1.0-1.2, 1.2-1.4,
// ..., 2.0-2.2, > 2.2; band edges belong to the upper band (lower bound inclusive). The table is
// max(0, 1 - 0.25 (slope band + roughness band)).
double RuleScore(double slope_deg, double roughness);

// The table's cell centres used for training: slopes 5, 15, 25, 35, 45 deg and roughness 1.1,
// 1.3, ..., 2.1, 2.3, with the rule's score.
void TableCellCentres(std::vector<Eigen::Vector2d>* inputs, std::vector<double>* scores);

// A Gaussian process on (slope_deg, roughness) with a squared-exponential kernel on
// standardised inputs, a constant mean (the training mean) and hyper-parameters (signal sigma,
// length scale, noise sigma) chosen by maximising the log marginal likelihood over a grid.
// Predictions are clamped to [0, 1]. Train once, predict often; immutable after Train.
//
//   GprScore gpr = GprScore::TrainOnTable();
//   double s = gpr.Predict(12.0, 1.05);
class GprScore {
 public:
  static GprScore TrainOnTable();
  static GprScore Train(const std::vector<Eigen::Vector2d>& inputs,
                        const std::vector<double>& scores);

  // The clamped posterior mean.
  double Predict(double slope_deg, double roughness) const;

  double signal_sigma() const { return signal_sigma_; }
  double length_scale() const { return length_scale_; }  // In standard deviations.
  double noise_sigma() const { return noise_sigma_; }
  double log_marginal_likelihood() const { return log_likelihood_; }

 private:
  double Kernel(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
  Eigen::Vector2d Standardise(double slope_deg, double roughness) const;

  std::vector<Eigen::Vector2d> inputs_;  // Standardised.
  Eigen::VectorXd alpha_;                // K^-1 (y - mean).
  Eigen::Vector2d input_mean_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d input_scale_ = Eigen::Vector2d::Ones();
  double mean_ = 0;
  double signal_sigma_ = 1, length_scale_ = 1, noise_sigma_ = 0.01, log_likelihood_ = 0;
};

}  // namespace sightline
