// What every shape's flight and the formation node refuse alike
// (formation_flight.h): a robot's delay and link against its run, and
// --delay's per-robot delays.
#include "aurora_control/formation/formation_flight.h"

#include <string>
#include <vector>

#include "aurora_control/link/link_yaml.h"
#include "aurora_control/params/limits.h"

namespace aurora_control {

void refuseRobotLink(const LinkParams& link, long delay, int r, long ticks, double Ts) {
  const std::string robot = "robot " + std::to_string(r + 1) + "'s link";
  const std::string late = latestPacketRefusal(link, delay, ticks, Ts);
  if (!late.empty()) throw ConfigError(robot + ": " + late);
  if (link.historyNeeded(delay) > kMaxDelaySamples) {
    throw ConfigError(robot + " with its delay of " + std::to_string(delay) + " needs " +
                      std::to_string(link.historyNeeded(delay)) + " samples of history: accepted up to " +
                      std::to_string(kMaxDelaySamples));
  }
}

void refuseRobotDelay(const LinkParams& link, long delay, int r, long ticks, double Ts) {
  if (!delayShorterThanRun(delay, ticks)) throw ConfigError(delayRunText(delay, ticks, Ts));
  refuseRobotLink(link, delay, r, ticks, Ts);
}

std::vector<long> robotDelays(const std::vector<long>& given, size_t robots, const std::string& shape, double Ts,
                              long ticks, const std::vector<long>& none, const std::string& robot) {
  if (given.empty()) return none;
  if (given.size() != robots) {
    throw ConfigError("--delay: give one delay per " + robot + " (" + std::to_string(robots) + " for " + shape +
                      "), or none: got " + std::to_string(given.size()));
  }
  std::vector<long> delays(robots);
  for (size_t r = 0; r < robots; ++r) {
    const std::string which = "(" + robot + " " + std::to_string(r + 1) + ")";
    const std::string refusal = delayRefusal(double(given[r]), false, Ts, delays[r]);
    if (!refusal.empty()) throw ConfigError("--delay " + std::to_string(given[r]) + " " + which + " " + refusal);
    if (!delayShorterThanRun(delays[r], ticks)) {
      throw ConfigError("--delay " + which + " = " + delayRunText(delays[r], ticks, Ts));
    }
  }
  return delays;
}

}  // namespace aurora_control
