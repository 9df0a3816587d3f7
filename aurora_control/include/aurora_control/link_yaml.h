// A link file (config/links/*.yaml, docs/links.md, "Link files"), read
// strictly: unknown keys, probabilities outside [0, 1), a burst below 1,
// negative delays and a latency beyond the history are refused, naming the
// key, the value and what is accepted.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "aurora_control/limits.h"
#include "aurora_control/link.h"
#include "aurora_control/yaml_reader.h"

namespace aurora_control {

inline void readJitter(const YamlReader& r, const YAML::Node& n, const std::string& key, LinkDirection& d) {
  r.onlyKeys(n, key, {"kind", "max", "mean"});
  const std::string kind = r.text(r.require(n, key, "kind", "uniform, geometric"), r.key(key, "kind"));
  if (kind == "uniform") d.jitter = JitterKind::kUniform;
  else if (kind == "geometric") d.jitter = JitterKind::kGeometric;
  else r.fail(r.key(key, "kind"), "= '" + kind + "' is unknown: accepted uniform, geometric");
  d.jitter_max = r.integer(r.require(n, key, "max", "whole samples >= 0"), r.key(key, "max"));
  if (d.jitter_max < 0) r.fail(r.key(key, "max"), "= " + YamlReader::fmt(double(d.jitter_max)) + " is refused: accepted whole samples >= 0");
  if (d.jitter == JitterKind::kGeometric) {
    d.jitter_mean = r.numberIn(r.require(n, key, "mean", "samples > 0"), r.key(key, "mean"), 0.0, 1e6, "samples", false);
  } else if (n["mean"]) {
    r.fail(r.key(key, "mean"), "is for the geometric jitter: a uniform jitter has only 'max'");
  }
}

inline LinkDirection readLinkDirection(const YamlReader& r, const YAML::Node& n, const std::string& key) {
  LinkDirection d;
  r.onlyKeys(n, key, {"delay", "jitter", "loss", "burst"});
  if (n["delay"]) {
    d.delay = r.integer(n["delay"], r.key(key, "delay"));
    if (d.delay < 0) r.fail(r.key(key, "delay"), "= " + YamlReader::fmt(double(d.delay)) + " is refused: accepted " + delayRangeText());
  }
  if (n["jitter"]) readJitter(r, n["jitter"], r.key(key, "jitter"), d);
  if (n["loss"]) {
    d.loss = r.number(n["loss"], r.key(key, "loss"));
    if (!(d.loss >= 0.0 && d.loss < 1.0)) r.fail(r.key(key, "loss"), "= " + YamlReader::fmt(d.loss) + " is refused: accepted a share in [0, 1)");
  }
  if (n["burst"]) {
    d.burst = r.number(n["burst"], r.key(key, "burst"));
    if (!(d.burst >= 1.0)) r.fail(r.key(key, "burst"), "= " + YamlReader::fmt(d.burst) + " is refused: accepted a mean run of losses >= 1 sample (1: independent losses)");
  }
  // The chain's entry probability q = loss / (burst (1 - loss)) must be a probability.
  if (d.burst > 1.0 && d.loss > d.burst / (d.burst + 1.0)) {
    r.fail(r.key(key, "loss"), "= " + YamlReader::fmt(d.loss) + " is refused with burst " + YamlReader::fmt(d.burst) +
                                   ": accepted up to burst / (burst + 1) = " + YamlReader::fmt(d.burst / (d.burst + 1.0)));
  }
  if (d.maxLatency() > kMaxDelaySamples) {
    r.fail(r.key(key, "delay"), "plus the jitter's max = " + std::to_string(d.maxLatency()) +
                                    " samples is beyond the history: accepted up to " + std::to_string(kMaxDelaySamples));
  }
  return d;
}

// `node`: the mapping under 'link:'.
inline LinkParams readLink(const YamlReader& r, const YAML::Node& node, const std::string& key) {
  LinkParams l;
  r.onlyKeys(node, key, {"uplink", "downlink", "seed", "cmd_timeout"});
  if (node["uplink"]) l.uplink = readLinkDirection(r, node["uplink"], r.key(key, "uplink"));
  if (node["downlink"]) l.downlink = readLinkDirection(r, node["downlink"], r.key(key, "downlink"));
  if (node["seed"]) {
    const long seed = r.integer(node["seed"], r.key(key, "seed"));
    if (seed < 0 || seed > 4294967295L) r.fail(r.key(key, "seed"), "= " + std::to_string(seed) + " is refused: accepted [0, 4294967295]");
    l.seed = static_cast<uint32_t>(seed);
  }
  if (node["cmd_timeout"]) l.cmd_timeout = r.numberIn(node["cmd_timeout"], r.key(key, "cmd_timeout"), 0.0, 60.0, "s", false);
  return l;
}

// The uplink's base delay from the run's delay (a tool's --delay, the node's
// delay/*; 0 when not given) and a link file's uplink delay: whichever is
// not 0; both given and different is refused (returns why, else "").
inline std::string combineUplinkDelay(long run_delay, const LinkParams& link, long& delay) {
  const long file_delay = link.uplink.delay;
  delay = run_delay != 0 ? run_delay : file_delay;
  if (run_delay != 0 && file_delay != 0 && run_delay != file_delay) {
    return "the delay " + std::to_string(run_delay) + " and the link's uplink delay " + std::to_string(file_delay) +
           " differ: give the uplink delay once (the link file's, or the delay with the file's at 0)";
  }
  return "";
}

inline LinkParams readLinkFile(const std::string& path) {
  const YAML::Node root = loadYamlFile("link file", path);
  const YamlReader r("link file '" + path + "': ");
  r.onlyKeys(root, "", {"link"});
  return readLink(r, r.require(root, "", "link", "uplink, downlink, seed, cmd_timeout"), "link");
}

}  // namespace aurora_control
