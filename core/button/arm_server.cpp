#include "core/button/arm_server.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <deque>

#include "core/button/option_check.h"

namespace sightline {

using button_internal::Invalid;

bool IsLoopbackAddress(const std::string& ipv4) {
  in_addr addr{};
  if (inet_pton(AF_INET, ipv4.c_str(), &addr) != 1) return false;
  return (ntohl(addr.s_addr) >> 24) == 127;
}

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
  if (!(handshake_s >= 0.01 && handshake_s <= 600))
    return Invalid(error, "button.arm.handshake_s must lie in [0.01, 600]");
  if (max_unauthenticated < 1 || max_unauthenticated > 1000)
    return Invalid(error, "button.arm.max_unauthenticated must lie in [1, 1000]");
  if (!(close_flush_s >= 0 && close_flush_s <= 10))
    return Invalid(error, "button.arm.close_flush_s must lie in [0, 10]");
  if (token.empty() && !IsLoopbackAddress(bind_address)) {
    return Invalid(error, "button.arm.token must be set when button.arm.bind_address (" +
                              bind_address +
                              ") is not a loopback address: any host could receive targets and "
                              "hold the connections");
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
              "When set, a client must send {\"token\": \"...\"} before it receives anything; "
              "required when bind_address is not a loopback address.")
      .Int("queue_messages", &O::queue_messages, "", 1, 100000, 1,
           "Per-client queue length; a slow client loses its oldest messages (counted).")
      .Double("heartbeat_s", &O::heartbeat_s, "s", 0, 3600, 0.1, "Heartbeat period; 0 = none.")
      .Int("max_clients", &O::max_clients, "", 1, 1000, 1,
           "Authorised clients at most; further ones are closed.")
      .Int("max_line_bytes", &O::max_line_bytes, "bytes", 64, 1 << 20, 64,
           "Longer client lines are discarded; an over-long token line closes the connection.")
      .Double("handshake_s", &O::handshake_s, "s", 0.01, 600, 0.5,
              "With a token: a connection that has not presented it after this long is closed.")
      .Int("max_unauthenticated", &O::max_unauthenticated, "", 1, 1000, 1,
           "Connections still owing the token at most; a new one closes the oldest.")
      .Double("close_flush_s", &O::close_flush_s, "s", 0, 10, 0.1,
              "On close: how long the stop lines may take to go out before the sockets close.");
}

namespace {

using Clock = std::chrono::steady_clock;
using Line = std::shared_ptr<const std::string>;

// Per wake-up and connection: at most this many bytes read (a flooder gets its turn like everyone
// else and no more) and this many lines written (a fast client with a full queue does not hold up
// the others).
constexpr size_t kReadChunk = 4096;
constexpr int kReadChunksPerWake = 4;
constexpr int kWriteLinesPerWake = 64;
constexpr int kAcceptsPerWake = 64;
// After this many max_line_bytes of anything but the arm's poses an authorised client is closed.
constexpr int64_t kChatterLines = 16;

Status Errno(const std::string& what) { return Unavailable(what + ": " + std::strerror(errno)); }

void SetNonBlocking(int fd) { fcntl(fd, F_SETFL, fcntl(fd, F_GETFL, 0) | O_NONBLOCK); }

Clock::duration Seconds(double s) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

}  // namespace

// What publishers hand to one authorised client; guarded by ArmServer::mutex_.
struct ArmServer::Outbox {
  std::deque<Line> stops;    // Never dropped.
  Line heartbeat;            // The latest one only.
  std::deque<Line> targets;  // Bounded by queue_messages; full = drop the oldest.

  bool empty() const { return stops.empty() && !heartbeat && targets.empty(); }
  // The next line to write: stops, then the heartbeat, then targets.
  Line Pop(bool* is_stop) {
    Line line;
    *is_stop = false;
    if (!stops.empty()) {
      line = std::move(stops.front());
      stops.pop_front();
      *is_stop = true;
    } else if (heartbeat) {
      line = std::move(heartbeat);
      heartbeat.reset();
    } else if (!targets.empty()) {
      line = std::move(targets.front());
      targets.pop_front();
    }
    return line;
  }
};

