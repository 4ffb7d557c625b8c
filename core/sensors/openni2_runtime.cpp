#include "core/sensors/openni2_runtime.h"

#include <OpenNI.h>

#include <mutex>
#include <set>
#include <string>

namespace sightline {
namespace {

// The one process-wide record of the handle, mirroring OpenNI2's own library-wide context.
struct RuntimeRegistry {
  std::mutex mutex;
  std::weak_ptr<OpenNi2Runtime> current;
  std::set<std::string> claimed_devices;
};

RuntimeRegistry& Registry() {
  static RuntimeRegistry registry;
  return registry;
}

}  // namespace

StatusOr<std::shared_ptr<OpenNi2Runtime>> OpenNi2Runtime::Acquire() {
  RuntimeRegistry& registry = Registry();
  std::lock_guard<std::mutex> lock(registry.mutex);
  if (std::shared_ptr<OpenNi2Runtime> alive = registry.current.lock()) return alive;
  if (openni::OpenNI::initialize() != openni::STATUS_OK) {
    const std::string detail = openni::OpenNI::getExtendedError();
    openni::OpenNI::shutdown();  // OpenNI counts initialisations, failed ones included.
    return Unavailable("OpenNI2 failed to initialise: " + detail);
  }
  std::shared_ptr<OpenNi2Runtime> runtime(new OpenNi2Runtime());
  registry.current = runtime;
  return runtime;
}

OpenNi2Runtime::~OpenNi2Runtime() {
  std::lock_guard<std::mutex> lock(Registry().mutex);
  openni::OpenNI::shutdown();
}

long OpenNi2Runtime::UseCount() {
  std::lock_guard<std::mutex> lock(Registry().mutex);
  return Registry().current.use_count();
}

}  // namespace sightline

namespace sightline {

Status OpenNi2Runtime::ClaimDevice(const std::string& uri) {
  std::lock_guard<std::mutex> lock(Registry().mutex);
  if (!Registry().claimed_devices.insert(uri).second) {
    return Unavailable("OpenNI2 device '" + uri +
                       "' is already open in this process (one source per device)");
  }
  return Status::Ok();
}

void OpenNi2Runtime::ReleaseDevice(const std::string& uri) {
  std::lock_guard<std::mutex> lock(Registry().mutex);
  Registry().claimed_devices.erase(uri);
}

}  // namespace sightline
