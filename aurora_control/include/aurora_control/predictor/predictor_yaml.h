// A controller file's `predictor:` block (docs/predictor.md,
// "Configuration"), the same for every law's file:
//   predictor:
//     form: resimulate          # resimulate | smith | off
//     model: ../vehicles/ardrone2.yaml   # relative to the controller file's folder
//     horizon: 0.0              # [s] further latency the loop cannot see (real robots)
// Refused naming the key: an unknown form, a model of another vehicle than
// the law flies, a horizon below 0 or beyond the history.
#pragma once

#include <cmath>
#include <string>

#include "aurora_control/params/limits.h"
#include "aurora_control/params/yaml_reader.h"
#include "aurora_control/predictor/state_predictor.h"
#include "aurora_common/yaml_file.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"

namespace aurora_control {

struct PredictorFile {
  PredictorForm form = PredictorForm::kOff;
  std::string model;     // the model's vehicle file (a path)
  double horizon = 0.0;  // [s]
  std::string file;      // the controller file it came from (for refusals)
};

// The forms' names, as a refusal lists them.
inline std::string acceptedPredictorForms() { return "accepted 'resimulate', 'smith', 'off'"; }

// The form of a name; false for an unknown one.
inline bool predictorFormOf(const std::string& name, PredictorForm& form) {
  for (PredictorForm f : {PredictorForm::kResimulate, PredictorForm::kSmith, PredictorForm::kOff}) {
    if (name == predictorFormName(f)) return form = f, true;
  }
  return false;
}

inline PredictorForm predictorFormNamed(const YamlReader& r, const YAML::Node& n, const std::string& key) {
  const std::string form = r.text(n, key);
  PredictorForm f = PredictorForm::kOff;
  if (!predictorFormOf(form, f)) r.fail(key, "= '" + form + "' is unknown: " + acceptedPredictorForms());
  return f;
}

// A predictor block `n` (at `key`, read by `r`: a file's or the node's
// parameters), a relative model taken from `folder` (none: refused, the
// node was not told its controller file); `file` names it in later
// refusals.
inline PredictorFile readPredictorBlock(const YamlReader& r, const YAML::Node& n, const std::string& key,
                                        const std::string& folder, const std::string& file) {
  PredictorFile p;
  p.file = file;
  r.onlyKeys(n, key, {"form", "model", "horizon"});
  p.form = predictorFormNamed(r, r.require(n, key, "form", "resimulate, smith, off"), r.key(key, "form"));
  if (p.form == PredictorForm::kOff) return p;
  const std::string model_key = r.key(key, "model");
  p.model = r.text(r.require(n, key, "model", "a vehicle file, e.g. ../vehicles/NAME.yaml"), model_key);
  if (!p.model.empty() && p.model[0] != '/') {
    if (folder.empty()) {
      r.fail(model_key, "= '" + p.model + "' is relative, but no ~controller_file says to what: give an absolute "
                        "path, or ~controller_file");
    }
    p.model = folder + "/" + p.model;
  }
  if (n["horizon"]) p.horizon = r.numberIn(n["horizon"], r.key(key, "horizon"), 0.0, 1e9, "s");
  return p;
}

// The block of the controller file at `path` (off when it has none).
inline PredictorFile readControllerPredictor(const std::string& path) {
  const YAML::Node root = loadYamlFile("controller file", path);
  if (!root["predictor"]) return PredictorFile{PredictorForm::kOff, "", 0.0, path};
  return readPredictorBlock(YamlReader("controller file '" + path + "': "), root["predictor"], "predictor",
                            aurora_common::folderOf(path), path);
}

// The predictor of a run of law `Law` with sample time Ts, a command
// delay `command_delay` [samples] and a history of `history` samples:
// its model loaded as the law's vehicle, its horizon in samples.
template <class Law>
PredictorRun<typename Law::Vehicle, double> predictorRun(const PredictorFile& f, double Ts, long command_delay,
                                                         long history, bool clamp) {
  PredictorRun<typename Law::Vehicle, double> p;
  p.form = f.form;
  if (!p.on()) return p;
  p.model = aurora_sim::loadVehicleFile<typename Law::Vehicle>(
      f.model, "the predictor of controller file '" + f.file + "' (its 'predictor.model'), beside the law '" +
                   std::string(Law::name()) + "'");
  const long horizon = std::lround(f.horizon / Ts);
  if (history + command_delay + horizon > kMaxDelaySamples) {
    throw ConfigError("controller file '" + f.file + "': 'predictor.horizon' = " + YamlReader::fmt(f.horizon) +
                      " s (" + std::to_string(horizon) + " samples) is refused: with the history of " +
                      std::to_string(history) + " and the command delay of " + std::to_string(command_delay) +
                      " samples it reaches beyond the " + std::to_string(kMaxDelaySamples) +
                      " samples the predictor keeps; give at most " +
                      YamlReader::fmt(double(kMaxDelaySamples - history - command_delay) * Ts) + " s");
  }
  p.path = CommandPath{command_delay, horizon, clamp};
  return p;
}

}  // namespace aurora_control
