// A formation file loaded once (docs/formation.md, "Formation files"): its
// path, the config folder its relative paths are looked up in, its root and
// its `formation.shape`, which chooses the shape's reader (shapes.h). Every
// entry point reads a formation file through one document, so the file is
// parsed once however many readers look at it. ROS-free.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "aurora_common/yaml_file.h"
#include "aurora_control/params/yaml_reader.h"

namespace aurora_control {

struct FormationDocument {
  std::string path, config_dir;
  YAML::Node root;
  std::string shape;  // formation.shape ("" when the file gives none)
};

inline FormationDocument loadFormationDocument(const std::string& path, const std::string& config_dir) {
  FormationDocument d{path, config_dir, aurora_common::loadYamlFile("formation file", path), ""};
  d.shape = aurora_common::yamlWord(d.root, "formation", "shape");
  return d;
}

// The reader of a document's refusals: "formation file 'PATH': ...".
inline YamlReader formationReader(const FormationDocument& d) { return YamlReader("formation file '" + d.path + "': "); }

namespace formation_detail {

// The document's 'formation:' mapping, its keys among `accepted`.
inline YAML::Node formationSection(const YamlReader& r, const FormationDocument& d,
                                   const std::vector<std::string>& accepted) {
  r.onlyKeys(d.root, "", {"formation"});
  std::string keys;
  for (const std::string& k : accepted) keys += (keys.empty() ? "" : ", ") + k;
  const YAML::Node n = r.require(d.root, "", "formation", keys);
  r.onlyKeys(n, "formation", accepted);
  return n;
}

}  // namespace formation_detail

// What the entry points that fly a shape declare in its entry (shapes.h)
// and define in their own files: flight's, the formation node's.
struct FormationFlightOptions;
struct FlightTable;
struct ShapedFlight;
class FormationCrew;
struct CrewRequest;

}  // namespace aurora_control
