#include "driver_command_channel.h"

#include <std_msgs/Empty.h>

#include <cstdio>

namespace aurora_control {

DriverCommandChannel::DriverCommandChannel(ros::NodeHandle& nh, const std::string& topic,
                                           const std::string& what, const DeliveryPolicy& policy)
    : what_(what), command_(policy) {
  pub_ = nh.advertise<std_msgs::Empty>(topic, 1);
}

void DriverCommandChannel::request(double now, double reference) {
  command_.request(now, reference);
  said_waiting_ = false;
}

void DriverCommandChannel::service(double now, bool shown) {
  if (!command_.pending()) return;
  // Counted on the publisher's side: a connected subscriber link receives
  // what is published from now on; before it, a publish is dropped.
  const bool listening = pub_.getNumSubscribers() > 0;
  if (!listening && command_.attempts() == 0 && !said_waiting_) {
    ROS_WARN("controller: %s held until the driver subscribes to %s", what_.c_str(),
             pub_.getTopic().c_str());
    said_waiting_ = true;
  }
  const Delivery before = command_.state();
  const bool sent = command_.update(now, listening, shown);
  if (sent) pub_.publish(std_msgs::Empty());
  logTransition(before, sent, now);
}

void DriverCommandChannel::logTransition(Delivery before, bool sent, double now) {
  const int n = command_.attempts();
  const DeliveryPolicy& p = command_.policy();
  const char* what = what_.c_str();
  switch (command_.state()) {
    case Delivery::kSending:
      if (before != Delivery::kSending) {
        ROS_INFO("controller: %s sent on %s%s", what, pub_.getTopic().c_str(),
                 said_waiting_ ? " (the driver subscribed)" : "");
      } else if (sent && n == 2) {
        char limit[48] = "";
        if (p.timeout > 0.0) std::snprintf(limit, sizeof limit, ", for %g s at most", p.timeout);
        ROS_WARN("controller: %s not shown by the state %.1f s after it was sent: re-sending "
                 "every %g s until it is%s", what, now - command_.firstAttemptAt(), p.resend_period,
                 limit);
      }
      break;
    case Delivery::kShown:
      if (before != Delivery::kShown) {
        ROS_INFO("controller: %s shown by the state after %d attempt%s", what, n, n == 1 ? "" : "s");
      }
      break;
    case Delivery::kTimedOut:
      if (before != Delivery::kTimedOut) {
        ROS_WARN("controller: %s not shown by the state within %g s of the first attempt: gave up "
                 "after %d attempts (no fresh state, or the driver does not act: check the drone)",
                 what, p.timeout, n);
      }
      break;
    default:
      break;
  }
}

TakeoffLand::TakeoffLand(ros::NodeHandle& nh, const std::string& takeoff_topic, const std::string& land_topic,
                         const std::string& who, const SafetyConfig& safety)
    : safety_(safety) {
  DeliveryPolicy until_shown;
  until_shown.resend_period = safety.command_resend_period;
  DeliveryPolicy land_policy = until_shown;
  land_policy.timeout = safety.land_resend_timeout;
  const std::string prefix = who.empty() ? "" : who + " ";
  takeoff_ = DriverCommandChannel(nh, takeoff_topic, prefix + "take-off", until_shown);
  land_ = DriverCommandChannel(nh, land_topic, prefix + "land", land_policy);
}

void TakeoffLand::takeoff(double now, double z) {
  land_.cancel();
  takeoff_.request(now, z);
}

void TakeoffLand::land(double now) {
  takeoff_.cancel();
  land_.request(now);
}

void TakeoffLand::service(double now, const double* fresh_X) {
  takeoff_.service(now, fresh_X && climbShown(fresh_X, takeoff_.command().reference(), safety_.takeoff_rise));
  land_.service(now, fresh_X && descentShown(fresh_X, safety_.descent_speed, safety_.landed_altitude));
}

}  // namespace aurora_control
