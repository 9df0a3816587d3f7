// The two-drone line's crew for the formation node (formation_crew.h): its
// entry's crew (shapes.h), from its file's run and the node's drones'
// vehicle file (the line's file names none).
#include "aurora_control/formation/line/line_yaml.h"
#include "../crew_of.h"

namespace aurora_control {

using namespace crew_detail;

std::unique_ptr<FormationCrew> LineShapeEntry::crew(const File& f, const CrewRequest& q) {
  const auto& vehicle = q.vehicle.get<UnnamedVehicle>(name());
  LineRun run = formationRun(f, vehicle);
  const double Ts = vehicle.Ts;
  const long ticks = formationTicks(run.reference.duration, Ts);
  requestedDelays(q, 2, Ts, ticks, [&](int r) -> FormationDrone<double, LineDrones>& { return run.drone[r]; });
  const LawSettings<LineDrones>& law = f.drones[0].controller;  // the robots' law; gains and models: the run's
  return std::unique_ptr<FormationCrew>(new CrewOf<LineFormation<double>, LawSettings<LineDrones>>(
      run, law, name(), std::string(formationLawName(f.law)) + ", drones: " + lawNameOf(law),
      {f.drones[0].name_space, f.drones[1].name_space}, {q.vehicle.file(), q.vehicle.file()}, ticks));
}

}  // namespace aurora_control
