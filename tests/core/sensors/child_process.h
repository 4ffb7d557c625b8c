// Test helper: a child process that dies with its owner (RAII and parent-death signal).
#pragma once

#include <sys/types.h>

#include <memory>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline::testing {

// A program run by a test, e.g. a camera simulator. Killed (SIGKILL) and reaped by the
// destructor; the kernel also kills it if the test process dies first (PR_SET_PDEATHSIG), so
// no simulator outlives a crashed test. Its output goes to /dev/null.
//
//   auto camera = ChildProcess::Start({"/usr/bin/arv-fake-gv-camera-0.8", "-i", "127.0.0.1"});
//   if (!camera.ok()) FAIL() << camera.status().ToString();
//   ...
//   (*camera)->Kill();   // mid-stream, to test a disconnect
class ChildProcess {
 public:
  // Starts argv[0] (a path) with the arguments; fails when it cannot be executed.
  static StatusOr<std::unique_ptr<ChildProcess>> Start(const std::vector<std::string>& argv);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  // SIGKILL and wait; idempotent.
  void Kill();
  // True while the process has not exited.
  bool Running();
  pid_t pid() const { return pid_; }

 private:
  explicit ChildProcess(pid_t pid) : pid_(pid) {}
  pid_t pid_;
  bool reaped_ = false;
};

}  // namespace sightline::testing