// One TCP connection; owned and touched by the I/O thread only.
struct ArmServer::Connection {
  int fd = -1;
  bool authorised = false;
  Clock::time_point deadline;      // Of the handshake, while not authorised.
  std::string in;                  // Bytes received, not yet a whole line.
  bool discarding = false;         // Inside an over-long line.
  int64_t chatter_bytes = 0;       // Received after the handshake, the arm's poses aside.
  bool is_arm = false;             // Sent the first valid arm_pose; the arm until it closes.
  bool has_pose = false;           // Of the arm: last_pose_stamp is set.
  double last_pose_stamp = 0;      // Of the arm's last accepted pose [s, arm clock].
  std::shared_ptr<Outbox> outbox;  // Once authorised.
  Line writing;                    // The line being written ...
  bool writing_stop = false;       // ... is a stop ...
  size_t offset = 0;               // ... of which this many bytes went out.
};

StatusOr<std::unique_ptr<ArmServer>> ArmServer::Start(ArmServerOptions options,
                                                      ArmPoseSink pose_sink,
                                                      ArmPoseStreamOptions pose_options) {
  std::string error;
  if (!options.IsValid(&error) || !pose_options.IsValid(&error)) return InvalidArgument(error);
  const std::string where = options.bind_address + ":" + std::to_string(options.port);
  const int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return Errno("arm server: socket");
  const int one = 1;
  setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof(one));
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(uint16_t(options.port));
  inet_pton(AF_INET, options.bind_address.c_str(), &addr.sin_addr);
  if (bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) != 0 || listen(fd, 64) != 0) {
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
  return std::unique_ptr<ArmServer>(new ArmServer(std::move(options), std::move(pose_sink),
                                                  pose_options, fd, ntohs(addr.sin_port),
                                                  pipe_fds[0], pipe_fds[1]));
}

ArmServer::ArmServer(ArmServerOptions options, ArmPoseSink pose_sink,
                     ArmPoseStreamOptions pose_options, int listen_fd, int port, int wake_read,
                     int wake_write)
    : options_(std::move(options)),
      pose_sink_(std::move(pose_sink)),
      pose_options_(pose_options),
      listen_fd_(listen_fd),
      port_(port),
      wake_read_(wake_read),
      wake_write_(wake_write) {
  thread_ = std::thread([this] { Run(); });
}

ArmServer::~ArmServer() { SendStopAndClose("shutdown"); }

void ArmServer::SendStopAndClose(const std::string& reason) {
  std::lock_guard<std::mutex> close_lock(close_mutex_);
  if (closed_) return;
  closed_ = true;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    QueueStopLocked(reason);
    closing_.store(true);  // Under mutex_: no target is queued after this stop.
  }
  Wake();
  if (thread_.joinable()) thread_.join();
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

int64_t ArmServer::QueueStopLocked(const std::string& reason) {
  stopped_.store(true);
  ++stats_.stops;
  const int64_t seq = seq_++;
  auto line = std::make_shared<const std::string>(StopLine(seq, NowS(), reason));
  last_stop_ = line;
  for (auto& box : outboxes_) {
    // Nothing published before the stop may reach the arm after it.
    stats_.dropped += int64_t(box->targets.size()) + (box->heartbeat ? 1 : 0);
    box->targets.clear();
    box->heartbeat.reset();
    if (int(box->stops.size()) >= options_.queue_messages) {
      box->stops.back() = line;  // A reader that far behind still gets the latest stop.
    } else {
      box->stops.push_back(line);
    }
  }
  return seq;
}

int64_t ArmServer::PublishTarget(const ArmTarget& target) {
  int64_t seq;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopped_.load() || closing_.load()) {
      ++stats_.suppressed;
      return -1;
    }
    // The arm reads these lines: a target it would refuse (or misread) never goes out.
    if (!target.position_m.allFinite() || !IsUnitVector(target.approach)) {
      ++stats_.malformed;
      return -1;
    }
    ++stats_.targets;
    seq = seq_++;
    auto line = std::make_shared<const std::string>(TargetLine(seq, NowS(), target));
    for (auto& box : outboxes_) {
      if (int(box->targets.size()) >= options_.queue_messages) {
        box->targets.pop_front();
        ++stats_.dropped;
      }
      box->targets.push_back(line);
    }
  }
  Wake();
  return seq;
}

int64_t ArmServer::PublishStop(const std::string& reason) {
  int64_t seq;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (closing_.load()) return -1;  // SendStopAndClose sent its own.
    seq = QueueStopLocked(reason);
  }
  Wake();
  return seq;
}

