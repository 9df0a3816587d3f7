// ROS parameters as a YAML tree, so the node reads its task (and checks its
// keys) with the same ROS-free loader as replay and the sweep.
#pragma once

#include <ros/ros.h>
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

namespace aurora_control {

// Doubles become 17-significant-digit text, which every yaml-cpp reads back
// to the same double (so the ROS loop stays bit-identical to the runner).
YAML::Node yamlFromXmlRpc(XmlRpc::XmlRpcValue& v);

// The parameter `key` of `nh` as YAML (an undefined node when it is not set).
YAML::Node paramAsYaml(const ros::NodeHandle& nh, const std::string& key);

// Refuses any parameter directly under `group` of `nh` (the node's private
// namespace when group is empty) whose name is not in `accepted`, naming it
// and the accepted names. Throws aurora_common::ConfigError.
void refuseUnknownParams(const ros::NodeHandle& nh, const std::string& group,
                         const std::vector<std::string>& accepted, const std::string& hint);

// The YAML files the launch loaded into the node's parameters (~yaml_files,
// a list of paths): roslaunch's loader keeps the last of a duplicated key
// where `flight` reads the files strictly, so each is read again here and a
// key given twice is refused, naming it and both lines
// (aurora_common/yaml_file.h). Throws aurora_common::ConfigError.
void refuseDuplicatedKeysInLoadedFiles(const ros::NodeHandle& pnh);

}  // namespace aurora_control
