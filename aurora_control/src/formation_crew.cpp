// The formation node's crews (formation_crew.h): the two-drone line's, and
// the reader that builds the crew of a formation file as `flight
// --formation` builds its run, by the file's shape (shapes.h; each other
// shape's crew is in its own file: uav_ugv_crew.cpp, triangle_crew.cpp).
#include "aurora_control/formation/formation_crew.h"

#include "aurora_control/formation/shapes.h"
#include "crew_of.h"

namespace aurora_control {

using namespace crew_detail;

std::unique_ptr<FormationCrew> LineShapeEntry::crew(const File& f, const CrewRequest& q) {
  ArdroneLineRun run = formationRun(f, q.line_vehicle);
  const double Ts = q.line_vehicle.Ts;
  requestedDelays(q, 2, Ts, formationTicks(run.reference.duration, Ts), [&](int r) -> FormationDrone<double, aurora_control::ArdroneLawData>& {
    return run.drone[r];
  });
  const LawSettings<ArdroneLawData>& law = f.drones[0].controller;  // the robots' law; gains and models: the run's
  return std::unique_ptr<FormationCrew>(new CrewOf<LineFormation<double>, LawSettings<ArdroneLawData>>(
      run, law, name(), std::string(formationLawName(f.law)) + ", drones: " + lawNameOf(law),
      {f.drones[0].name_space, f.drones[1].name_space}, {q.line_vehicle_file, q.line_vehicle_file},
      formationTicks(run.reference.duration, Ts)));
}

std::unique_ptr<FormationCrew> loadFormationCrew(const CrewRequest& q, const FormationDocument& d) {
  std::unique_ptr<FormationCrew> crew;
  withFormationDocument(d, "", [&](auto e, const auto& file) { crew = decltype(e)::crew(file, q); });
  return crew;
}

std::unique_ptr<FormationCrew> loadFormationCrew(const CrewRequest& q) {
  return loadFormationCrew(q, loadFormationDocument(q.file, q.config_dir));
}

}  // namespace aurora_control
