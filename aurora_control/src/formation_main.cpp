// The formation node: the drones of a formation file, flown together.
#include "aurora_common/ros/node_main.h"
#include "formation_node.h"

int main(int argc, char** argv) {
  return aurora_common::runNode<aurora_control::FormationNode>(argc, argv, "formation_controller");
}
