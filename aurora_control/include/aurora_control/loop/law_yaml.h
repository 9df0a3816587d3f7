// The controller files' schema (config/controllers/*.yaml, 'controller:'),
// read strictly for the node, replay, a flight and a formation's robots:
// the law's name (a law of the list, other_laws.h), all of its gains (none
// may be missing), nothing else. A law whose every gain is one of its sweep
// rows (law_gain_rows.h, gainAt: the AR.Drone's two) is read by its rows,
// each in its row's range:
//   pd_saturated:   kp, kd in [kPdGainMin, kPdGainMax] = [0, 10] (pd_controller.h)
//   underactuated:  k1_x, k2_x, ..., k1_psi, k2_psi in [0.001, 100] (underactuated_law.h)
// any other law by the reader its controller-file header gives
// (readLawGains, found by its gains' type; the law list includes it).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "aurora_control/law/other_laws.h"
#include "aurora_control/loop/delayed_controller.h"
#include "aurora_control/params/yaml_reader.h"

namespace aurora_control {

// The name under 'controller:' of a controller file ("" when it has none):
// what chooses the vehicle a flight flies.
inline std::string controllerFileName(const std::string& path) {
  return aurora_common::yamlFileWord("controller file", path, "controller", "name");
}

namespace law_yaml_detail {
template <class Law>
constexpr bool rows(decltype(&Law::gainAt)) {
  return true;
}
template <class Law>
constexpr bool rows(...) {
  return false;
}

template <class Law, class Gains>
std::vector<std::pair<std::string, double*>> slots(std::true_type /*rows*/, Gains& g) {
  std::vector<std::pair<std::string, double*>> out;
  for (int i = 0; i < Law::kGainCount; ++i) out.emplace_back(Law::gainRow(i).name, &Law::gainAt(g, i));
  return out;
}
template <class Law, class Gains>
std::vector<std::pair<std::string, double*>> slots(std::false_type, Gains& g) {
  return gainSlots(g);
}
}  // namespace law_yaml_detail

// Whether every gain of Law is one of its sweep rows (it declares gainAt):
// its controller file is its rows, and the controller node changes them
// live (live_settings.h).
template <class Law>
constexpr bool gainsAreRows() {
  return law_yaml_detail::rows<Law>(nullptr);
}

// Every gain of law Law in g by name, in its file's order: its rows, or its
// gain lists (gainSlots). The node's Control.gain_names and log; replay
// reads them back.
template <class Law, class Gains>
std::vector<std::pair<std::string, double*>> lawGainSlots(Law, Gains& g) {
  return law_yaml_detail::slots<Law>(std::integral_constant<bool, gainsAreRows<Law>()>(), g);
}

// Law's gain named `name` in g (nullptr: the law has none of that name).
template <class Law, class Gains>
double* gainNamed(Law law, Gains& g, const std::string& name) {
  for (const auto& slot : lawGainSlots(law, g)) {
    if (slot.first == name) return slot.second;
  }
  return nullptr;
}

// A gain's accepted range as a refusal gives it ("a number in [0, 10]").
inline std::string gainRangeText(const GainRow& row) {
  return "a number in [" + YamlReader::fmt(row.min) + ", " + YamlReader::fmt(row.max) + "]";
}

namespace law_yaml_detail {
template <class Law, class Gains>
void readGains(std::true_type /*rows*/, const YamlReader& r, const YAML::Node& c, const std::string& key, Gains& g,
               double) {
  std::vector<std::string> accepted{"name"};
  for (int i = 0; i < Law::kGainCount; ++i) accepted.push_back(Law::gainRow(i).name);
  r.onlyKeys(c, key, accepted);
  for (int i = 0; i < Law::kGainCount; ++i) {
    const GainRow row = Law::gainRow(i);
    const YAML::Node v = r.require(c, key, row.name, gainRangeText(row));
    Law::gainAt(g, i) = r.numberIn(v, r.key(key, row.name), row.min, row.max, "");
  }
}
template <class Law, class Gains>
void readGains(std::false_type, const YamlReader& r, const YAML::Node& c, const std::string& key, Gains& g,
               double Ts) {
  readLawGains(r, c, key, g, Ts);
}
}  // namespace law_yaml_detail

// Law's gains from the mapping at `key` (its name already read), for a
// vehicle of sample time Ts (the compensator's rate must divide it).
template <class Law, class Gains>
void readGainsOf(Law, const YamlReader& r, const YAML::Node& c, const std::string& key, Gains& g, double Ts) {
  law_yaml_detail::readGains<Law>(std::integral_constant<bool, gainsAreRows<Law>()>(), r, c, key, g, Ts);
}

// The name of the law the mapping at `key` names; refused when the mapping
// is missing or names no law of the list.
inline std::string lawNameIn(const YamlReader& r, const YAML::Node& c, const std::string& key) {
  if (!c || !c.IsMap()) {
    r.fail(key, std::string("is missing or not a mapping: load a controller file such as config/controllers/") +
                    aurora_common::FirstType<KnownLaws>::type::name() + ".yaml");
  }
  const std::string name = r.text(r.require(c, key, "name", knownLawNames()), r.key(key, "name"));
  if (!isKnownLawName(name)) {
    r.fail(r.key(key, "name"), "= '" + name + "' is unknown: accepted controllers: " + knownLawNames() +
                                   " (by vehicle: " + lawVehicleNames() + ")");
  }
  return name;
}

// The mapping at `key` into `set`: the law it names (one of Data's family)
// and its gains (set.Ts already set: the compensator's rate must divide
// the vehicle's).
template <class Data>
void readLawMapping(const YamlReader& r, const YAML::Node& c, const std::string& key, LawSettings<Data>& set) {
  const std::string name = lawNameIn(r, c, key);
  set.law = lawIndexOf<Data>(name);
  if (set.law < 0) {
    r.fail(r.key(key, "name"), "= '" + name + "' is refused here: it flies the " + vehicleOfLaw(name) +
                                   "; accepted: " + aurora_common::entryNames([](auto&& f) { forEachLawOf<Data>(f); }) +
                                   " (the " + Data::Vehicle::name() + "'s)");
  }
  set.withLawType([&](auto law) { readGainsOf(law, r, c, key, set.gains, set.Ts); });
}

// Law's controller file (controller.name is Law::name()) for a vehicle of
// sample time Ts: its gains by the law's reader, its 'clamp_commands'
// (where the law does not saturate its own commands: lawSaturation) and a
// 'predictor:' (predictor_yaml.h). A flight's (flight_setup.h).
template <class Law>
struct LawFile {
  typename Law::template Gains<double> gains = presetGains<typename Law::Data>();
  bool clamp = true;     // clamp_commands, true when not given
  YAML::Node mapping;    // its 'controller:' (a rate of its own: mappingRate)
};

template <class Law>
LawFile<Law> readLawFile(const std::string& path, double Ts) {
  const YAML::Node root = loadYamlFile("controller file", path);
  const YamlReader r("controller file '" + path + "': ");
  if (lawSaturation<Law>()) r.onlyKeys(root, "", {"controller", "predictor"});
  else r.onlyKeys(root, "", {"controller", "clamp_commands", "predictor"});
  LawFile<Law> f;
  f.mapping = root["controller"];
  readGainsOf(Law(), r, f.mapping, "controller", f.gains, Ts);
  if (root["clamp_commands"]) f.clamp = r.boolean(root["clamp_commands"], "clamp_commands");
  return f;
}

// The law and gains of a controller file (config/controllers/*.yaml) of a
// law of Data's family: its 'controller:'; an optional 'clamp_commands'
// (checked: a formation's robots never clamp) and 'predictor:'
// (predictor_yaml.h). A formation's robots' (formation_file.h, controllerAt).
template <class Data>
LawSettings<Data> readControllerFile(const std::string& path) {
  const YAML::Node root = loadYamlFile("controller file", path);
  const YamlReader r("controller file '" + path + "': ");
  r.onlyKeys(root, "", {"controller", "clamp_commands", "predictor"});
  LawSettings<Data> set;
  readLawMapping(r, root["controller"], "controller", set);
  if (root["clamp_commands"]) r.boolean(root["clamp_commands"], "clamp_commands");
  return set;
}

}  // namespace aurora_control
