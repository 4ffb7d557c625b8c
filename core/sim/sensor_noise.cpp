#include "core/sim/sensor_noise.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/sim/random.h"

namespace sightline::sim {

void ApplyDepthModel(const RenderedView& view, const RgbdSensorOptions& sensor,
                     const NoiseModel& noise, uint64_t seed, cv::Mat* depth_m) {
  depth_m->create(view.depth_m.size(), CV_32FC1);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float min_z = static_cast<float>(sensor.min_depth_m);
  const float max_z = static_cast<float>(sensor.max_depth_m);
  const float min_cos = static_cast<float>(std::cos(sensor.max_incidence_deg * M_PI / 180));
  // Float arithmetic: the output is float, and 1e-7 relative rounding is far below the noise.
  const float fb = static_cast<float>(sensor.focal_px * noise.ir_baseline_m);  // Native 640x480.
  const float sigma_d = static_cast<float>(noise.depth_sigma_coeff) * fb;      // Pixels.
  const float step = static_cast<float>(noise.disparity_step_px);
  const float inverse_step = step > 0 ? 1.0f / step : 0.0f;
  const bool perturb = sigma_d > 0 || step > 0;
  GaussianStream gauss(seed);
  for (int v = 0; v < view.depth_m.rows; ++v) {
    const float* z_row = view.depth_m.ptr<float>(v);
    const float* cos_row = view.incidence_cos.ptr<float>(v);
    float* out = depth_m->ptr<float>(v);
    for (int u = 0; u < view.depth_m.cols; ++u) {
      const float z = z_row[u];
      // Draw for every pixel so the noise at a pixel does not depend on the others' validity.
      const float n = sigma_d > 0 ? gauss.Next() : 0.0f;
      if (!(z >= min_z && z <= max_z) || cos_row[u] < min_cos) {
        out[u] = nan;
        continue;
      }
      if (!perturb) {
        out[u] = z;
        continue;
      }
      float d = fb / z + sigma_d * n;
      // Round to the nearest step (lrint is one instruction, unlike std::round).
      if (step > 0 && d > 0) d = static_cast<float>(std::lrint(d * inverse_step)) * step;
      out[u] = d > 0 ? fb / d : nan;
    }
  }
}

void AddImageNoise(double sigma, uint64_t seed, cv::Mat* image) {
  if (!(sigma > 0) || image->empty()) return;
  CV_Assert(image->depth() == CV_8U);
  GaussianStream gauss(seed);
  const float s = static_cast<float>(sigma);
  const int values = image->cols * image->channels();
  float n[4];
  for (int v = 0; v < image->rows; ++v) {
    uint8_t* row = image->ptr<uint8_t>(v);
    for (int i = 0; i < values; i += 4) {
      gauss.Next4(n);
      const int count = std::min(4, values - i);
      for (int k = 0; k < count; ++k) {
        const float x = row[i + k] + s * n[k] + 0.5f;
        row[i + k] = static_cast<uint8_t>(x < 0 ? 0 : (x > 255 ? 255 : x));
      }
    }
  }
}

}  // namespace sightline::sim
