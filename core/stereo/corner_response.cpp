#include "core/stereo/corner_response.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace sightline {

namespace {

// The rows of the response; kBlock > 0 fixes the block size at compile time (so the loops
// vectorise), 0 takes `block` at run time.
template <int kBlock>
void ResponseRows(const cv::Mat& derivatives, const cv::Rect& valid, const cv::Rect& region,
                  int block, float scale, cv::Mat* response) {
  const int b = kBlock > 0 ? kBlock : block;
  const int h = b / 2;
  const int w = valid.width, span = w + 2 * h;
  // Products of the derivatives summed over the block's rows, per column.
  std::vector<float> xx(static_cast<size_t>(span)), xy(xx.size()), yy(xx.size());
  for (int y = valid.y; y < valid.y + valid.height; ++y) {
    std::fill(xx.begin(), xx.end(), 0.0f);
    std::fill(xy.begin(), xy.end(), 0.0f);
    std::fill(yy.begin(), yy.end(), 0.0f);
    for (int dy = -h; dy <= h; ++dy) {
      const short* d = derivatives.ptr<short>(y + dy) + 2 * (valid.x - h);
      for (int x = 0; x < span; ++x) {
        const float gx = d[2 * x], gy = d[2 * x + 1];
        xx[static_cast<size_t>(x)] += gx * gx;
        xy[static_cast<size_t>(x)] += gx * gy;
        yy[static_cast<size_t>(x)] += gy * gy;
      }
    }
    float* out = response->ptr<float>(y - region.y) + (valid.x - region.x);
    const float* pxx = xx.data();
    const float* pxy = xy.data();
    const float* pyy = yy.data();
    for (int x = 0; x < w; ++x) {
      float a = 0, c = 0, d = 0;
      for (int k = 0; k < b; ++k) {
        a += pxx[x + k];
        d += pxy[x + k];
        c += pyy[x + k];
      }
      const float half_diff = 0.5f * (a - c);
      out[x] = scale * (0.5f * (a + c) - std::sqrt(half_diff * half_diff + d * d));
    }
  }
}

}  // namespace

void MinEigenResponse(const cv::Mat& derivatives, const cv::Rect& region, int block_size,
                      cv::Mat* response) {
  CV_Assert(derivatives.type() == CV_16SC2 && block_size >= 1 && block_size % 2 == 1);
  response->create(region.size(), CV_32FC1);
  response->setTo(0);
  const int h = block_size / 2;
  // Pixels whose whole block lies inside the image.
  const cv::Rect valid =
      region & cv::Rect(h, h, derivatives.cols - 2 * h, derivatives.rows - 2 * h);
  if (valid.width <= 0 || valid.height <= 0) return;
  // cornerMinEigenVal scales a 3x3 Sobel derivative by 1 / (4 * block * 255); a Scharr
  // derivative of a ramp is 4 times a Sobel one.
  const float d_scale = 1.0f / (16.0f * static_cast<float>(block_size) * 255.0f);
  const float scale = d_scale * d_scale;
  switch (block_size) {
    case 3:
      ResponseRows<3>(derivatives, valid, region, 3, scale, response);
      break;
    case 5:
      ResponseRows<5>(derivatives, valid, region, 5, scale, response);
      break;
    default:
      ResponseRows<0>(derivatives, valid, region, block_size, scale, response);
  }
}

}  // namespace sightline
