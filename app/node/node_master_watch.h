// sightline-node's registrations outlive its master: a thread checks the master every second
// and, when it answers again after it went away (a restarted roscore knows nothing of the node),
// registers the node's publishers and subscriptions anew. Latched topics (map, stop) then reach
// new subscribers again, since the publishers keep their last message.
#pragma once

#include <atomic>
#include <thread>

namespace sightline::node {

// Runs from construction to destruction (ros::init and the node's advertising done before).
class MasterReregistration {
 public:
  MasterReregistration();
  ~MasterReregistration();
  MasterReregistration(const MasterReregistration&) = delete;
  MasterReregistration& operator=(const MasterReregistration&) = delete;

  // How often the node registered anew so far.
  int reregistrations() const { return reregistrations_.load(); }

 private:
  void Run();

  std::atomic<bool> done_{false};
  std::atomic<int> reregistrations_{0};
  std::thread thread_;
};

}  // namespace sightline::node
