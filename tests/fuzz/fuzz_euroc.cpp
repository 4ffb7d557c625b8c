// libFuzzer target: the EuRoC files, read by EurocSource::Open in a folder of one 8x6 stereo
// pair. The first byte picks the file the rest replaces: cam0/data.csv, cam0/sensor.yaml or the
// ground truth (state_groundtruth_estimate0/data.csv); the other files stay valid.
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/io/euroc_source.h"
#include "tests/fuzz/fuzz_file.h"

namespace {

const char kSensorYaml[] =
    "sensor_type: camera\n"
    "T_BS:\n  cols: 4\n  rows: 4\n  data: [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]\n"
    "rate_hz: 20\nresolution: [8, 6]\ncamera_model: pinhole\n"
    "intrinsics: [4.0, 4.0, 4.0, 3.0]\ndistortion_model: radial-tangential\n"
    "distortion_coefficients: [0.0, 0.0, 0.0, 0.0]\n";
const char kRightYaml[] =
    "sensor_type: camera\n"
    "T_BS:\n  cols: 4\n  rows: 4\n  data: [1, 0, 0, 0.1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]\n"
    "rate_hz: 20\nresolution: [8, 6]\ncamera_model: pinhole\n"
    "intrinsics: [4.0, 4.0, 4.0, 3.0]\ndistortion_model: radial-tangential\n"
    "distortion_coefficients: [0.0, 0.0, 0.0, 0.0]\n";
const char kDataCsv[] = "#timestamp [ns],filename\n1403715273262142976,1403715273262142976.png\n";
const char kTruthCsv[] =
    "#timestamp, p_x, p_y, p_z, q_w, q_x, q_y, q_z\n1403715273262142976,0,0,0,1,0,0,0\n";

void Write(const std::string& relative, const std::string& text) {
  sightline::fuzz::WriteInput(relative, reinterpret_cast<const uint8_t*>(text.data()), text.size());
}

// Writes the valid files of the folder once, and every file a previous input replaced.
void ResetFolder() {
  static bool images = false;
  if (!images) {
    const std::string dir = sightline::fuzz::ScratchDir() + "/euroc/mav0";
    for (const char* cam : {"/cam0/data", "/cam1/data"}) {
      std::filesystem::create_directories(dir + cam);
      cv::imwrite(dir + cam + "/1403715273262142976.png", cv::Mat(6, 8, CV_8UC1, cv::Scalar(100)));
    }
    images = true;
  }
  Write("euroc/mav0/cam0/data.csv", kDataCsv);
  Write("euroc/mav0/cam1/data.csv", kDataCsv);
  Write("euroc/mav0/cam0/sensor.yaml", kSensorYaml);
  Write("euroc/mav0/cam1/sensor.yaml", kRightYaml);
  Write("euroc/mav0/state_groundtruth_estimate0/data.csv", kTruthCsv);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const char* const kFiles[] = {"euroc/mav0/cam0/data.csv", "euroc/mav0/cam0/sensor.yaml",
                                       "euroc/mav0/state_groundtruth_estimate0/data.csv"};
  ResetFolder();
  sightline::fuzz::WriteInput(kFiles[data[0] % 3], data + 1, size - 1);
  sightline::EurocSource source(sightline::fuzz::ScratchDir() + "/euroc");
  (void)source.Open();
  return 0;
}
