// A client of the arm-target protocol: connects, optionally presents the token and reads JSON
// lines. Used by `sightline-cli arm-listen` and the protocol tests (a real TCP peer).
#pragma once

#include <string>

#include "core/common/status.h"

namespace sightline {

// One TCP connection. Move-only; closes on destruction.
//
//   auto client = ArmClient::Connect("127.0.0.1", 5757, "secret");
//   while (true) {
//     StatusOr<std::string> line = client->ReadLine(1000);
//     if (!line.ok()) break;  // kOutOfRange: timeout; kUnavailable: closed.
//   }
class ArmClient {
 public:
  // Connects (blocking, up to timeout_ms) and sends {"token": ...} when the token is not empty.
  // Unavailable when the server cannot be reached; InvalidArgument for a bad address.
  static StatusOr<ArmClient> Connect(const std::string& host, int port, const std::string& token,
                                     int timeout_ms = 2000);
  // Parses "HOST:PORT".
  static Status ParseAddress(const std::string& text, std::string* host, int* port);

  ArmClient(ArmClient&& other) noexcept;
  ArmClient& operator=(ArmClient&& other) noexcept;
  ~ArmClient();

  // The next line without its '\n'. OutOfRange after timeout_ms without a whole line;
  // Unavailable once the server closed (or reset) the connection; ParseError for a line longer
  // than max_line_bytes (it is dropped whole, the next call reads the line after it).
  StatusOr<std::string> ReadLine(int timeout_ms);
  // Longest line ReadLine() returns (default 65536 bytes): memory stays bounded whatever the
  // peer sends.
  void set_max_line_bytes(size_t bytes) { max_line_bytes_ = bytes; }
  // Sends raw bytes (tests send malformed input with it).
  Status Send(const std::string& bytes);
  void Close();

 private:
  explicit ArmClient(int fd) : fd_(fd) {}
  int fd_ = -1;
  std::string buffer_;
  size_t max_line_bytes_ = 65536;
  bool discarding_ = false;  // Inside an over-long line: bytes are dropped up to its '\n'.
  size_t discarded_ = 0;     // Bytes of it dropped so far.
};

}  // namespace sightline
