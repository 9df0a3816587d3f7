// The simulated robot of the vehicle file loaded under `vehicle` (an
// AR.Drone 2.0, a Bebop 2 or a Pioneer P3-DX: its `type`).
#include "sim_node.h"
#include "aurora_common/ros/node_main.h"

int main(int argc, char** argv) {
  return aurora_common::runNode<aurora_sim::VehicleSimNode>(argc, argv, "vehicle_sim");
}
