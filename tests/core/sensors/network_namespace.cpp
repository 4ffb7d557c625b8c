#include "tests/core/sensors/network_namespace.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <net/if.h>
#include <netinet/in.h>
#include <sched.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace sightline::testing {
namespace {

std::string Errno(const std::string& what) { return what + ": " + std::strerror(errno); }

bool WriteFile(const std::string& path, const std::string& text) {
  std::ofstream file(path);
  file << text;
  file.close();
  return static_cast<bool>(file);
}

// Sets an IPv4 address (with /8 mask) on `name` ("lo" or an alias such as "lo:1").
Status SetAddress(int fd, const std::string& name, const std::string& address) {
  ifreq request{};
  std::strncpy(request.ifr_name, name.c_str(), IFNAMSIZ - 1);
  sockaddr_in* in = reinterpret_cast<sockaddr_in*>(&request.ifr_addr);
  in->sin_family = AF_INET;
  if (inet_pton(AF_INET, address.c_str(), &in->sin_addr) != 1) {
    return InvalidArgument("not an IPv4 address: " + address);
  }
  if (ioctl(fd, SIOCSIFADDR, &request) != 0) return Internal(Errno("SIOCSIFADDR " + name));
  inet_pton(AF_INET, "255.0.0.0", &in->sin_addr);
  if (ioctl(fd, SIOCSIFNETMASK, &request) != 0) return Internal(Errno("SIOCSIFNETMASK " + name));
  return Status::Ok();
}

}  // namespace

Status EnterPrivateNetworkNamespace(const std::vector<std::string>& extra_loopback_addresses) {
  if (unshare(CLONE_NEWNET) != 0) {
    const uid_t uid = getuid();
    const gid_t gid = getgid();
    if (unshare(CLONE_NEWUSER | CLONE_NEWNET) != 0) {
      return Unavailable(
          Errno("cannot create a private network namespace (unshare -n as root "
                "or unshare -rn without)"));
    }
    if (!WriteFile("/proc/self/setgroups", "deny") ||
        !WriteFile("/proc/self/uid_map", "0 " + std::to_string(uid) + " 1") ||
        !WriteFile("/proc/self/gid_map", "0 " + std::to_string(gid) + " 1")) {
      return Unavailable("cannot map the user into the new user namespace");
    }
  }
  const int fd = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return Internal(Errno("socket"));
  ifreq request{};
  std::strncpy(request.ifr_name, "lo", IFNAMSIZ - 1);
  Status status;
  if (ioctl(fd, SIOCGIFFLAGS, &request) != 0) {
    status = Internal(Errno("SIOCGIFFLAGS lo"));
  } else {
    request.ifr_flags |= IFF_UP | IFF_RUNNING;
    if (ioctl(fd, SIOCSIFFLAGS, &request) != 0) status = Internal(Errno("SIOCSIFFLAGS lo"));
  }
  for (size_t i = 0; status.ok() && i < extra_loopback_addresses.size(); ++i) {
    status = SetAddress(fd, "lo:" + std::to_string(i + 1), extra_loopback_addresses[i]);
  }
  close(fd);
  return status;
}

}  // namespace sightline::testing
