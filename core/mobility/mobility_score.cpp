#include "core/mobility/mobility_score.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>

namespace sightline {

double RuleScore(double slope_deg, double roughness) {
  if (!std::isfinite(slope_deg) || !std::isfinite(roughness)) return 0;
  const int slope_band = std::clamp(static_cast<int>(std::floor(slope_deg / 10.0)), 0, 4);
  const int rough_band =
      std::clamp(static_cast<int>(std::floor((roughness - 1.0) / 0.2 + 1e-9)), 0, 6);
  return std::max(0.0, 1.0 - 0.25 * (slope_band + rough_band));
}

void TableCellCentres(std::vector<Eigen::Vector2d>* inputs, std::vector<double>* scores) {
  inputs->clear();
  scores->clear();
  for (double slope : {5.0, 15.0, 25.0, 35.0, 45.0}) {
    for (double rough : {1.1, 1.3, 1.5, 1.7, 1.9, 2.1, 2.3}) {
      inputs->emplace_back(slope, rough);
      scores->push_back(RuleScore(slope, rough));
    }
  }
}

GprScore GprScore::TrainOnTable() {
  std::vector<Eigen::Vector2d> inputs;
  std::vector<double> scores;
  TableCellCentres(&inputs, &scores);
  return Train(inputs, scores);
}

GprScore GprScore::Train(const std::vector<Eigen::Vector2d>& inputs,
                         const std::vector<double>& scores) {
  GprScore gp;
  const int n = static_cast<int>(inputs.size());
  if (n == 0) return gp;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero(), mean2 = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& x : inputs) mean += x, mean2 += x.cwiseProduct(x);
  mean /= n;
  Eigen::Vector2d var = mean2 / n - mean.cwiseProduct(mean);
  gp.input_mean_ = mean;
  gp.input_scale_ = var.cwiseMax(1e-12).cwiseSqrt();
  gp.inputs_.clear();
  for (const Eigen::Vector2d& x : inputs) gp.inputs_.push_back(gp.Standardise(x.x(), x.y()));
  Eigen::VectorXd y(n);
  for (int i = 0; i < n; ++i) y(i) = scores[i];
  gp.mean_ = y.mean();
  const Eigen::VectorXd centred = y.array() - gp.mean_;

  // Hyper-parameters: the grid point of largest log marginal likelihood
  //   -1/2 y^T K^-1 y - 1/2 log |K| - n/2 log 2 pi.
  double best = -std::numeric_limits<double>::infinity();
  GprScore trial = gp;
  for (int il = 0; il <= 24; ++il) {
    const double length = 0.1 * std::pow(10.0, il / 12.0);  // 0.1 .. 10
    for (int is = 0; is <= 12; ++is) {
      const double signal = 0.05 * std::pow(10.0, is / 6.0);  // 0.05 .. 5
      for (int in = 0; in <= 6; ++in) {
        const double noise = 1e-3 * std::pow(10.0, in / 3.0);  // 0.001 .. 0.1
        trial.length_scale_ = length, trial.signal_sigma_ = signal, trial.noise_sigma_ = noise;
        Eigen::MatrixXd k(n, n);
        for (int i = 0; i < n; ++i) {
          for (int j = 0; j < n; ++j) k(i, j) = trial.Kernel(gp.inputs_[i], gp.inputs_[j]);
          k(i, i) += noise * noise;
        }
        Eigen::LLT<Eigen::MatrixXd> llt(k);
        if (llt.info() != Eigen::Success) continue;
        const Eigen::VectorXd alpha = llt.solve(centred);
        const double log_det = 2 * llt.matrixLLT().diagonal().array().log().sum();
        const double ll = -0.5 * centred.dot(alpha) - 0.5 * log_det - 0.5 * n * std::log(2 * M_PI);
        if (ll > best) {
          best = ll;
          gp.length_scale_ = length, gp.signal_sigma_ = signal, gp.noise_sigma_ = noise;
          gp.alpha_ = alpha;
          gp.log_likelihood_ = ll;
        }
      }
    }
  }
  return gp;
}

Eigen::Vector2d GprScore::Standardise(double slope_deg, double roughness) const {
  return (Eigen::Vector2d(slope_deg, roughness) - input_mean_).cwiseQuotient(input_scale_);
}

double GprScore::Kernel(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  return signal_sigma_ * signal_sigma_ *
         std::exp(-0.5 * (a - b).squaredNorm() / (length_scale_ * length_scale_));
}

double GprScore::Predict(double slope_deg, double roughness) const {
  if (alpha_.size() == 0 || !std::isfinite(slope_deg) || !std::isfinite(roughness)) return 0;
  const Eigen::Vector2d x = Standardise(slope_deg, roughness);
  double mean = mean_;
  for (size_t i = 0; i < inputs_.size(); ++i) mean += Kernel(x, inputs_[i]) * alpha_(i);
  return std::clamp(mean, 0.0, 1.0);
}

}  // namespace sightline
