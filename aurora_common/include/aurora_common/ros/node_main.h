// The whole of a node's main(): init, construct the node class with
// (nh, private_nh), spin; a ConfigError ends the process with code 2 and
// its message (ROS_FATAL). A node that ends as planned (the sim at
// stop_after: endAsPlanned()) or on Ctrl-C / SIGTERM (roslaunch stopping it)
// exits 0; one shut down from outside before that (another node registered
// under its name: a second launch on this master; rosnode kill) exits
// kExitShutDownFromOutside, so a launch never calls such a run complete.
#pragma once

#include <ros/ros.h>

#include <csignal>
#include <cstdio>
#include <memory>

#include "aurora_common/ros/params.h"

namespace aurora_common {

constexpr int kExitShutDownFromOutside = 3;

namespace node_main_detail {
inline volatile std::sig_atomic_t& interrupted() {
  static volatile std::sig_atomic_t flag = 0;
  return flag;
}
inline bool& planned() {
  static bool flag = false;
  return flag;
}
// roscpp's own SIGINT handler does just this, without the flag.
inline void onSignal(int) {
  interrupted() = 1;
  ros::requestShutdown();
}
}  // namespace node_main_detail

// The node ends itself: its run is complete (the sim at stop_after).
inline void endAsPlanned() {
  node_main_detail::planned() = true;
  ros::requestShutdown();
}

// A node whose class its parameters choose (a vehicle's simulator, a law's
// controller): Choose::make(nh, private_nh) builds it; this keeps it alive.
template <class Choose>
class ChosenNode {
 public:
  ChosenNode(ros::NodeHandle nh, ros::NodeHandle private_nh) : node_(Choose::make(nh, private_nh)) {}

 private:
  std::shared_ptr<void> node_;
};

template <class Node>
int runNode(int argc, char** argv, const char* name) {
  try {
    ros::init(argc, argv, name, ros::init_options::NoSigintHandler);
  } catch (const ros::InvalidNameException& e) {
    // e.g. ns:="my drone": one line naming the fix, not an uncaught abort.
    std::fprintf(stderr, "%s: %s: use letters, digits, '_' and '/' (ns:=my_drone)\n", name, e.what());
    return 2;
  }
  // The handles outlive the node: destroying the last NodeHandle shuts
  // rosconsole down, which would swallow the fatal message below.
  ros::NodeHandle nh, private_nh("~");
  try {
    std::signal(SIGINT, node_main_detail::onSignal);
    std::signal(SIGTERM, node_main_detail::onSignal);
    Node node{nh, private_nh};
    ros::spin();
    if (!node_main_detail::planned() && !node_main_detail::interrupted()) {
      // stderr, not ROS_ERROR: ros::shutdown() has closed rosconsole by now.
      std::fprintf(stderr, "%s: shut down from outside before its run ended (another node registered as %s: a "
                   "second launch on this master? or rosnode kill): exit status %d, the run is not complete\n",
                   name, ros::this_node::getName().c_str(), kExitShutDownFromOutside);
      return kExitShutDownFromOutside;
    }
  } catch (const ConfigError& e) {
    ROS_FATAL("%s: %s", name, e.what());
    return 2;
  } catch (const ros::InvalidNameException& e) {
    ROS_FATAL("%s: %s: use letters, digits, '_' and '/' in names", name, e.what());
    return 2;
  }
  return 0;
}

}  // namespace aurora_common
