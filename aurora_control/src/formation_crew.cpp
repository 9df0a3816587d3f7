// The formation node's crew of a formation file (formation_crew.h), built
// as `flight --formation` builds its run, by the file's shape (shapes.h);
// each shape's crew is in its own folder (line/line_crew.cpp,
// uav_ugv/uav_ugv_crew.cpp, triangle/triangle_crew.cpp).
#include "aurora_control/formation/formation_crew.h"

#include "aurora_control/formation/shapes.h"

namespace aurora_control {

std::unique_ptr<FormationCrew> loadFormationCrew(const CrewRequest& q, const FormationDocument& d) {
  std::unique_ptr<FormationCrew> crew;
  withFormationDocument(d, "", [&](auto e, const auto& file) { crew = decltype(e)::crew(file, q); });
  return crew;
}

std::unique_ptr<FormationCrew> loadFormationCrew(const CrewRequest& q) {
  return loadFormationCrew(q, loadFormationDocument(q.file, q.config_dir));
}

}  // namespace aurora_control
