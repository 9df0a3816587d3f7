// The registry test's shape's crew for the formation node (formation_crew.h):
// its three test_quads in their file's namespaces, each its delay (the
// node's delay_1 .. delay_3; 0 unless given), as the shipped shapes' crews
// are built (aurora_control/src/crew_of.h).
#include "three_abreast/three_abreast_entry.h"
#include "crew_of.h"

namespace registry {

std::unique_ptr<aurora_control::FormationCrew> ThreeAbreastEntry::crew(const File& file,
                                                                       const aurora_control::CrewRequest& q) {
  using Settings = aurora_control::LawSettings<TestQuadPd>;
  ThreeAbreastRun run = file.run;
  aurora_control::crew_detail::requestedDelays(
      q, 3, run.drone[0].plant.Ts, file.ticks,
      [&](int r) -> aurora_control::FormationDrone<double, TestQuadPd>& { return run.drone[r]; });
  return std::unique_ptr<aurora_control::FormationCrew>(new aurora_control::crew_detail::CrewOf<Shape, Settings>(
      run, file.law, name(), "inverse kinematics, robots: test_quad_pd",
      {file.name_space[0], file.name_space[1], file.name_space[2]},
      {file.vehicle_file, file.vehicle_file, file.vehicle_file}, file.ticks));
}

}  // namespace registry
