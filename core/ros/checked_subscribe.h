// Subscriptions whose messages are checked against their definition before roscpp decodes them
// (CheckSerializedMessage): a publisher that sends a CameraInfo claiming 4e9 doubles is refused
// with a message instead of making the subscriber allocate 32 GB. Only core/ros's .cpp files and
// the ROS front ends include this header (it pulls roscpp).
#pragma once

#include <ros/node_handle.h>
#include <ros/subscribe_options.h>
#include <ros/subscription_callback_helper.h>

#include <boost/function.hpp>
#include <boost/make_shared.hpp>
#include <functional>
#include <string>
#include <utility>

#include "core/ros/message_check.h"

namespace sightline {

template <class M>
class CheckedSubscriptionHelper
    : public ros::SubscriptionCallbackHelperT<const boost::shared_ptr<M const>&> {
  using Base = ros::SubscriptionCallbackHelperT<const boost::shared_ptr<M const>&>;

 public:
  // `on_refused` gets "field D declares ..." for every refused message (roscpp's spinner
  // thread); the callback never sees it.
  CheckedSubscriptionHelper(const typename Base::Callback& callback,
                            std::function<void(const std::string&)> on_refused)
      : Base(callback), on_refused_(std::move(on_refused)) {}

  ros::VoidConstPtr deserialize(
      const ros::SubscriptionCallbackHelperDeserializeParams& p) override {
    Status ok =
        CheckSerializedMessage(ros::message_traits::DataType<M>::value(),
                               ros::message_traits::Definition<M>::value(), p.buffer, p.length);
    if (!ok.ok()) {
      if (on_refused_) on_refused_(ok.message());
      return ros::VoidConstPtr();  // roscpp drops a message that did not deserialize.
    }
    return Base::deserialize(p);
  }

 private:
  std::function<void(const std::string&)> on_refused_;
};

// nh.subscribe<M>(topic, queue, callback) with the check in front of roscpp's decoding.
template <class M>
ros::Subscriber SubscribeChecked(ros::NodeHandle& nh, const std::string& topic, uint32_t queue,
                                 boost::function<void(const boost::shared_ptr<M const>&)> callback,
                                 std::function<void(const std::string&)> on_refused) {
  ros::SubscribeOptions options;
  options.template init<M>(topic, queue, callback);
  options.helper =
      boost::make_shared<CheckedSubscriptionHelper<M>>(callback, std::move(on_refused));
  return nh.subscribe(options);
}

}  // namespace sightline
