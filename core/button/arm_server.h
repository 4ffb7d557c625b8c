// The arm-target server: serves the protocol of PROTOCOL.md (JSON lines, version 2) to TCP
// clients from its own I/O thread (POSIX sockets, poll()), and takes the arm's pose stream
// (`arm_pose` lines, core/button/arm_pose_stream.h) from the one client that is the arm.
//
// Publishing never waits for a client or for socket I/O: Publish* take a short lock that only
// guards the per-client queues, and the I/O thread holds that lock only to move one line out of a
// queue, never across recv() or send(). Every connection is read at most a fixed number of bytes
// per wake-up, so a client that floods the server cannot delay the others.
//
// Per client there are three queues: stops (never dropped), the latest heartbeat (a newer one
// replaces it) and targets (bounded; a full queue drops its oldest target). They are written in
// that order. A stop removes the targets and the heartbeat still queued for a client: nothing
// published before a stop reaches the arm after it.
//
// The I/O thread parses the `arm_pose` lines of authorised clients; the first authorised client
// that sends a valid one is the arm until it disconnects, and its poses within
// button.arm_pose.max_rate_hz go to the sink given at Start. Poses of other clients, malformed or
// out of order ones are refused and counted (the last error text is kept).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/button/arm_pose_stream.h"
#include "core/button/arm_protocol.h"
#include "core/common/status.h"
#include "core/options/option_table.h"

namespace sightline {

// Server options. Keys "button.arm.*".
struct ArmServerOptions {
  std::string bind_address = "127.0.0.1";  // IPv4 address to bind; 0.0.0.0 = every interface.
  int port = 5757;                         // TCP port; 0 = any free port (see port()).
  std::string token;            // Clients must send {"token": ...} first; required off loopback.
  int queue_messages = 64;      // Per-client target queue; full = drop the oldest target, count.
  double heartbeat_s = 0.5;     // Heartbeat period [s]; 0 = none.
  int max_clients = 8;          // Authorised clients; further ones are closed.
  int max_line_bytes = 1024;    // Longer client lines are discarded (a failed handshake).
  double handshake_s = 2.0;     // With a token: time a connection has to present it [s].
  int max_unauthenticated = 4;  // Connections still owing the token; a new one evicts the oldest.
  double close_flush_s = 0.5;   // SendStopAndClose waits this long for the stop lines [s].

  bool IsValid(std::string* error) const;
  static OptionTable<ArmServerOptions> Describe();
};

// True for 127.0.0.0/8 (the only addresses a server without a token may bind).
bool IsLoopbackAddress(const std::string& ipv4);

// Counters since Start().
struct ArmServerStats {
  int clients = 0;                 // Connected now (authorised or owing the token).
  int authorised = 0;              // Connected and receiving.
  int64_t targets = 0;             // Targets published.
  int64_t stops = 0;               // Stops published (SendStopAndClose included).
  int64_t suppressed = 0;          // Targets refused while stopped or closing.
  int64_t malformed = 0;           // Targets refused: position not finite, approach not unit.
  int64_t heartbeats = 0;          // Heartbeats published.
  int64_t sent_lines = 0;          // Lines fully written to clients.
  int64_t sent_stops = 0;          // Stop lines fully written to clients.
  int64_t dropped = 0;             // Targets and heartbeats dropped (full queue, or a stop).
  int64_t ignored_lines = 0;       // Client lines ignored after the handshake.
  int64_t rejected_clients = 0;    // Connections closed at once (max_clients).
  int64_t token_failures = 0;      // Closed after a wrong, malformed or over-long token line.
  int64_t handshake_timeouts = 0;  // Closed for not presenting the token within handshake_s.
  int64_t evicted = 0;             // Unauthenticated, closed to make room for a newer one.
  int64_t closed_for_input = 0;    // Authorised, closed for sending too much (see PROTOCOL.md).
  int64_t poses_received = 0;      // arm_pose lines of the arm handed to the sink.
  int64_t poses_over_rate = 0;     // arm_pose lines of the arm above max_rate_hz, dropped.
  int64_t poses_refused = 0;       // Malformed, out of order, not the arm's, before the token.
  std::string last_pose_error;     // Why the last one was refused (names the member).
  bool arm_connected = false;      // A client is the arm now.
};

// Where the arm's poses go: called on the server's I/O thread for every accepted arm_pose, in
// stamp order; it must return quickly (store the pose, wake a waiter) and never call the server.
using ArmPoseSink = std::function<void(const ArmPoseMessage&)>;

// Thread-safe: every public method may be called from any thread.
//
//   auto server = ArmServer::Start(options);
//   if (!server.ok()) return server.status();
//   (*server)->PublishTarget(target);     // Never blocks on a client.
//   (*server)->PublishStop("operator");   // Targets suppressed until Resume().
//   (*server)->SendStopAndClose("quit");  // Every exit path: a stop line, then closed.
class ArmServer {
 public:
  // Binds, listens and starts the thread. InvalidArgument for invalid options (a non-loopback
  // bind address without a token among them), Unavailable when the address cannot be bound (the
  // message names address and port). Without `pose_sink` every arm_pose line is refused
  // (counted); `pose_options` gives the parser's limits and max_rate_hz.
  static StatusOr<std::unique_ptr<ArmServer>> Start(ArmServerOptions options,
                                                    ArmPoseSink pose_sink = nullptr,
                                                    ArmPoseStreamOptions pose_options = {});
  // SendStopAndClose("shutdown").
  ~ArmServer();
  ArmServer(const ArmServer&) = delete;
  ArmServer& operator=(const ArmServer&) = delete;

