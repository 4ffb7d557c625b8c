#include "core/button/region_classifier.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <opencv2/objdetect.hpp>

namespace sightline {

namespace {

#include "core/button/region_classifier_weights.inc"

constexpr int kPatch = 32;

// The square around `box`, 1.5 times its longer side, at kPatch x kPatch; the image's border
// is replicated where the square leaves it.
cv::Mat SquarePatch(const cv::Mat& grey, const cv::Rect& box) {
  const double side = std::max(8.0, 1.5 * std::max(box.width, box.height));
  const double cx = box.x + 0.5 * box.width, cy = box.y + 0.5 * box.height;
  const cv::Rect square(int(std::lround(cx - 0.5 * side)), int(std::lround(cy - 0.5 * side)),
                        int(std::lround(side)), int(std::lround(side)));
  const cv::Rect inside = square & cv::Rect(0, 0, grey.cols, grey.rows);
  if (inside.empty()) return cv::Mat(kPatch, kPatch, CV_8UC1, cv::Scalar(0));
  cv::Mat crop, patch;
  cv::copyMakeBorder(grey(inside), crop, inside.y - square.y, square.br().y - inside.br().y,
                     inside.x - square.x, square.br().x - inside.br().x, cv::BORDER_REPLICATE);
  cv::resize(crop, patch, cv::Size(kPatch, kPatch), 0, 0, cv::INTER_AREA);
  return patch;
}

}  // namespace

Eigen::VectorXd RegionFeatures(const cv::Mat& grey, const cv::Rect& box) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(kRegionFeatureSize);
  if (grey.empty() || grey.type() != CV_8UC1 || box.width <= 0 || box.height <= 0) return f;
  const cv::Mat patch = SquarePatch(grey, box);
  static const cv::HOGDescriptor hog(cv::Size(kPatch, kPatch), cv::Size(16, 16), cv::Size(8, 8),
                                     cv::Size(8, 8), 9);
  std::vector<float> d;
  hog.compute(patch, d);
  const int n = std::min<int>(int(d.size()), kRegionFeatureSize - 3);
  for (int i = 0; i < n; ++i) f[i] = d[i];
  f[kRegionFeatureSize - 3] = std::log(double(box.width) / box.height);
  // The region (the middle two thirds of the square) against its surroundings.
  cv::Mat inner_mask = cv::Mat::zeros(patch.size(), CV_8UC1);
  const int m = kPatch / 6;
  inner_mask(cv::Rect(m, m, kPatch - 2 * m, kPatch - 2 * m)).setTo(255);
  cv::Mat outer_mask;
  cv::bitwise_not(inner_mask, outer_mask);
  cv::Scalar mean, sd;
  cv::meanStdDev(patch, mean, sd);
  const double inner = cv::mean(patch, inner_mask)[0], outer = cv::mean(patch, outer_mask)[0];
  f[kRegionFeatureSize - 2] = (inner - outer) / (sd[0] + 1);
  f[kRegionFeatureSize - 1] = sd[0] / (mean[0] + 1);
  return f;
}

const RegionClassifier& RegionClassifier::BuiltIn() {
  static const RegionClassifier model = [] {
    RegionClassifier c;
    if (!kRegionModelTrained) return c;
    constexpr int d = kRegionFeatureSize;
    static_assert(sizeof(kRegionWeights) / sizeof(double) == d || !kRegionModelTrained);
    c.mean_ = Eigen::Map<const Eigen::VectorXd>(kRegionMean, d);
    c.inv_scale_ = Eigen::Map<const Eigen::VectorXd>(kRegionInvScale, d);
    c.weights_ = Eigen::Map<const Eigen::VectorXd>(kRegionWeights, d);
    c.bias_ = kRegionBias;
    return c;
  }();
  return model;
}

