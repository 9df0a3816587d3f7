// Delay-study controller node.
#include "aurora_common/ros/node_main.h"
#include "controller_node.h"

int main(int argc, char** argv) {
  return aurora_common::runNode<aurora_control::ControllerNode>(argc, argv, "controller");
}
