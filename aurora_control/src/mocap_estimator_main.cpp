// Motion-capture state estimator node.
#include "aurora_common/ros/node_main.h"
#include "mocap_estimator_node.h"

int main(int argc, char** argv) {
  return aurora_common::runNode<aurora_control::MocapEstimatorNode>(argc, argv, "mocap_estimator");
}
