// Simulated Parrot AR.Drone 2.0.
#include "ardrone_sim_node.h"
#include "aurora_common/ros/node_main.h"

int main(int argc, char** argv) {
  return aurora_common::runNode<aurora_sim::ArdroneSimNode>(argc, argv, "ardrone_sim");
}
