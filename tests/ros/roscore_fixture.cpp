#include "tests/ros/roscore_fixture.h"

#include <XmlRpcClient.h>
#include <XmlRpcValue.h>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>
#include <vector>

#include "tests/support/test_data.h"

namespace sightline::testing {

namespace {

double NowS() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string Tail(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string all = text.str();
  return all.size() > 2000 ? all.substr(all.size() - 2000) : all;
}

// Reaps `pid` if it exited; true when it is gone.
bool Reaped(pid_t pid, int* status) { return waitpid(pid, status, WNOHANG) == pid; }

// Every process below `root` (children, their children, ...), read from /proc/PID/stat.
// roslaunch starts rosmaster and rosout in sessions of their own (setsid), so killing roscore's
// process group does not reach them.
std::vector<pid_t> Descendants(pid_t root) {
  std::vector<std::pair<pid_t, pid_t>> parent_of;  // (pid, ppid)
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || !std::all_of(name.begin(), name.end(), ::isdigit)) continue;
    std::ifstream in(entry.path() / "stat");
    std::string stat;
    if (!std::getline(in, stat)) continue;
    // "pid (comm) state ppid ...": comm may hold spaces and parentheses; the last ')' ends it.
    const size_t close = stat.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(stat.substr(close + 1));
    std::string state;
    pid_t ppid = 0;
    if (rest >> state >> ppid) parent_of.emplace_back(pid_t(std::stoi(name)), ppid);
  }
  std::vector<pid_t> found{root};
  for (size_t i = 0; i < found.size(); ++i) {
    for (const auto& [pid, ppid] : parent_of) {
      if (ppid == found[i]) found.push_back(pid);
    }
  }
  found.erase(found.begin());
  return found;
}

}  // namespace

// A free port below the kernel's ephemeral range: every ROS node binds its XML-RPC and TCPROS
// servers to port 0, and the kernel hands out ephemeral ports, so a master port in that range,
// freed while a test restarts its master, could be taken by another test's node meanwhile.
int FreeLoopbackPort() {
  int ephemeral_low = 32768;
  std::ifstream("/proc/sys/net/ipv4/ip_local_port_range") >> ephemeral_low;
  const int low = 10000, high = std::max(low + 1000, ephemeral_low);
  std::mt19937 random(std::random_device{}());
  std::uniform_int_distribution<int> pick(low, high - 1);
  for (int attempt = 0; attempt < 200; ++attempt) {
    const int port = pick(random);
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    addr.sin_port = htons(static_cast<uint16_t>(port));
    const bool free = bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) == 0;
    close(fd);
    if (free) return port;
  }
  return 0;
}

bool MasterAnswers(int port) {
  XmlRpc::XmlRpcClient client("127.0.0.1", port, "/");
  XmlRpc::XmlRpcValue args, result;
  args[0] = std::string("/roscore_fixture");
  const bool ok = client.execute("getPid", args, result) && !client.isFault() &&
                  result.getType() == XmlRpc::XmlRpcValue::TypeArray && result.size() >= 1 &&
                  static_cast<int>(result[0]) == 1;
  client.close();
  return ok;
}

std::string RoscoreFixture::uri() const { return "http://127.0.0.1:" + std::to_string(port_); }

std::string RoscoreFixture::Env() const {
  return "env ROS_MASTER_URI=" + uri() + " ROS_HOME=" + folder_ + "/home ROS_LOG_DIR=" + folder_ +
         "/log ROS_IP=127.0.0.1 ";
}

void RoscoreFixture::ExportEnv() const {
  setenv("ROS_MASTER_URI", uri().c_str(), 1);
  setenv("ROS_HOME", (folder_ + "/home").c_str(), 1);
  setenv("ROS_LOG_DIR", (folder_ + "/log").c_str(), 1);
  setenv("ROS_IP", "127.0.0.1", 1);
}

std::string RoscoreFixture::Start(double timeout_s, int port) {
  port_ = port != 0 ? port : FreeLoopbackPort();
  if (port_ == 0) return "no free loopback port";
  if (MasterAnswers(port_)) {
    return "a master already answers on port " + std::to_string(port_) + " (not this test's)";
  }
  folder_ = TempDir("roscore_" + std::to_string(port_));
  std::filesystem::create_directories(folder_ + "/home");
  std::filesystem::create_directories(folder_ + "/log");
  const std::string log = folder_ + "/roscore.log";
  ChildProcess child;
  if (!child.Start(Env() + "roscore -p " + std::to_string(port_), log)) {
    return "cannot start roscore";
  }
  pid_ = child.Release();
  const double end = NowS() + timeout_s;
  int status = 0;
  while (NowS() < end) {
    if (Reaped(pid_, &status)) {
      pid_ = -1;
      return "roscore exited at start: " + Tail(log);
    }
    if (MasterAnswers(port_)) return "";
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  Stop();
  return "roscore did not answer within the timeout: " + Tail(log);
}

void RoscoreFixture::Stop() {
  if (pid_ <= 0) return;
  const std::vector<pid_t> children = Descendants(pid_);  // rosmaster, rosout.
  kill(-pid_, SIGINT);  // roscore shuts rosout and rosmaster down on SIGINT.
  int status = 0;
  const double end = NowS() + 10;
  bool reaped = false;
  while (NowS() < end && !(reaped = Reaped(pid_, &status))) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (!reaped) {
    // roscore did not finish its shutdown in time: killed alone, it would leave the master
    // answering. Its children go first, while they are still its own (live or zombie, their
    // pids are not reused before roscore reaps them), then roscore.
    for (const pid_t child : children) kill(child, SIGKILL);
    kill(-pid_, SIGKILL);
    waitpid(pid_, &status, 0);
  }
  pid_ = -1;
  const double gone = NowS() + 5;
  while (NowS() < gone && MasterAnswers(port_)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

bool ChildProcess::Start(const std::string& command, const std::string& log_path) {
  const pid_t pid = fork();
  if (pid < 0) return false;
  if (pid == 0) {
    setpgid(0, 0);
    // exec: the child's pid is the command's (signals reach it, not a shell).
    const std::string line = "exec " + command + " > '" + log_path + "' 2>&1";
    execl("/bin/sh", "sh", "-c", line.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  setpgid(pid, pid);
  pid_ = pid;
  return true;
}

int ChildProcess::Wait(double timeout_s) {
  if (pid_ <= 0) return -1;
  const double end = NowS() + timeout_s;
  int status = 0;
  while (NowS() < end) {
    if (Reaped(pid_, &status)) {
      pid_ = -1;
      return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return -1;
}

void ChildProcess::Interrupt() {
  if (pid_ > 0) kill(pid_, SIGINT);
}

void ChildProcess::Kill() {
  if (pid_ <= 0) return;
  kill(-pid_, SIGKILL);
  int status = 0;
  waitpid(pid_, &status, 0);
  pid_ = -1;
}

}  // namespace sightline::testing
