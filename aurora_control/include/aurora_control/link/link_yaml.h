// A link file (config/links/*.yaml, docs/links.md, "Link files"), read
// strictly: unknown keys, probabilities outside [0, 1), a burst below 1,
// negative delays and a latency beyond the history are refused, naming the
// key, the value and what is accepted.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <string>

#include "aurora_control/params/limits.h"
#include "aurora_control/link/link.h"
#include "aurora_control/params/parameter_table.h"
#include "aurora_control/params/yaml_reader.h"

namespace aurora_control {

// The chain's entry probability q = loss r / (1 - loss) must be a
// probability: with a burst b > 1, loss <= b / (b + 1). "" or the refusal.
inline std::string burstLossRefusal(const LinkDirection& d) {
  if (d.burst <= 1.0 || d.loss <= d.burst / (d.burst + 1.0)) return "";
  return "is refused with burst " + YamlReader::fmt(d.burst) + ": accepted up to burst / (burst + 1) = " +
         YamlReader::fmt(d.burst / (d.burst + 1.0));
}

inline void readJitter(const YamlReader& r, const YAML::Node& n, const std::string& key, LinkDirection& d) {
  r.onlyKeys(n, key, {"kind", "max", "mean"});
  const std::string kind = r.text(r.require(n, key, "kind", "uniform, geometric"), r.key(key, "kind"));
  if (kind == jitterKindName(JitterKind::kUniform)) d.jitter = JitterKind::kUniform;
  else if (kind == jitterKindName(JitterKind::kGeometric)) d.jitter = JitterKind::kGeometric;
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
  if (n["delay"]) {  // the one delay parse (limits.h)
    const double given = r.number(n["delay"], r.key(key, "delay"));
    const std::string refusal = delayRefusal(given, false, 0.0, d.delay);
    if (!refusal.empty()) r.fail(r.key(key, "delay"), "= " + YamlReader::fmt(given) + " " + refusal);
  }
  if (n["jitter"]) readJitter(r, n["jitter"], r.key(key, "jitter"), d);
  // The ranges of the parameter table (parameter_table.h), as the live settings.
  const ParameterSpec& loss = kParameterTable[kRowUplinkLoss];
  const ParameterSpec& burst = kParameterTable[kRowUplinkBurst];
  if (n["loss"]) d.loss = r.numberIn(n["loss"], r.key(key, "loss"), loss.min, loss.max, "(a share of packets)");
  if (n["burst"]) d.burst = r.numberIn(n["burst"], r.key(key, "burst"), burst.min, burst.max, "samples (1: independent losses)");
  const std::string chain = burstLossRefusal(d);
  if (!chain.empty()) r.fail(r.key(key, "loss"), "= " + YamlReader::fmt(d.loss) + " " + chain);
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

// The one rule of a delay given beside a link (docs/links.md, "A delay
// beside a link"), at every entry point (flight and --formation, the
// controller and formation nodes and their launch files, replay, Python, a
// formation file's drones, sweep files): a delay given replaces the link's
// uplink delay, 0 included; none given (kDelayNotGiven) keeps the link's,
// which is 0 without a link.
constexpr long kDelayNotGiven = -1;

inline long delayInForce(long given, const LinkParams& link) {
  return given == kDelayNotGiven ? link.uplink.delay : given;
}

// Where the delay in force came from, for start-up lines: "3 samples (given;
// replaces the link's uplink delay 1)" or "1 samples (the link's uplink delay)".
inline std::string delayOriginText(long given, const LinkParams& link) {
  const long d = delayInForce(given, link);
  std::string out = std::to_string(d) + " samples";
  if (given == kDelayNotGiven) return out + (link.uplink.delay != 0 ? " (the link's uplink delay)" : "");
  if (link.uplink.delay != 0 || !link.ideal()) {
    out += " (given; replaces the link's uplink delay " + std::to_string(link.uplink.delay) + ")";
  }
  return out;
}

// A run's latest packet over `link` with the uplink delay `delay` (its
// delay plus the jitter, or the command path: LinkParams::historyNeeded)
// must arrive within the run of `iterations` steps, as the delay itself
// must (limits.h, delayShorterThanRun). "" or the refusal, to follow the key.
inline std::string latestPacketRefusal(const LinkParams& link, long delay, long iterations, double Ts) {
  const long latest = link.historyNeeded(delay);
  if (delayShorterThanRun(latest, iterations)) return "";
  return "its latest packet (the delay plus the jitter, or the command path) is " + delayRunText(latest, iterations, Ts);
}

// A link in one line, for logs (every value that defines it).
inline std::string linkText(const LinkParams& l) {
  std::string out;
  const char* names[] = {"uplink", "downlink"};
  const LinkDirection* dirs[] = {&l.uplink, &l.downlink};
  for (int i = 0; i < 2; ++i) {
    const LinkDirection& d = *dirs[i];
    char buf[192];
    std::snprintf(buf, sizeof buf, "%s delay %ld, jitter %s max %ld mean %g, loss %g, burst %g; ", names[i], d.delay,
                  jitterKindName(d.jitter),
                  d.jitter_max, d.jitter_mean, d.loss, d.burst);
    out += buf;
  }
  return out + "seed " + std::to_string(l.seed) + ", cmd_timeout " + YamlReader::fmt(l.cmd_timeout) + " s";
}

inline LinkParams readLinkFile(const std::string& path) {
  const YAML::Node root = loadYamlFile("link file", path);
  const YamlReader r("link file '" + path + "': ");
  r.onlyKeys(root, "", {"link"});
  return readLink(r, r.require(root, "", "link", "uplink, downlink, seed, cmd_timeout"), "link");
}

}  // namespace aurora_control
