// What the controller node and replay say of a loop's law: its name and its
// gains in force by name (Control.controller, gain_names, gains), and those
// gains read back from a recorded Control message, for every law of the
// list alike (law_yaml.h's slots). ROS-free.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "aurora_control/loop/delayed_controller.h"
#include "aurora_control/loop/law_yaml.h"

namespace aurora_control {

template <class Data>
std::vector<std::pair<std::string, double>> gainsInForce(const LawSettings<Data>& set) {
  std::vector<std::pair<std::string, double>> out;
  typename Data::template Gains<double> g = set.gains;
  set.withLawType([&](auto law) {
    for (const auto& slot : lawGainSlots(law, g)) out.emplace_back(slot.first, *slot.second);
  });
  return out;
}

// Sets every gain of the law in force from names and values
// (Control.gain_names, gains); "" when all were there, else the first
// missing name.
template <class Data>
std::string setGainsNamed(LawSettings<Data>& set, const std::vector<std::string>& names,
                          const std::vector<double>& values) {
  std::string missing;
  set.withLawType([&](auto law) {
    for (const auto& slot : lawGainSlots(law, set.gains)) {
      size_t i = 0;
      while (i < names.size() && names[i] != slot.first) ++i;
      if (i >= names.size() || i >= values.size()) {
        missing = slot.first;
        return;
      }
      *slot.second = values[i];
    }
  });
  return missing;
}

}  // namespace aurora_control