void ArmServer::Resume() {
  std::lock_guard<std::mutex> lock(mutex_);
  stopped_.store(false);
  last_stop_.reset();
}

ArmServerStats ArmServer::Stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

void ArmServer::Heartbeat() {
  std::lock_guard<std::mutex> lock(mutex_);
  // closing_ is set under this lock right after the final stop: nothing follows that stop.
  if (closing_.load()) return;
  ++stats_.heartbeats;
  // Made under the same lock as stops: a heartbeat never says "enabled" after a stop.
  auto line = std::make_shared<const std::string>(HeartbeatLine(seq_++, NowS(), !stopped_.load()));
  for (auto& box : outboxes_) {
    if (box->heartbeat) ++stats_.dropped;
    box->heartbeat = line;
  }
}

void ArmServer::Authorise(Connection& c, int authorised_now) {
  if (authorised_now >= options_.max_clients) {
    std::lock_guard<std::mutex> lock(mutex_);
    ++stats_.rejected_clients;
    Close(c);
    return;
  }
  c.authorised = true;
  c.in.clear();
  c.outbox = std::make_shared<Outbox>();
  std::lock_guard<std::mutex> lock(mutex_);
  if (last_stop_) c.outbox->stops.push_back(last_stop_);  // Joined while stopped.
  outboxes_.push_back(c.outbox);
}

void ArmServer::Accept(std::vector<std::unique_ptr<Connection>>& connections) {
  for (int k = 0; k < kAcceptsPerWake; ++k) {
    const int fd = accept4(listen_fd_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) return;
    const int one = 1;
    setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one));
    auto c = std::make_unique<Connection>();
    c->fd = fd;
    int authorised = 0;
    Connection* oldest_pending = nullptr;
    int pending = 0;
    for (const auto& other : connections) {
      if (other->fd < 0) continue;
      if (other->authorised) {
        ++authorised;
      } else {
        ++pending;
        if (!oldest_pending || other->deadline < oldest_pending->deadline)
          oldest_pending = other.get();
      }
    }
    if (options_.token.empty()) {
      Authorise(*c, authorised);
      if (c->fd < 0) continue;
    } else {
      // Room for the newcomer: idle sockets cannot lock a client with the token out.
      if (pending >= options_.max_unauthenticated && oldest_pending) {
        {
          std::lock_guard<std::mutex> lock(mutex_);
          ++stats_.evicted;  // Counted before the peer can see the close.
        }
        Close(*oldest_pending);
      }
      c->deadline = Clock::now() + Seconds(options_.handshake_s);
    }
    connections.push_back(std::move(c));
  }
}

void ArmServer::HandleLine(Connection& c) {
  if (!c.authorised) {
    // One attempt per connection: a wrong or malformed token line closes it.
    const std::optional<std::string> token = c.discarding ? std::nullopt : ParseTokenLine(c.in);
    if (token && TokensMatch(*token, options_.token)) {
      int authorised = 0;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        authorised = int(outboxes_.size());
      }
      Authorise(c, authorised);
    } else {
      if (!c.discarding && ParseArmPoseLine(c.in, pose_options_).ok())
        RefusePose("arm_pose before the token: the connection is closed");
      {
        std::lock_guard<std::mutex> lock(mutex_);
        ++stats_.token_failures;
      }
      Close(c);
    }
    return;
  }
  const LineKind kind = c.discarding ? LineKind::kOther : HandlePose(c);
  if (kind == LineKind::kArmPose) {
    c.chatter_bytes -= int64_t(c.in.size()) + 1;  // The arm's poses are not chatter.
    return;
  }
  if (kind == LineKind::kRefusedPose) return;  // Counted; its bytes stay on the budget.
  std::lock_guard<std::mutex> lock(mutex_);
  ++stats_.ignored_lines;  // Other lines are ignored.
}

void ArmServer::RefusePose(const std::string& why) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++stats_.poses_refused;
  stats_.last_pose_error = why;
}

