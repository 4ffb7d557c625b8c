// Test helper: moves the test process into a private network namespace, so that GigE Vision
// discovery broadcasts and camera streams never leave it.
#pragma once

#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline::testing {

// Enters a new network namespace: unshare(CLONE_NEWNET) when privileged (root), else a new
// user namespace mapping the current user to root as well (what `unshare -rn` does). Then
// brings the loopback interface up (127.0.0.1/8) and adds each of `extra_loopback_addresses`
// (e.g. "127.0.0.2") as an alias of lo, so that several cameras can each own an address.
// Call while the process is single-threaded (a user namespace requires it), e.g. from a
// ::testing::Environment's SetUp(). Child processes started afterwards share the namespace.
Status EnterPrivateNetworkNamespace(const std::vector<std::string>& extra_loopback_addresses);

}  // namespace sightline::testing
