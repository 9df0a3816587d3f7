// The triangle's crew for the formation node (formation_crew.h): its entry's
// crew (shapes.h), from its file's setup.
#include "aurora_control/formation/triangle/triangle_yaml.h"
#include "../crew_of.h"

namespace aurora_control {

using namespace crew_detail;

// The triangle's three drones (robots.namespaces; TriangleSetup's
// unless the file names others); kinematic robots
// (the file names no vehicle) have no vehicle to simulate or drive.
std::unique_ptr<FormationCrew> TriangleShapeEntry::crew(const File& setup, const CrewRequest& q) {
  if (setup.kinematic) {
    throw ConfigError("formation file '" + q.file + "': formation.robots names no vehicle: its robots are kinematic "
                      "(each at its reference), which only `flight --formation` flies; the formation node flies "
                      "vehicles: give " + flyingTriangleKeys());
  }
  TriangleRun<TriangleDroneLaw> run = triangleRun<TriangleDroneLaw>(setup);
  const long steps = triangleSteps(setup);
  requestedDelays(q, 3, setup.drone.Ts, steps,
                  [&](int r) -> FormationDrone<double, TriangleDrones>& { return run.drone[r]; });
  return std::unique_ptr<FormationCrew>(new CrewOf<Triangle, LawSettings<TriangleDrones>>(
      run, LawSettings<TriangleDrones>::flying<TriangleDroneLaw>(), name(),
      std::string(triangleLawName(setup.law)) + ", drones: underactuated", {setup.name_space[0], setup.name_space[1], setup.name_space[2]},
      {setup.drone_file, setup.drone_file, setup.drone_file}, steps));
}

}  // namespace aurora_control
