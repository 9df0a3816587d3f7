// The UAV-UGV line's crew for the formation node (formation_crew.h): its entry's
// crew (shapes.h), from its file's setup.
#include "aurora_control/formation/uav_ugv/uav_ugv_yaml.h"
#include "../crew_of.h"

namespace aurora_control {

using namespace crew_detail;

// The UAV-UGV line's robots: robot 1 the ground robot, robot 2 the drone,
// in their file's namespaces (UavUgvLineSetup's unless it names others).
std::unique_ptr<FormationCrew> UavUgvShapeEntry::crew(const File& setup, const CrewRequest& q) {
  UavUgvRun run = uavUgvRun(setup);
  requestedDelays(q, 2, setup.tick, setup.ticks(), [&](int r) -> FormationDrone<double, UavUgvRobots::Data>& {
    return run.drone[r];
  });
  const std::string laws = std::string("without integration; ") + UavUgvGroundLaw::name() + " and " +
                           UavUgvDroneLaw::name();
  return std::unique_ptr<FormationCrew>(new CrewOf<UavUgvShape, LawSettings<UavUgvRobots>>(
      run, LawSettings<UavUgvRobots>(), name(), laws,
      {setup.name_space[0], setup.name_space[1]}, {setup.vehicle_file[0], setup.vehicle_file[1]}, setup.ticks()));
}

}  // namespace aurora_control
