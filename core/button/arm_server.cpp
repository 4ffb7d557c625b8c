#include "core/button/arm_server.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <deque>

#include "core/button/option_check.h"

namespace sightline {

using button_internal::Invalid;

bool ArmServerOptions::IsValid(std::string* error) const {
  in_addr addr{};
  if (inet_pton(AF_INET, bind_address.c_str(), &addr) != 1) {
    return Invalid(error, "button.arm.bind_address = '" + bind_address + "': not an IPv4 address");
  }
  if (port < 0 || port > 65535) return Invalid(error, "button.arm.port must lie in [0, 65535]");
  if (token.find_first_of("\"\\\n\r") != std::string::npos) {
    return Invalid(error, "button.arm.token must not contain quotes, backslashes or line breaks");
  }
  if (queue_messages < 1 || queue_messages > 100000) {
    return Invalid(error, "button.arm.queue_messages must lie in [1, 100000]");
  }
  if (!(heartbeat_s >= 0 && heartbeat_s <= 3600))
    return Invalid(error, "button.arm.heartbeat_s must lie in [0, 3600]");
  if (max_clients < 1 || max_clients > 1000)
    return Invalid(error, "button.arm.max_clients must lie in [1, 1000]");
  if (max_line_bytes < 64 || max_line_bytes > 1 << 20) {
    return Invalid(error, "button.arm.max_line_bytes must lie in [64, 1048576]");
  }
  return true;
}

OptionTable<ArmServerOptions> ArmServerOptions::Describe() {
  using O = ArmServerOptions;
  return OptionTable<O>("button.arm")
      .String("bind_address", &O::bind_address,
              "IPv4 address the target server binds; 127.0.0.1 keeps it on this machine.")
      .Int("port", &O::port, "", 0, 65535, 1, "TCP port of the target server; 0 = any free port.")
      .String("token", &O::token,
              "When set, a client must send {\"token\": \"...\"} before it receives anything.")
      .Int("queue_messages", &O::queue_messages, "", 1, 100000, 1,
           "Per-client queue length; a slow client loses its oldest messages (counted).")
      .Double("heartbeat_s", &O::heartbeat_s, "s", 0, 3600, 0.1, "Heartbeat period; 0 = none.")
      .Int("max_clients", &O::max_clients, "", 1, 1000, 1, "Further connections are closed.")
      .Int("max_line_bytes", &O::max_line_bytes, "bytes", 64, 1 << 20, 64,
           "Longer client lines are discarded.");
}

struct ArmServer::Client {
  int fd = -1;
  bool authorised = false;
  std::string in;           // Bytes received, not yet a whole line.
  bool discarding = false;  // Inside an over-long line.
  std::deque<std::shared_ptr<const std::string>> out;
  size_t out_offset = 0;  // Bytes of out.front() already written.
};

namespace {

Status Errno(const std::string& what) { return Unavailable(what + ": " + std::strerror(errno)); }

void SetNonBlocking(int fd) { fcntl(fd, F_SETFL, fcntl(fd, F_GETFL, 0) | O_NONBLOCK); }

bool IsStop(const std::string& line) { return line.find("\"type\":\"stop\"") != std::string::npos; }

}  // namespace

StatusOr<std::unique_ptr<ArmServer>> ArmServer::Start(ArmServerOptions options) {
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);
  const std::string where = options.bind_address + ":" + std::to_string(options.port);
  const int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return Errno("arm server: socket");
  const int one = 1;
  setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof(one));
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(uint16_t(options.port));
  inet_pton(AF_INET, options.bind_address.c_str(), &addr.sin_addr);
  if (bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) != 0 || listen(fd, 16) != 0) {
    Status s = Errno("arm server: cannot listen on " + where);
    close(fd);
    return s;
  }
  socklen_t len = sizeof(addr);
  getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len);
  SetNonBlocking(fd);
  int pipe_fds[2];
  if (pipe2(pipe_fds, O_CLOEXEC | O_NONBLOCK) != 0) {
    close(fd);
    return Errno("arm server: pipe");
  }
  return std::unique_ptr<ArmServer>(
      new ArmServer(std::move(options), fd, ntohs(addr.sin_port), pipe_fds[0], pipe_fds[1]));
}

ArmServer::ArmServer(ArmServerOptions options, int listen_fd, int port, int wake_read,
                     int wake_write)
    : options_(std::move(options)),
      listen_fd_(listen_fd),
      port_(port),
      wake_read_(wake_read),
      wake_write_(wake_write) {
  thread_ = std::thread([this] { Run(); });
}

ArmServer::~ArmServer() { Shutdown(); }

void ArmServer::Shutdown() {
  if (!running_.exchange(false)) return;
  Wake();
  if (thread_.joinable()) thread_.join();
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto& c : clients_) close(c->fd);
  clients_.clear();
  close(listen_fd_);
  close(wake_read_);
  close(wake_write_);
}

double ArmServer::NowS() {
  using namespace std::chrono;
  return duration<double>(system_clock::now().time_since_epoch()).count();
}

void ArmServer::Wake() {
  const char byte = 1;
  [[maybe_unused]] ssize_t n = write(wake_write_, &byte, 1);  // Full pipe: already awake.
}