StatusOr<RegionClassifier> RegionClassifier::Train(const std::vector<Eigen::VectorXd>& features,
                                                   const std::vector<int>& is_button,
                                                   const RegionTrainOptions& options) {
  const int n = int(features.size());
  if (n == 0 || int(is_button.size()) != n) {
    return InvalidArgument("region classifier: no samples, or labels and features differ");
  }
  const int positives = int(std::count(is_button.begin(), is_button.end(), 1));
  if (positives == 0 || positives == n) {
    return InvalidArgument("region classifier: samples of both classes are needed (" +
                           std::to_string(positives) + " buttons of " + std::to_string(n) + ")");
  }
  if (!(options.l2 > 0) || options.iterations < 1) {
    return InvalidArgument("region classifier: l2 must be > 0 and iterations >= 1");
  }
  const int d = kRegionFeatureSize;
  Eigen::MatrixXd x(n, d + 1);
  for (int i = 0; i < n; ++i) {
    if (features[i].size() != d) return InvalidArgument("region classifier: wrong feature size");
    x.row(i).head(d) = features[i].transpose();
  }
  RegionClassifier c;
  c.mean_ = x.leftCols(d).colwise().mean().transpose();
  c.inv_scale_.resize(d);
  for (int j = 0; j < d; ++j) {
    const double sd =
        std::sqrt((x.col(j).array() - c.mean_[j]).square().sum() / std::max(1, n - 1));
    c.inv_scale_[j] = sd > 1e-9 ? 1.0 / sd : 0.0;
    x.col(j) = (x.col(j).array() - c.mean_[j]) * c.inv_scale_[j];
  }
  x.col(d).setOnes();
  Eigen::VectorXd y(n), weight(n);
  for (int i = 0; i < n; ++i) {
    y[i] = is_button[i] ? 1.0 : 0.0;
    weight[i] = 0.5 * n / (is_button[i] ? positives : n - positives);
  }
  Eigen::VectorXd w = Eigen::VectorXd::Zero(d + 1);
  Eigen::VectorXd penalty = Eigen::VectorXd::Constant(d + 1, options.l2);
  penalty[d] = 0;  // The bias is not penalised.
  for (int it = 0; it < options.iterations; ++it) {
    const Eigen::VectorXd z = x * w;
    const Eigen::VectorXd p = (1.0 / (1.0 + (-z.array()).exp())).matrix();
    const Eigen::VectorXd r = weight.cwiseProduct(p - y);
    const Eigen::VectorXd grad = x.transpose() * r + penalty.cwiseProduct(w);
    const Eigen::VectorXd curvature = weight.array() * p.array() * (1 - p.array()) + 1e-12;
    Eigen::MatrixXd h = x.transpose() * curvature.asDiagonal() * x;
    h.diagonal() += penalty;
    const Eigen::VectorXd step = h.ldlt().solve(grad);
    w -= step;
    if (step.norm() < 1e-8 * (1 + w.norm())) break;
  }
  c.weights_ = w.head(d);
  c.bias_ = w[d];
  return c;
}

double RegionClassifier::ButtonProbability(const Eigen::VectorXd& features) const {
  if (empty() || features.size() != weights_.size()) return 1.0;
  const double z = weights_.dot((features - mean_).cwiseProduct(inv_scale_)) + bias_;
  return 1.0 / (1.0 + std::exp(-z));
}

std::string RegionClassifier::ToSource() const {
  std::string out;
  auto array = [&out](const char* name, const Eigen::VectorXd& v) {
    out += std::string("constexpr double ") + name + "[] = {";
    char text[40];
    for (int i = 0; i < v.size(); ++i) {
      const char* separator = i == 0 ? "\n    " : i % 4 ? ", " : ",\n    ";
      std::snprintf(text, sizeof(text), "%s%.17g", separator, v[i]);
      out += text;
    }
    out += "};\n";
  };
  out += "constexpr bool kRegionModelTrained = " + std::string(empty() ? "false" : "true") + ";\n";
  array("kRegionMean", mean_);
  array("kRegionInvScale", inv_scale_);
  array("kRegionWeights", weights_);
  char text[64];
  std::snprintf(text, sizeof(text), "constexpr double kRegionBias = %.17g;\n", bias_);
  out += text;
  return out;
}

}  // namespace sightline