ArmServer::LineKind ArmServer::HandlePose(Connection& c) {
  if (c.in.find("arm_pose") == std::string::npos) return LineKind::kOther;
  StatusOr<ArmPoseMessage> pose = ParseArmPoseLine(c.in, pose_options_);
  std::string refusal;
  if (!pose.ok()) {
    refusal = pose.status().message();
  } else if (!pose_sink_) {
    refusal = "arm_pose: this server takes no arm poses";
  } else if (arm_present_ && !c.is_arm) {
    refusal = "arm_pose: another client is the arm (one arm per server)";
  } else if (c.has_pose && !(pose->stamp_s > c.last_pose_stamp)) {
    refusal = "arm_pose: \"stamp\" is not after the arm's previous pose";
  }
  if (!refusal.empty()) {
    RefusePose(refusal);
    return LineKind::kRefusedPose;
  }
  if (!c.is_arm) c.is_arm = arm_present_ = true;
  if (c.has_pose && !KeepsRate(c.last_pose_stamp, pose->stamp_s, pose_options_.max_rate_hz)) {
    std::lock_guard<std::mutex> lock(mutex_);
    ++stats_.poses_over_rate;  // Dropped; a well-behaved arm above the rate is not chatter.
    return LineKind::kArmPose;
  }
  c.has_pose = true;
  c.last_pose_stamp = pose->stamp_s;
  pose_sink_(*pose);  // Quick by contract; no lock held.
  std::lock_guard<std::mutex> lock(mutex_);
  ++stats_.poses_received;
  return LineKind::kArmPose;
}

void ArmServer::Read(Connection& c) {
  char buffer[kReadChunk];
  for (int chunk = 0; chunk < kReadChunksPerWake && c.fd >= 0; ++chunk) {
    const ssize_t n = recv(c.fd, buffer, sizeof(buffer), 0);
    if (n == 0) {
      Close(c);
      return;
    }
    if (n < 0) {
      if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) Close(c);
      return;
    }
    if (c.authorised) c.chatter_bytes += n;  // The arm's poses are refunded line by line.
    for (ssize_t i = 0; i < n && c.fd >= 0; ++i) {
      const char ch = buffer[i];
      if (ch != '\n') {
        if (!c.discarding) c.in.push_back(ch);
        if (int(c.in.size()) > options_.max_line_bytes) {
          c.in.clear();
          c.discarding = true;
          if (!c.authorised) HandleLine(c);  // An over-long token line is a failed attempt.
        }
        continue;
      }
      const bool was_authorised = c.authorised;
      HandleLine(c);
      c.in.clear();
      c.discarding = false;
      // Authorised by this line: the rest of the chunk is its first lines (an arm streams its
      // poses right after the token), on the budget like every byte after the handshake.
      if (!was_authorised && c.authorised) c.chatter_bytes += n - i - 1;
    }
    if (c.fd >= 0 && c.authorised && c.chatter_bytes > kChatterLines * options_.max_line_bytes) {
      std::lock_guard<std::mutex> lock(mutex_);
      ++stats_.closed_for_input;
      Close(c);
      return;
    }
    if (n < ssize_t(sizeof(buffer))) return;  // Drained.
  }
}

void ArmServer::Write(Connection& c) {
  for (int lines = 0; lines < kWriteLinesPerWake && c.fd >= 0; ++lines) {
    if (!c.writing) {
      std::lock_guard<std::mutex> lock(mutex_);
      c.writing = c.outbox->Pop(&c.writing_stop);
      c.offset = 0;
      if (!c.writing) return;
    }
    const std::string& line = *c.writing;
    const ssize_t n =
        send(c.fd, line.data() + c.offset, line.size() - c.offset, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0) {
      if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) Close(c);
      return;
    }
    c.offset += size_t(n);
    if (c.offset < line.size()) return;  // Socket full: POLLOUT tells when to go on.
    c.writing.reset();
    std::lock_guard<std::mutex> lock(mutex_);
    ++stats_.sent_lines;
    if (c.writing_stop) ++stats_.sent_stops;
  }
}

void ArmServer::Close(Connection& c) {
  if (c.fd < 0) return;
  if (c.is_arm) arm_present_ = c.is_arm = false;  // Another client may be the arm now.
  // Read what the peer sent so that close() ends with FIN, not a reset that could discard the
  // stop line still in flight to it (bounded: a flooder is reset).
  shutdown(c.fd, SHUT_WR);
  char drain[kReadChunk];
  for (int k = 0; k < kReadChunksPerWake && recv(c.fd, drain, sizeof(drain), MSG_DONTWAIT) > 0;
       ++k) {
  }
  close(c.fd);
  c.fd = -1;
}