void ArmServer::Broadcast(const std::string& line, bool is_stop) {
  auto shared = std::make_shared<const std::string>(line);
  for (auto& c : clients_) {
    if (!c->authorised) continue;
    if (int(c->out.size()) >= options_.queue_messages) {
      // Drop the oldest message not being written; a stop only displaces non-stops.
      auto victim = c->out.begin() + (c->out_offset > 0 ? 1 : 0);
      if (is_stop) {
        while (victim != c->out.end() && IsStop(**victim)) ++victim;
      }
      if (victim == c->out.end()) {
        ++stats_.dropped;
        continue;
      }
      c->out.erase(victim);
      ++stats_.dropped;
    }
    c->out.push_back(shared);
  }
}

int64_t ArmServer::PublishTarget(const ArmTarget& target) {
  int64_t seq;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopped_.load()) {
      ++stats_.suppressed;
      return -1;
    }
    ++stats_.targets;
    seq = seq_++;
    Broadcast(TargetLine(seq, NowS(), target), false);
  }
  Wake();
  return seq;
}

int64_t ArmServer::PublishStop(const std::string& reason) {
  int64_t seq;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_.store(true);
    ++stats_.stops;
    seq = seq_++;
    Broadcast(StopLine(seq, NowS(), reason), true);
  }
  Wake();
  return seq;
}

void ArmServer::Resume() { stopped_.store(false); }

ArmServerStats ArmServer::Stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  ArmServerStats s = stats_;
  s.clients = int(clients_.size());
  s.authorised = 0;
  for (const auto& c : clients_) s.authorised += c->authorised ? 1 : 0;
  return s;
}

void ArmServer::Heartbeat() {
  std::lock_guard<std::mutex> lock(mutex_);
  ++stats_.heartbeats;
  Broadcast(HeartbeatLine(seq_++, NowS(), !stopped_.load()), false);
}

void ArmServer::Accept() {
  while (true) {
    const int fd = accept4(listen_fd_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) return;
    std::lock_guard<std::mutex> lock(mutex_);
    if (int(clients_.size()) >= options_.max_clients) {
      ++stats_.rejected_clients;
      close(fd);
      continue;
    }
    const int one = 1;
    setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one));
    auto client = std::make_unique<Client>();
    client->fd = fd;
    client->authorised = options_.token.empty();
    clients_.push_back(std::move(client));
  }
}

bool ArmServer::Read(Client& c) {
  char buffer[4096];
  while (true) {
    const ssize_t n = recv(c.fd, buffer, sizeof(buffer), 0);
    if (n == 0) return false;
    if (n < 0) return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR;
    for (ssize_t i = 0; i < n; ++i) {
      const char ch = buffer[i];
      if (ch != '\n') {
        if (!c.discarding) c.in.push_back(ch);
        if (int(c.in.size()) > options_.max_line_bytes) {
          c.in.clear();
          c.discarding = true;
        }
        continue;
      }
      if (c.discarding) {
        ++stats_.ignored_lines;
      } else if (!c.authorised) {
        const std::optional<std::string> token = ParseTokenLine(c.in);
        if (token && *token == options_.token)
          c.authorised = true;
        else
          ++stats_.ignored_lines;
      } else {
        ++stats_.ignored_lines;  // Clients have nothing to say after the handshake.
      }
      c.in.clear();
      c.discarding = false;
    }
  }
}

bool ArmServer::Write(Client& c) {
  while (!c.out.empty()) {
    const std::string& line = *c.out.front();
    const ssize_t n = send(c.fd, line.data() + c.out_offset, line.size() - c.out_offset,
                           MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0) return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR;
    c.out_offset += size_t(n);
    if (c.out_offset < line.size()) return true;
    c.out.pop_front();
    c.out_offset = 0;
    ++stats_.sent_lines;
  }
  return true;
}

void ArmServer::Run() {
  using Clock = std::chrono::steady_clock;
  const auto period = std::chrono::duration<double>(options_.heartbeat_s);
  auto next_heartbeat = Clock::now() + std::chrono::duration_cast<Clock::duration>(period);
  std::vector<pollfd> fds;
  while (running_.load()) {
    int timeout_ms = -1;
    if (options_.heartbeat_s > 0) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(next_heartbeat - Clock::now());
      timeout_ms = int(std::max<int64_t>(0, left.count()));
    }
    fds.clear();
    fds.push_back({wake_read_, POLLIN, 0});
    fds.push_back({listen_fd_, POLLIN, 0});
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (const auto& c : clients_) {
        fds.push_back({c->fd, short(POLLIN | (c->out.empty() ? 0 : POLLOUT)), 0});
      }
    }
    if (poll(fds.data(), fds.size(), timeout_ms) < 0 && errno != EINTR) break;
    if (fds[0].revents & POLLIN) {
      char drain[256];
      while (read(wake_read_, drain, sizeof(drain)) > 0) {
      }
    }
    if (!running_.load()) break;
    if (fds[1].revents & POLLIN) Accept();
    if (options_.heartbeat_s > 0 && Clock::now() >= next_heartbeat) {
      Heartbeat();
      next_heartbeat = Clock::now() + std::chrono::duration_cast<Clock::duration>(period);
    }
    std::lock_guard<std::mutex> lock(mutex_);
    // Clients polled this round keep their indices: clients_ only grows in Accept (appended).
    for (size_t i = 2; i < fds.size(); ++i) {
      Client& c = *clients_[i - 2];
      bool alive = !(fds[i].revents & (POLLERR | POLLNVAL));
      if (alive && (fds[i].revents & (POLLIN | POLLHUP))) alive = Read(c);
      if (alive) alive = Write(c);  // Also sends what was queued since poll().
      if (!alive) {
        close(c.fd);
        c.fd = -1;
      }
    }
    std::erase_if(clients_, [](const std::unique_ptr<Client>& c) { return c->fd < 0; });
  }
}

}  // namespace sightline
