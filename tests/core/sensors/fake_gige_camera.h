// Test helper: GigE Vision fake cameras (arv-fake-gv-camera-0.8) inside a private network
// namespace that the test process enters before any test runs. The executable's path comes from
// the target's SIGHTLINE_ARV_FAKE_GV_CAMERA definition.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "tests/core/sensors/child_process.h"

namespace sightline::testing {

// A gtest environment that enters the namespace (with these loopback aliases) while the process
// is still single-threaded; register it with ::testing::AddGlobalTestEnvironment.
::testing::Environment* NewPrivateNetworkEnvironment(std::vector<std::string> loopback_aliases);

// Whether the environment entered the namespace (FailedPrecondition before it ran).
const Status& PrivateNetworkStatus();

// The device id Aravis gives a fake camera with this serial.
std::string FakeCameraDeviceId(const std::string& serial);

// Starts a fake camera serving `address`; null (and a test failure) when it cannot start.
std::unique_ptr<ChildProcess> StartFakeCamera(const std::string& address,
                                              const std::string& serial);

// Waits (bounded) until Aravis discovery finds the camera.
bool WaitFakeCameraDiscoverable(const std::string& serial, std::chrono::seconds limit);

}  // namespace sightline::testing

#define SIGHTLINE_REQUIRE_PRIVATE_NETWORK()                                 \
  if (!::sightline::testing::PrivateNetworkStatus().ok()) {                 \
    GTEST_SKIP() << "needs a private network namespace: "                   \
                 << ::sightline::testing::PrivateNetworkStatus().message(); \
  }
