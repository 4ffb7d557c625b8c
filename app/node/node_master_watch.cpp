// Registering anew: the node's own slave API (getPublications, getSubscriptions) lists what it
// advertised and subscribed with the types; the master gets registerPublisher /
// registerSubscriber for each, and the publishers the master names for a subscription are handed
// to the node's own publisherUpdate, as roscpp does when it subscribes.
#include "app/node/node_master_watch.h"

#include <ros/master.h>
#include <ros/network.h>
#include <ros/this_node.h>
#include <ros/xmlrpc_manager.h>
#include <xmlrpcpp/XmlRpcClient.h>

#include <chrono>
#include <cstdio>
#include <string>

namespace sightline::node {

namespace {

// Calls the node's own slave API; the payload (third element of the answer), or an invalid value.
XmlRpc::XmlRpcValue CallSelf(const std::string& method, XmlRpc::XmlRpcValue& params) {
  std::string host;
  uint32_t port = 0;
  const std::string& uri = ros::XMLRPCManager::instance()->getServerURI();
  if (!ros::network::splitURI(uri, host, port)) return {};
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpc::XmlRpcValue result;
  if (!client.execute(method.c_str(), params, result) ||
      result.getType() != XmlRpc::XmlRpcValue::TypeArray || result.size() < 3) {
    return {};
  }
  return result[2];
}

// [[topic, type], ...] of the node's getPublications / getSubscriptions.
XmlRpc::XmlRpcValue OwnTopics(const char* method) {
  XmlRpc::XmlRpcValue params;
  params[0] = ros::this_node::getName();
  XmlRpc::XmlRpcValue topics = CallSelf(method, params);
  return topics.getType() == XmlRpc::XmlRpcValue::TypeArray ? topics : XmlRpc::XmlRpcValue();
}

// Registers every publication and subscription; false when the master refused one.
bool RegisterAll() {
  const std::string me = ros::this_node::getName();
  const std::string my_uri = ros::XMLRPCManager::instance()->getServerURI();
  bool ok = true;
  for (const char* kind : {"Publisher", "Subscriber"}) {
    const bool subscriber = std::string(kind) == "Subscriber";
    XmlRpc::XmlRpcValue topics = OwnTopics(subscriber ? "getSubscriptions" : "getPublications");
    if (!topics.valid()) continue;
    for (int i = 0; i < topics.size(); ++i) {
      if (topics[i].getType() != XmlRpc::XmlRpcValue::TypeArray || topics[i].size() < 2) continue;
      XmlRpc::XmlRpcValue args, result, payload;
      args[0] = me;
      args[1] = topics[i][0];
      args[2] = topics[i][1];
      args[3] = my_uri;
      if (!ros::master::execute(std::string("register") + kind, args, result, payload, false)) {
        ok = false;
        continue;
      }
      if (subscriber && payload.getType() == XmlRpc::XmlRpcValue::TypeArray) {
        XmlRpc::XmlRpcValue update;
        update[0] = me;
        update[1] = topics[i][0];
        update[2] = payload;
        CallSelf("publisherUpdate", update);
      }
    }
  }
  return ok;
}

}  // namespace

MasterReregistration::MasterReregistration() : thread_([this] { Run(); }) {}

MasterReregistration::~MasterReregistration() {
  done_.store(true);
  thread_.join();
}

void MasterReregistration::Run() {
  bool was_up = true;
  auto next = std::chrono::steady_clock::now();
  while (!done_.load()) {
    if (std::chrono::steady_clock::now() < next) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      continue;
    }
    next += std::chrono::seconds(1);
    bool up = ros::master::check();
    if (up && !was_up) {
      // A master that went away again during this is met by the next round.
      if (RegisterAll()) {
        reregistrations_.fetch_add(1);
        std::fprintf(stderr,
                     "sightline-node: the ROS master at %s answers again; registered anew\n",
                     ros::master::getURI().c_str());
      } else {
        up = false;
      }
    }
    was_up = up;
  }
}

}  // namespace sightline::node
