#include "tests/core/sensors/fake_gige_camera.h"

#include <utility>

#include "core/sensors/aravis_source.h"
#include "core/sensors/device_info.h"
#include "tests/core/sensors/network_namespace.h"

namespace sightline::testing {
namespace {

Status& MutableStatus() {
  static Status status = FailedPrecondition("the test environment did not run");
  return status;
}

class PrivateNetworkEnvironment : public ::testing::Environment {
 public:
  explicit PrivateNetworkEnvironment(std::vector<std::string> aliases)
      : aliases_(std::move(aliases)) {}
  void SetUp() override { MutableStatus() = EnterPrivateNetworkNamespace(aliases_); }

 private:
  std::vector<std::string> aliases_;
};

}  // namespace

::testing::Environment* NewPrivateNetworkEnvironment(std::vector<std::string> loopback_aliases) {
  return new PrivateNetworkEnvironment(std::move(loopback_aliases));
}

const Status& PrivateNetworkStatus() { return MutableStatus(); }

std::string FakeCameraDeviceId(const std::string& serial) { return "Aravis-Fake-" + serial; }

std::unique_ptr<ChildProcess> StartFakeCamera(const std::string& address,
                                              const std::string& serial) {
  StatusOr<std::unique_ptr<ChildProcess>> camera =
      ChildProcess::Start({SIGHTLINE_ARV_FAKE_GV_CAMERA, "-i", address, "-s", serial});
  EXPECT_TRUE(camera.ok()) << camera.status().ToString();
  return camera.ok() ? std::move(*camera) : nullptr;
}

bool WaitFakeCameraDiscoverable(const std::string& serial, std::chrono::seconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < deadline) {
    for (const DeviceInfo& d : AravisSource::Enumerate(false)) {
      if (d.uri == "aravis://" + FakeCameraDeviceId(serial)) return true;
    }
  }
  return false;
}

}  // namespace sightline::testing
