// sightline-cli arm-listen: a client of the arm-target protocol that prints what arrives and
// can play an arm's recorded poses to the server as arm_pose lines, for demos and tests
// (core/button/PROTOCOL.md).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "app/cli/cli_args.h"
#include "app/cli/commands.h"
#include "core/button/arm_client.h"
#include "core/button/arm_pose_stream.h"
#include "core/common/trajectory.h"

namespace sightline::cli {

namespace {

const char kHelp[] =
    "usage: sightline-cli arm-listen HOST:PORT [--token T] [--count N] [--timeout S]\n"
    "                                [--no-heartbeats] [--max-line-bytes B] [--poses FILE]\n"
    "\n"
    "Connects to Sightline's arm-target server and prints every JSON line it sends (targets,\n"
    "heartbeats, stops), one per line, as they arrive. See core/button/PROTOCOL.md.\n"
    "\n"
    "  --token T         present this token first (needed when the server has one)\n"
    "  --count N         exit after N printed messages\n"
    "  --timeout S       exit with an error when nothing is printed for S seconds\n"
    "  --no-heartbeats   do not print (or count) heartbeat messages\n"
    "  --max-line-bytes B  longer lines are dropped and reported on stderr (default 65536)\n"
    "  --poses FILE      act as the arm: send FILE's poses (TUM: stamp, base_from_end_effector,\n"
    "                    e.g. a recording's arm_poses.txt) as arm_pose lines, all at once\n"
    "                    after the handshake (the server keeps button.arm_pose.keep_s of them)\n"
    "\n"
    "Exits 0 after --count messages, or when the server closes the stream after a stop line;\n"
    "a stream that ends without a stop (the arm would not know to stop) exits 1.\n";

bool ParsePositive(const std::string& text, double* value) {
  char* end = nullptr;
  *value = std::strtod(text.c_str(), &end);
  return end && *end == '\0' && *value > 0;
}

// FILE's poses as arm_pose lines.
StatusOr<std::string> PoseLines(const std::string& file) {
  StatusOr<Trajectory> poses = ReadTumTrajectory(file);
  if (!poses.ok()) return poses.status();
  std::string lines;
  for (const TimedPose& p : poses->poses()) {
    ArmPoseMessage m;
    m.stamp_s = p.time_s;
    m.base_from_end_effector = p.world_from_sensor;
    lines += ArmPoseLine(m) + "\n";
  }
  return lines;
}

}  // namespace

int ArmListenCommand(const std::vector<std::string>& argv) {
  auto parsed =
      CliArgs::Parse(argv, {"--token", "--count", "--timeout", "--max-line-bytes", "--poses"},
                     {"--help", "--no-heartbeats"});
  if (!parsed.ok()) return Fail("arm-listen: " + parsed.status().message());
  if (parsed->Has("--help")) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  if (parsed->positionals().size() != 1) return Fail("arm-listen: expected HOST:PORT (see --help)");
  std::string host;
  int port = 0;
  const Status address = ArmClient::ParseAddress(parsed->positionals()[0], &host, &port);
  if (!address.ok()) return Fail("arm-listen: " + address.message());
  double count = 0, timeout_s = 0;
  if (auto v = parsed->Value("--count"); v && !ParsePositive(*v, &count)) {
    return Fail("arm-listen: --count must be a positive number");
  }
  if (auto v = parsed->Value("--timeout"); v && !ParsePositive(*v, &timeout_s)) {
    return Fail("arm-listen: --timeout must be a positive number of seconds");
  }
  double max_line_bytes = 65536;
  if (auto v = parsed->Value("--max-line-bytes"); v && !ParsePositive(*v, &max_line_bytes)) {
    return Fail("arm-listen: --max-line-bytes must be a positive number");
  }
  std::string poses;
  if (auto file = parsed->Value("--poses")) {
    StatusOr<std::string> lines = PoseLines(*file);
    if (!lines.ok()) return Fail("arm-listen: --poses: " + lines.status().message());
    poses = std::move(*lines);
  }
  auto client = ArmClient::Connect(host, port, parsed->Value("--token").value_or(""));
  if (!client.ok()) return Fail("arm-listen: " + client.status().message());
  if (!poses.empty()) {
    const Status sent = client->Send(poses);
    if (!sent.ok()) return Fail("arm-listen: --poses: " + sent.message());
  }
  client->set_max_line_bytes(size_t(max_line_bytes));
  const bool heartbeats = !parsed->Has("--no-heartbeats");
  using Clock = std::chrono::steady_clock;
  auto last_printed = Clock::now();
  long printed = 0;
  bool stopped = false;  // The last message that was not a heartbeat is a stop.
  while (count <= 0 || printed < long(count)) {
    int wait_ms = 1000;
    if (timeout_s > 0) {
      const double left_s =
          timeout_s - std::chrono::duration<double>(Clock::now() - last_printed).count();
      if (left_s <= 0) {
        return Fail("arm-listen: nothing arrived within " + parsed->Value("--timeout").value() +
                    " s");
      }
      wait_ms = std::max(1, int(left_s * 1000));
    }
    StatusOr<std::string> line = client->ReadLine(wait_ms);
    if (!line.ok()) {
      if (line.status().code() == StatusCode::kOutOfRange) continue;  // Deadline checked above.
      if (line.status().code() == StatusCode::kParseError) {          // Over-long: dropped, go on.
        std::fprintf(stderr, "sightline-cli: arm-listen: %s\n", line.status().message().c_str());
        continue;
      }
      if (count > 0 || !stopped) {
        return Fail("arm-listen: " + line.status().message() +
                    (stopped ? "" : " without a stop line"));
      }
      std::fprintf(stderr, "sightline-cli: arm-listen: %s after a stop line\n",
                   line.status().message().c_str());
      return 0;  // The server closed the stream after telling the arm to stop.
    }
    const bool heartbeat = line->find("\"type\":\"heartbeat\"") != std::string::npos;
    if (!heartbeat) stopped = line->find("\"type\":\"stop\"") != std::string::npos;
    if (!heartbeats && heartbeat) continue;
    std::printf("%s\n", line->c_str());
    std::fflush(stdout);
    ++printed;
    last_printed = Clock::now();
  }
  return 0;
}

}  // namespace sightline::cli
