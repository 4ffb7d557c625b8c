#include "core/button/arm_client.h"

#include <arpa/inet.h>
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

#include "core/button/arm_protocol.h"
#include "core/common/json_writer.h"

namespace sightline {

Status ArmClient::ParseAddress(const std::string& text, std::string* host, int* port) {
  const size_t colon = text.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 >= text.size()) {
    return InvalidArgument("address '" + text + "': expected HOST:PORT");
  }
  const std::string port_text = text.substr(colon + 1);
  char* end = nullptr;
  const long value = std::strtol(port_text.c_str(), &end, 10);
  if (*end != '\0' || value < 1 || value > 65535) {
    return InvalidArgument("address '" + text + "': port must be a number in [1, 65535]");
  }
  *host = text.substr(0, colon);
  *port = int(value);
  return Status::Ok();
}

StatusOr<ArmClient> ArmClient::Connect(const std::string& host, int port, const std::string& token,
                                       int timeout_ms) {
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found) != 0 || !found) {
    return InvalidArgument("arm client: cannot resolve host '" + host + "'");
  }
  const int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  int rc = connect(fd, found->ai_addr, found->ai_addrlen);
  freeaddrinfo(found);
  const std::string where = host + ":" + std::to_string(port);
  if (rc != 0 && errno == EINPROGRESS) {
    pollfd p{fd, POLLOUT, 0};
    rc = poll(&p, 1, timeout_ms) == 1 ? 0 : -1;
    int err = 0;
    socklen_t len = sizeof(err);
    if (rc == 0) getsockopt(fd, SOL_SOCKET, SO_ERROR, &err, &len);
    if (rc != 0 || err != 0) {
      close(fd);
      return Unavailable("arm client: cannot connect to " + where + ": " +
                         (err ? std::strerror(err) : "timeout"));
    }
  } else if (rc != 0) {
    const std::string reason = std::strerror(errno);
    close(fd);
    return Unavailable("arm client: cannot connect to " + where + ": " + reason);
  }
  ArmClient client(fd);
  if (!token.empty()) {
    SIGHTLINE_RETURN_IF_ERROR(client.Send("{\"token\": \"" + JsonWriter::Escape(token) + "\"}\n"));
  }
  return client;
}

ArmClient::ArmClient(ArmClient&& o) noexcept
    : fd_(o.fd_),
      buffer_(std::move(o.buffer_)),
      max_line_bytes_(o.max_line_bytes_),
      discarding_(o.discarding_),
      discarded_(o.discarded_) {
  o.fd_ = -1;
}

ArmClient& ArmClient::operator=(ArmClient&& o) noexcept {
  if (this != &o) {
    Close();
    fd_ = o.fd_;
    buffer_ = std::move(o.buffer_);
    max_line_bytes_ = o.max_line_bytes_;
    discarding_ = o.discarding_;
    discarded_ = o.discarded_;
    o.fd_ = -1;
  }
  return *this;
}

ArmClient::~ArmClient() { Close(); }

void ArmClient::Close() {
  if (fd_ >= 0) close(fd_);
  fd_ = -1;
}

Status ArmClient::Send(const std::string& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    pollfd p{fd_, POLLOUT, 0};
    if (poll(&p, 1, 2000) != 1) return Unavailable("arm client: send timed out");
    const ssize_t n = send(fd_, bytes.data() + done, bytes.size() - done, MSG_NOSIGNAL);
    if (n < 0 && errno != EAGAIN && errno != EINTR) {
      return Unavailable(std::string("arm client: send failed: ") + std::strerror(errno));
    }
    if (n > 0) done += size_t(n);
  }
  return Status::Ok();
}

StatusOr<std::string> ArmClient::ReadLine(int timeout_ms) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::milliseconds(timeout_ms);
  while (true) {
    const size_t newline = buffer_.find('\n');
    if (newline != std::string::npos) {
      if (discarding_) {  // The end of an over-long line: report it, keep what follows.
        const size_t length = discarded_ + newline;
        buffer_.erase(0, newline + 1);
        discarding_ = false;
        discarded_ = 0;
        return ParseError("arm client: dropped a line of " + std::to_string(length) +
                          " bytes (longer than " + std::to_string(max_line_bytes_) + ")");
      }
      if (newline > max_line_bytes_) {
        buffer_.erase(0, newline + 1);
        return ParseError("arm client: dropped a line of " + std::to_string(newline) +
                          " bytes (longer than " + std::to_string(max_line_bytes_) + ")");
      }
      std::string line = buffer_.substr(0, newline);
      buffer_.erase(0, newline + 1);
      return line;
    }
    if (buffer_.size() > max_line_bytes_) {  // No end in sight: drop what came so far.
      discarding_ = true;
      discarded_ += buffer_.size();
      buffer_.clear();
    }
    if (fd_ < 0) return Unavailable("arm client: connection closed");
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() < 0)
      return OutOfRange("arm client: no line within " + std::to_string(timeout_ms) + " ms");
    pollfd p{fd_, POLLIN, 0};
    const int ready = poll(&p, 1, int(left.count()));
    if (ready == 0) continue;
    if (ready < 0 && errno != EINTR) return Unavailable("arm client: poll failed");
    char chunk[4096];
    const ssize_t n = recv(fd_, chunk, sizeof(chunk), MSG_DONTWAIT);
    if (n == 0) {
      Close();
      return Unavailable("arm client: connection closed by the server");
    }
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
      const std::string reason = std::strerror(errno);
      Close();
      return Unavailable("arm client: connection lost: " + reason);
    }
    if (n > 0) buffer_.append(chunk, size_t(n));
  }
}

}  // namespace sightline
