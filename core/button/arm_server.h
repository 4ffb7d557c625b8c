// The arm-target server: serves the protocol of PROTOCOL.md (JSON lines, version 1) to any
// number of TCP clients from its own thread (POSIX sockets, poll()). Publishing never blocks on
// a client: each client has a bounded queue; when it is full the oldest message is dropped and
// counted. STOP goes out at once and suppresses targets until Resume().
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/button/arm_protocol.h"
#include "core/common/status.h"
#include "core/options/option_table.h"

namespace sightline {

// Server options. Keys "button.arm.*".
struct ArmServerOptions {
  std::string bind_address = "127.0.0.1";  // IPv4 address to bind; 0.0.0.0 = every interface.
  int port = 5757;                         // TCP port; 0 = any free port (see port()).
  std::string token;                       // Non-empty: clients must send {"token": ...} first.
  int queue_messages = 64;                 // Per-client queue; full = drop oldest, count.
  double heartbeat_s = 0.5;                // Heartbeat period [s]; 0 = none.
  int max_clients = 8;                     // More connections are closed at once.
  int max_line_bytes = 1024;               // Longer client lines are discarded.

  bool IsValid(std::string* error) const;
  static OptionTable<ArmServerOptions> Describe();
};

// Counters since Start().
struct ArmServerStats {
  int clients = 0;               // Connected now.
  int authorised = 0;            // Connected and receiving.
  int64_t targets = 0;           // Targets published.
  int64_t stops = 0;             // Stops published.
  int64_t suppressed = 0;        // Targets refused while stopped.
  int64_t heartbeats = 0;        // Heartbeats published.
  int64_t sent_lines = 0;        // Lines fully written to clients.
  int64_t dropped = 0;           // Lines dropped from full client queues.
  int64_t ignored_lines = 0;     // Client lines ignored (malformed, wrong token, after handshake).
  int64_t rejected_clients = 0;  // Connections refused (max_clients).
};

// Thread-safe: Publish*, Resume, Stats may be called from any thread.
//
//   auto server = ArmServer::Start(options);
//   if (!server.ok()) return server.status();
//   (*server)->PublishTarget(target);     // Never blocks on a client.
//   (*server)->PublishStop("operator");   // Targets suppressed until Resume().
class ArmServer {
 public:
  // Binds, listens and starts the thread. InvalidArgument for invalid options, Unavailable
  // when the address cannot be bound (the message names address and port).
  static StatusOr<std::unique_ptr<ArmServer>> Start(ArmServerOptions options);
  ~ArmServer();
  ArmServer(const ArmServer&) = delete;
  ArmServer& operator=(const ArmServer&) = delete;

  int port() const { return port_; }
  // Queues a target for every authorised client; returns its seq, or -1 while stopped.
  int64_t PublishTarget(const ArmTarget& target);
  // Queues a stop for every authorised client ahead of nothing: it is sent at once. Targets
  // are suppressed until Resume().
  int64_t PublishStop(const std::string& reason);
  // The operator starts again: targets are accepted.
  void Resume();
  bool stopped() const { return stopped_.load(); }
  ArmServerStats Stats() const;
  // Closes every connection and joins the thread; called by the destructor.
  void Shutdown();

 private:
  struct Client;
  ArmServer(ArmServerOptions options, int listen_fd, int port, int wake_read, int wake_write);
  void Run();
  void Broadcast(const std::string& line, bool is_stop);
  void Wake();
  void Accept();
  bool Read(Client& client);
  bool Write(Client& client);
  void Heartbeat();
  static double NowS();

  const ArmServerOptions options_;
  const int listen_fd_;
  const int port_;
  const int wake_read_, wake_write_;
  std::atomic<bool> running_{true};
  std::atomic<bool> stopped_{false};
  mutable std::mutex mutex_;  // Guards clients_, stats_ and seq_.
  std::vector<std::unique_ptr<Client>> clients_;
  ArmServerStats stats_;
  int64_t seq_ = 0;
  std::thread thread_;
};

}  // namespace sightline