void ArmServer::Run() {
  // A stop must go out while the perception pipeline keeps every core busy: this thread asks
  // for a higher priority than the workers (nice -10). Without the right to (no CAP_SYS_NICE,
  // RLIMIT_NICE too low) it keeps the default; nothing else depends on it.
  [[maybe_unused]] const int ignored = setpriority(PRIO_PROCESS, pid_t(syscall(SYS_gettid)), -10);
  const bool heartbeats = options_.heartbeat_s > 0;
  auto next_heartbeat = Clock::now() + Seconds(options_.heartbeat_s);
  std::vector<std::unique_ptr<Connection>> connections;
  std::vector<pollfd> fds;
  std::vector<Connection*> polled;
  bool flushing = false;
  Clock::time_point flush_deadline;
  while (true) {
    const auto now = Clock::now();
    if (closing_.load() && !flushing) {
      flushing = true;  // The final stop is queued: unauthenticated peers have nothing coming.
      flush_deadline = now + Seconds(options_.close_flush_s);
      for (auto& c : connections)
        if (!c->authorised) Close(*c);
    }
    // Which authorised connections have something to write (one short lock for all).
    fds.clear();
    polled.clear();
    fds.push_back({wake_read_, POLLIN, 0});
    fds.push_back({listen_fd_, short(flushing ? 0 : POLLIN), 0});
    Clock::time_point wake_at = Clock::time_point::max();
    if (heartbeats && !flushing) wake_at = next_heartbeat;
    if (flushing) wake_at = flush_deadline;
    bool pending_output = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (const auto& c : connections) {
        if (c->fd < 0) continue;
        const bool out = c->authorised && (c->writing || !c->outbox->empty());
        pending_output |= out;
        fds.push_back({c->fd, short(POLLIN | (out ? POLLOUT : 0)), 0});
        polled.push_back(c.get());
        if (!c->authorised) wake_at = std::min(wake_at, c->deadline);
      }
    }
    if (flushing && (!pending_output || now >= flush_deadline)) break;
    int timeout_ms = -1;
    if (wake_at != Clock::time_point::max()) {
      const auto left = std::chrono::ceil<std::chrono::milliseconds>(wake_at - now);
      timeout_ms = int(std::clamp<int64_t>(left.count(), 0, 60000));
    }
    if (poll(fds.data(), fds.size(), timeout_ms) < 0 && errno != EINTR) break;
    if (fds[0].revents & POLLIN) {
      char drain[256];
      while (read(wake_read_, drain, sizeof(drain)) > 0) {
      }
    }
    if (!flushing && (fds[1].revents & POLLIN)) Accept(connections);
    if (heartbeats && !flushing && Clock::now() >= next_heartbeat) {
      Heartbeat();
      next_heartbeat = Clock::now() + Seconds(options_.heartbeat_s);
    }
    // Every authorised connection is offered its queue, polled for POLLOUT or not: lines
    // published while poll() slept go out now.
    const auto after = Clock::now();
    for (size_t i = 0; i < polled.size(); ++i) {
      Connection& c = *polled[i];
      const short revents = fds[i + 2].revents;
      if (revents & (POLLERR | POLLNVAL)) Close(c);
      if (c.fd >= 0 && (revents & (POLLIN | POLLHUP))) Read(c);
      if (c.fd >= 0 && c.authorised) Write(c);
      if (c.fd >= 0 && !c.authorised && after >= c.deadline) {
        {
          std::lock_guard<std::mutex> lock(mutex_);
          ++stats_.handshake_timeouts;
        }
        Close(c);
      }
    }
    for (auto& c : connections) {  // Accepted this round: offer their queue too.
      if (c->fd >= 0 && c->authorised) Write(*c);
    }
    // Forget the closed ones.
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& c : connections) {
      if (c->fd < 0 && c->outbox) std::erase(outboxes_, c->outbox);
    }
    std::erase_if(connections, [](const std::unique_ptr<Connection>& c) { return c->fd < 0; });
    stats_.clients = int(connections.size());
    stats_.authorised = int(outboxes_.size());
    stats_.arm_connected = arm_present_;
  }
  for (auto& c : connections) Close(*c);
  std::lock_guard<std::mutex> lock(mutex_);
  outboxes_.clear();
  stats_.clients = 0;
  stats_.authorised = 0;
  stats_.arm_connected = false;
}

}  // namespace sightline
