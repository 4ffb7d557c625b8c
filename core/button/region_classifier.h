// Button or printed label? The outline rules of the detector cannot tell a button from a label,
// a sign or a glyph printed beside it (they are compact outlines too). This is a logistic model
// on the appearance of the region a tap selects: the HOG of its square surroundings at 32x32
// (9 blocks of 2x2 cells, 9 orientations) and three shape and contrast figures, standardised.
// It is trained on the regions the detector selects from taps on labelled photos
// (`sightline-cli train-button-classifier`); the product's weights are built in.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline {

inline constexpr int kRegionFeatureSize = 9 * 36 + 3;

// The features of the region with bounding box `box` (image pixels) of `grey` (CV_8UC1).
Eigen::VectorXd RegionFeatures(const cv::Mat& grey, const cv::Rect& box);

struct RegionTrainOptions {
  double l2 = 15.0;     // Ridge penalty on the standardised weights.
  int iterations = 30;  // Newton steps (the loss is convex; fewer suffice).
};

class RegionClassifier {
 public:
  RegionClassifier() = default;

  // The product's model (trained on tests/data/button_panels/labels.csv's 38 photos).
  static const RegionClassifier& BuiltIn();

  // A model from samples' features and whether each is a button (1) or not (0); both classes
  // weigh alike whatever their counts. InvalidArgument without samples of both classes.
  static StatusOr<RegionClassifier> Train(const std::vector<Eigen::VectorXd>& features,
                                          const std::vector<int>& is_button,
                                          const RegionTrainOptions& options = {});

  bool empty() const { return weights_.size() == 0; }
  // Probability that the region is a button; 1 when the model is empty.
  double ButtonProbability(const Eigen::VectorXd& features) const;

  // The model as the C++ initialisers of region_classifier_weights.inc.
  std::string ToSource() const;

 private:
  Eigen::VectorXd mean_, inv_scale_, weights_;
  double bias_ = 0;
};

}  // namespace sightline
