// OpenNI2's process-wide initialisation as an explicit, reference-counted handle.
#pragma once

#include <memory>
#include <string>

#include "core/common/status.h"

namespace sightline {

// OpenNI2 keeps its drivers and devices in one library-wide context that must be initialised
// before use and shut down after. That state is unavoidable; this handle makes it explicit:
// every user (source, enumeration, probe) holds a shared handle, the first Acquire()
// initialises OpenNI2, and the last handle released shuts it down. Acquire/release are
// serialised, so any number of sources may be created and destroyed from any threads, and a
// second session after a full shutdown initialises again.
//
//   StatusOr<std::shared_ptr<OpenNi2Runtime>> runtime = OpenNi2Runtime::Acquire();
//   if (!runtime.ok()) return runtime.status();   // "OpenNI2 failed to initialise: ..."
//   openni::Device device;  // ... use OpenNI2 while *runtime is held ...
class OpenNi2Runtime {
 public:
  // Initialises OpenNI2 unless another handle is alive.
  static StatusOr<std::shared_ptr<OpenNi2Runtime>> Acquire();
  // Shuts OpenNI2 down when this is the last handle.
  ~OpenNi2Runtime();
  OpenNi2Runtime(const OpenNi2Runtime&) = delete;
  OpenNi2Runtime& operator=(const OpenNi2Runtime&) = delete;

  // Handles alive now (0 = OpenNI2 shut down); for tests and diagnostics.
  static long UseCount();

  // Marks a live device URI as used by one source. OpenNI2 shares one device between all
  // handles of a process and crashes when a second handle enables frame sync, so a second
  // source for the same device gets kUnavailable ("already open in this process") instead.
  Status ClaimDevice(const std::string& uri);
  // Ends a claim (no-op for URIs not claimed).
  void ReleaseDevice(const std::string& uri);

 private:
  OpenNi2Runtime() = default;
};

}  // namespace sightline
