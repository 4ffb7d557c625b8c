#include "core/sim/texture_images.h"

#include <opencv2/imgproc.hpp>

#include "core/sim/random.h"

namespace sightline::sim {
namespace {

cv::Scalar RandomColor(std::mt19937& engine, double lo, double hi) {
  return cv::Scalar(Uniform(engine, lo, hi), Uniform(engine, lo, hi), Uniform(engine, lo, hi));
}

std::string RandomWord(std::mt19937& engine, int min_length, int max_length) {
  static const char kLetters[] = "ABCDEFGHIJKLMNOPRSTUVWZ0123456789";
  const int length = static_cast<int>(Uniform(engine, min_length, max_length + 1));
  std::string word;
  for (int i = 0; i < length; ++i) {
    word += kLetters[static_cast<int>(Uniform(engine, 0, sizeof(kLetters) - 1))];
  }
  return word;
}

}  // namespace

TextureImage MakePosterImage(uint64_t seed, int width_px, int height_px) {
  std::mt19937 engine = MakeEngine(seed);
  cv::Mat img(height_px, width_px, CV_8UC3, RandomColor(engine, 200, 250));
  const double unit = width_px / 40.0;
  // Title band.
  const int band = static_cast<int>(height_px * Uniform(engine, 0.14, 0.2));
  cv::rectangle(img, cv::Rect(0, 0, width_px, band), RandomColor(engine, 20, 160), cv::FILLED);
  cv::putText(img, RandomWord(engine, 4, 7), cv::Point(static_cast<int>(unit), band * 3 / 4),
              cv::FONT_HERSHEY_DUPLEX, width_px / 220.0, cv::Scalar(245, 245, 245),
              std::max(1, static_cast<int>(unit / 2)), cv::LINE_AA);
  // Pictures: overlapping blocks and discs.
  const int blocks = static_cast<int>(Uniform(engine, 3, 7));
  for (int i = 0; i < blocks; ++i) {
    const int w = static_cast<int>(Uniform(engine, 0.15, 0.5) * width_px);
    const int h = static_cast<int>(Uniform(engine, 0.08, 0.25) * height_px);
    const int x = static_cast<int>(Uniform(engine, 0, width_px - w));
    const int y = static_cast<int>(Uniform(engine, band + unit, height_px * 0.6));
    cv::rectangle(img, cv::Rect(x, y, w, h), RandomColor(engine, 10, 230), cv::FILLED);
    if (Uniform(engine, 0, 1) < 0.5) {
      cv::circle(img, cv::Point(x + w / 2, y + h / 2), std::min(w, h) / 3,
                 RandomColor(engine, 10, 230), cv::FILLED, cv::LINE_AA);
    }
  }
  // Lines of small text.
  const cv::Scalar ink = RandomColor(engine, 0, 80);
  for (double y = height_px * 0.68; y < height_px - unit; y += 2.2 * unit) {
    int x = static_cast<int>(unit);
    while (x < width_px - 4 * unit) {
      const std::string word = RandomWord(engine, 2, 8);
      cv::putText(img, word, cv::Point(x, static_cast<int>(y)), cv::FONT_HERSHEY_SIMPLEX,
                  unit / 22.0, ink, std::max(1, static_cast<int>(unit / 6)), cv::LINE_AA);
      int baseline = 0;
      x += cv::getTextSize(word, cv::FONT_HERSHEY_SIMPLEX, unit / 22.0, 1, &baseline).width +
           static_cast<int>(unit);
    }
  }
  return {img};
}

TextureImage MakeButtonLabelImage(const std::string& label, bool round, int size_px) {
  cv::Mat img(size_px, size_px, CV_8UC3, cv::Scalar(150, 150, 150));
  const cv::Point center(size_px / 2, size_px / 2);
  const int thick = std::max(1, size_px / 24);
  if (round) {
    cv::circle(img, center, size_px / 2 - thick, cv::Scalar(225, 225, 222), cv::FILLED,
               cv::LINE_AA);
    cv::circle(img, center, size_px / 2 - 2 * thick, cv::Scalar(90, 90, 90), thick, cv::LINE_AA);
  } else {
    img.setTo(cv::Scalar(225, 225, 222));
    cv::rectangle(img, cv::Rect(thick, thick, size_px - 2 * thick, size_px - 2 * thick),
                  cv::Scalar(90, 90, 90), thick, cv::LINE_AA);
  }
  const double scale = size_px / (label.size() > 1 ? 60.0 : 45.0);
  const int stroke = std::max(1, size_px / 18);
  int baseline = 0;
  const cv::Size text = cv::getTextSize(label, cv::FONT_HERSHEY_DUPLEX, scale, stroke, &baseline);
  cv::putText(img, label, cv::Point(center.x - text.width / 2, center.y + text.height / 2),
              cv::FONT_HERSHEY_DUPLEX, scale, cv::Scalar(25, 25, 30), stroke, cv::LINE_AA);
  return {img};
}

TextureImage MakeDisplayImage(const std::string& text, int width_px, int height_px) {
  cv::Mat img(height_px, width_px, CV_8UC3, cv::Scalar(25, 22, 20));
  const double scale = height_px / 36.0;
  const int stroke = std::max(1, height_px / 14);
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, stroke, &baseline);
  cv::putText(img, text, cv::Point((width_px - size.width) / 2, (height_px + size.height) / 2),
              cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(40, 60, 235), stroke, cv::LINE_AA);
  return {img};
}

}  // namespace sightline::sim
