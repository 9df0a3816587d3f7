// Delay-study controller node.
#include "aurora_sim/ros/node_main.h"
#include "controller_node.h"

int main(int argc, char** argv) {
  return aurora_sim::runNode<aurora_control::ControllerNode>(argc, argv, "controller");
}
