// The nodes that publish a topic, as the master knows them (its system
// state). A sim that owns /clock checks with it that no other node does
// (aurora_sim's sim_node.cpp).
#pragma once

#include <ros/master.h>
#include <ros/this_node.h>

#include <string>
#include <vector>

namespace aurora_common {

// Empty when the master does not answer: the caller's check is then skipped,
// never failed on a guess.
inline std::vector<std::string> publishersOf(const std::string& topic) {
  XmlRpc::XmlRpcValue args, result, state;
  args[0] = ros::this_node::getName();
  std::vector<std::string> nodes;
  if (!ros::master::execute("getSystemState", args, result, state, true)) return nodes;
  XmlRpc::XmlRpcValue& publishers = state[0];  // [[topic, [node, ...]], ...]
  for (int i = 0; i < publishers.size(); ++i) {
    if (static_cast<std::string>(publishers[i][0]) != topic) continue;
    for (int j = 0; j < publishers[i][1].size(); ++j) nodes.push_back(static_cast<std::string>(publishers[i][1][j]));
  }
  return nodes;
}

}  // namespace aurora_common