  int port() const { return port_; }
  // Queues a target for every authorised client; returns its seq, or -1 while stopped or closed.
  int64_t PublishTarget(const ArmTarget& target);
  // Queues a stop for every authorised client ahead of everything still queued (the queued
  // targets and heartbeat are dropped) and wakes the I/O thread. Targets are suppressed until
  // Resume(). A client that authenticates while stopped receives the last stop at once. Returns
  // the stop's seq, or -1 once closed.
  int64_t PublishStop(const std::string& reason);
  // The operator starts again: targets are accepted.
  void Resume();
  bool stopped() const { return stopped_.load(); }
  ArmServerStats Stats() const;
  // The one call for every exit path (GUI quit, pipeline switch, serving turned off, end of the
  // source, a signal): publishes a stop with `reason`, waits up to close_flush_s for every
  // authorised client to receive its queued stop lines, then closes every connection and the
  // listening socket and joins the thread. Idempotent; Publish* return -1 afterwards. A client
  // that never reads cannot receive it and is closed when the wait ends.
  void SendStopAndClose(const std::string& reason);
  // SendStopAndClose("shutdown").
  void Shutdown() { SendStopAndClose("shutdown"); }

 private:
  struct Outbox;
  struct Connection;
  // What an authorised client's line was.
  enum class LineKind { kOther, kArmPose, kRefusedPose };
  ArmServer(ArmServerOptions options, ArmPoseSink pose_sink, ArmPoseStreamOptions pose_options,
            int listen_fd, int port, int wake_read, int wake_write);
  void Run();
  void Wake();
  int64_t QueueStopLocked(const std::string& reason);
  void Accept(std::vector<std::unique_ptr<Connection>>& connections);
  void Authorise(Connection& c, int authorised_now);
  void Read(Connection& c);
  void HandleLine(Connection& c);
  LineKind HandlePose(Connection& c);
  void RefusePose(const std::string& why);
  void Write(Connection& c);
  void Close(Connection& c);
  void Heartbeat();
  static double NowS();

  const ArmServerOptions options_;
  const ArmPoseSink pose_sink_;
  const ArmPoseStreamOptions pose_options_;
  bool arm_present_ = false;  // I/O thread only: a connection is the arm.
  const int listen_fd_;
  const int port_;
  const int wake_read_, wake_write_;
  std::atomic<bool> stopped_{false};
  std::atomic<bool> closing_{false};  // Set by SendStopAndClose: the I/O thread flushes and ends.
  std::mutex close_mutex_;            // Serialises SendStopAndClose callers.
  bool closed_ = false;               // Guarded by close_mutex_.
  mutable std::mutex mutex_;  // Guards outboxes_, stats_, seq_, last_stop_; never held across I/O.
  std::vector<std::shared_ptr<Outbox>> outboxes_;  // Of the authorised clients.
  ArmServerStats stats_;
  int64_t seq_ = 0;
  std::shared_ptr<const std::string> last_stop_;  // While stopped: for clients that join.
  std::thread thread_;
};

}  // namespace sightline
