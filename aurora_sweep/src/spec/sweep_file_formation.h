// A formation sweep's part of a sweep file (docs/formation.md, "Formation
// sweeps"): `formation:` names a formation file, every combination's run;
// its criteria; its links. Called by sweep_file.cpp's parser.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "aurora_control/params/yaml_reader.h"
#include "aurora_sweep/sweep_spec.h"

namespace aurora_sweep {

// sweep.formation = `file` (resolved): the formation's run, its drones' law,
// their delays and the formation's gains as the fixed values; the link
// values NaN (each drone keeps its own link unless the sweep gives one).
// Refuses the keys the formation file gives instead (controller, task,
// link, clamp_commands).
void readSweepFormation(const aurora_control::YamlReader& r, const YAML::Node& sweep, const std::string& file,
                        const std::string& config_dir, SweepSpec& spec);

// sweep.criteria of a formation sweep (FormationCriteria's thresholds).
void readFormationCriteria(const aurora_control::YamlReader& r, const YAML::Node& c,
                           aurora_control::FormationCriteria<double>& cr);

// Each drone's link under the sweep's link values: the loss against the
// burst (each direction's worst case), the history, repeats that draw.
void checkFormationLinks(const aurora_control::YamlReader& r, const SweepSpec& spec);

}  // namespace aurora_sweep
