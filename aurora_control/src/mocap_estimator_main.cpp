// Motion-capture state estimator node.
#include "aurora_sim/ros/node_main.h"
#include "mocap_estimator_node.h"

int main(int argc, char** argv) {
  return aurora_sim::runNode<aurora_control::MocapEstimatorNode>(argc, argv, "mocap_estimator");
}
