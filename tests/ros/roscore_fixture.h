// A private ROS master for tests: `roscore -p PORT` on a free loopback port with ROS_HOME and
// ROS_LOG_DIR in a temporary folder, waited for until it answers, and stopped by pid (with its
// children rosmaster and rosout, killed if roscore is slow to). No test depends on a global master.
#pragma once

#include <sys/types.h>

#include <string>

namespace sightline::testing {

class RoscoreFixture {
 public:
  RoscoreFixture() = default;
  ~RoscoreFixture() { Stop(); }
  RoscoreFixture(const RoscoreFixture&) = delete;
  RoscoreFixture& operator=(const RoscoreFixture&) = delete;

  // Starts the master and waits (up to `timeout_s`) until it answers getPid. Returns "" or why
  // it failed (with the end of roscore's log). `port` 0 takes a free one; a given port restarts a
  // master where a stopped one was (its clients see the same URI come back).
  std::string Start(double timeout_s = 60, int port = 0);
  // Stops roscore (SIGINT; after 10 s SIGKILL to it and to its rosmaster and rosout, which live
  // in sessions of their own), reaps it and waits until the port no longer answers. Safe to call
  // twice.
  void Stop();

  int port() const { return port_; }
  pid_t pid() const { return pid_; }  // roscore's; -1 when stopped.
  std::string uri() const;
  const std::string& folder() const { return folder_; }
  // "env ROS_MASTER_URI=... ROS_HOME=... ROS_LOG_DIR=... ROS_IP=127.0.0.1 " to put before a
  // command (ChildProcess runs it with exec).
  std::string Env() const;
  // Sets those variables in this process (before ros::init).
  void ExportEnv() const;

 private:
  int port_ = 0;
  pid_t pid_ = -1;
  std::string folder_;
};

// Whether the master at 127.0.0.1:port answers getPid (XML-RPC), without ros::init.
bool MasterAnswers(int port);
// A TCP port on 127.0.0.1 that was free a moment ago.
int FreeLoopbackPort();

// A child process (`exec COMMAND` through /bin/sh, so its pid is the command's) with its output
// in `log_path`, in its own process group.
class ChildProcess {
 public:
  ChildProcess() = default;
  ~ChildProcess() { Kill(); }
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  bool Start(const std::string& command, const std::string& log_path);
  // Waits up to `timeout_s` for the exit; the exit code, or -1 on timeout / a signal.
  int Wait(double timeout_s);
  // SIGINT to the command (Ctrl-C).
  void Interrupt();
  // SIGKILL to the process group, then reaps.
  void Kill();
  pid_t pid() const { return pid_; }
  // Hands the process over to the caller: it is no longer killed here.
  pid_t Release() {
    const pid_t pid = pid_;
    pid_ = -1;
    return pid;
  }

 private:
  pid_t pid_ = -1;
};

}  // namespace sightline::testing
