// replay: feeds a recorded flight's state stream through the controller core
// offline, with its recorded timing (each recorded control cycle sees the
// states received up to it), and compares the commands with the recorded
// ones. Same configuration: identical commands. Changed configuration: the
// new commands next to the old. Any recorded flight becomes a regression
// test for controller changes.
#include <aurora_msgs/Control.h>
#include <aurora_msgs/DroneState.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <yaml-cpp/yaml.h>

#include <boost/program_options.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "aurora_common/number_text.h"
#include "aurora_control/predictor/predictor_yaml.h"
#include "aurora_control/loop/delayed_controller.h"
#include "option_values.h"
#include "aurora_control/loop/law_settings_yaml.h"
#include "aurora_control/law/other_laws.h"
#include "aurora_control/link/link_yaml.h"
#include "aurora_control/params/limits.h"
#include "aurora_control/params/shipped_files.h"
#include "aurora_control/task/tracking.h"
#include "aurora_common/ros/config_dir.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"
#include "aurora_sim/ros/conversions.h"
#include "aurora_control/ros/control_msg.h"

namespace po = boost::program_options;

namespace {

using namespace aurora_control;

const char* kAbout =
    "usage: replay BAG [options]\n"
    "\n"
    "Replays the recorded states of BAG through the controller core and compares the\n"
    "commands with the recorded control messages. Without options the recorded\n"
    "configuration (gains, delay, clamping, as recorded cycle by cycle) is used and the\n"
    "commands must be identical.\n"
    "\n"
    "options";

constexpr int kCapacity = kDelayHistory;  // limits.h, as the node

[[noreturn]] void fail(const std::string& msg, int code = 2) {
  std::fprintf(stderr, "replay: %s\n", msg.c_str());
  std::exit(code);
}

double number(const std::string& flag, const std::string& v);

// A PD gain, with the node's range (limits.h).
double gain(const std::string& flag, const std::string& v) {
  const double x = number(flag, v);
  if (x < kPdGainMin || x > kPdGainMax) {
    fail(flag + " " + v + " is outside the accepted range [" + YamlReader::fmt(kPdGainMin) + ", " +
         YamlReader::fmt(kPdGainMax) + "]");
  }
  return x;
}

double number(const std::string& flag, const std::string& v) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (end == v.c_str() || *end != '\0' || !std::isfinite(x)) {
    fail(flag + " '" + v + "' is not a number");
  }
  return x;
}

struct Overrides {
  bool kp = false, kd = false, delay = false, delay_seconds = false, clamp = false, law = false;
  double kp_value = 0, kd_value = 0, delay_seconds_value = 0;
  long delay_value = 0;
  bool clamp_value = true;
  // --controller FILE: its law's name and mapping (read with its vehicle's sample time: fileLaw).
  std::string controller_path, controller_name;
  YAML::Node controller_mapping;
  bool any() const { return kp || kd || delay || delay_seconds || clamp || law; }
};

void loadControllerFile(const std::string& path, Overrides& o) {
  try {
    o.controller_path = path;
    if (readControllerPredictor(path).form != PredictorForm::kOff) {
      throw ConfigError("--controller " + path + ": its 'predictor' block is refused here: replay follows the "
                        "predictor the bag's Control messages say the node ran (docs/predictor.md, \"In the ROS "
                        "loop\"); give the file without it, and --predictor-model FILE for its model");
    }
    o.controller_name = controllerFileName(path);
    o.law = true;
    const YAML::Node root = loadYamlFile("controller file", path);
    const YamlReader r("controller file '" + path + "': ");
    r.onlyKeys(root, "", {"controller", "clamp_commands", "predictor"});  // an 'off' predictor: refused above otherwise
    o.controller_mapping = root["controller"];
    lawNameIn(r, o.controller_mapping, "controller");
    if (root["clamp_commands"]) o.clamp = true, o.clamp_value = r.boolean(root["clamp_commands"], "clamp_commands");
  } catch (const ConfigError& e) {
    fail(e.what());
  }
}

// The gains recorded in a control message (the node writes them each
// cycle, so a live reconfiguration replays too); one law per bag.
template <class Data>
void recordedLaw(const aurora_msgs::Control& c, LawSettings<Data>& set) {
  if (c.controller != lawNameOf(set)) {
    fail("control message of step " + std::to_string(c.step) + ": controller '" + c.controller + "' where '" +
         lawNameOf(set) + "' was recorded before: one law per bag");
  }
  const std::string missing = setGainsNamed(set, c.gain_names, c.gains);
  if (!missing.empty()) fail("control message of step " + std::to_string(c.step) + ": gain '" + missing + "' missing");
}

// The command line (a mistake ends the program with status 2 and the usage).
struct Arguments {
  std::string bag_path, ns, out_path;
  std::string vehicle_path;  // default: configDir()/vehicles/NAME.yaml, NAME the law's vehicle (vehicleFor)
  std::string link_path;     // default: the ideal link
  std::string predictor_model_path;  // default: the vehicle file (docs/predictor.md, "In the ROS loop")
  bool expect_identical = false;
  Overrides o;
};

// The options' values as given (numbers as text, so that a refusal quotes them).
struct Given {
  std::string controller, kp, kd, delay, delay_seconds;
  std::vector<std::string> bags;
};

po::options_description describe(Arguments& args, Given& g) {
  po::options_description d(kAbout, 100, 50);
  d.add_options()
      ("ns", po::value(&args.ns)->value_name("NAME"), "drone namespace (default: the only one in the bag)")
      ("controller", po::value(&g.controller)->value_name("FILE"),
       "controller YAML (config/controllers/*.yaml), or a shipped NAME (config/controllers/NAME.yaml): law, gains, clamping")
      ("kp", po::value(&g.kp)->value_name("X"), "gain of the PD law")
      ("kd", po::value(&g.kd)->value_name("X"), "gain of the PD law")
      ("vehicle", po::value(&args.vehicle_path)->value_name("FILE"),
       ("vehicle YAML the law flies and inverts (default: vehicles/NAME.yaml of the aurora_config package, NAME the "
        "law's vehicle: " + lawVehicleNames() + ")").c_str())
      ("delay", po::value(&g.delay)->value_name("N"), "delay in samples")
      ("link", po::value(&args.link_path)->value_name("FILE"),
       "link YAML (config/links/*.yaml, docs/links.md), or a shipped NAME (config/links/NAME.yaml: wifi_lab, ...): "
       "replay over that link (the delay stays the recorded or given one)")
      ("delay-seconds", po::value(&g.delay_seconds)->value_name("S"), "delay in seconds (rounded to whole samples)")
      ("predictor-model", po::value(&args.predictor_model_path)->value_name("FILE"),
       "vehicle YAML the node's state predictor used as its model, where the bag's Control.predictor is on "
       "(default: the vehicle file, as the node's live switch takes)")
      ("clamp", "clamp commands to [-1, 1]")
      ("no-clamp", "do not clamp commands")
      ("out", po::value(&args.out_path)->value_name("FILE"), "CSV: step, recorded and replayed commands per cycle (u1 .. uN: the vehicle's, in the bag's Control.command_names order)")
      ("expect-identical", po::bool_switch(&args.expect_identical), "exit 1 unless every command is identical")
      ("help,h", "this text");
  return d;
}

[[noreturn]] void usageError(const std::string& msg, const po::options_description& d) {
  std::ostringstream usage;
  usage << d;
  fail(msg + "\n\n" + usage.str());
}

// The overrides from what was given, checked with the node's limits (limits.h).
void readOverrides(const po::variables_map& vm, const Given& g, Overrides& o) {
  if (!g.controller.empty()) loadControllerFile(g.controller, o);
  if (!g.kp.empty()) o.kp = true, o.kp_value = gain("--kp", g.kp);
  if (!g.kd.empty()) o.kd = true, o.kd_value = gain("--kd", g.kd);
  if (!g.delay.empty() && !g.delay_seconds.empty()) fail("--delay and --delay-seconds exclude each other: give one");
  if (!g.delay.empty()) {
    const std::string refusal = delayRefusal(number("--delay", g.delay), false, 0.0, o.delay_value);
    if (!refusal.empty()) fail("--delay " + g.delay + " " + refusal);
    o.delay = true;
  }
  if (!g.delay_seconds.empty()) {
    // Rounded with each cycle's recorded Ts and checked there (cycleSettings, delayRefusal).
    o.delay_seconds = true, o.delay_seconds_value = number("--delay-seconds", g.delay_seconds);
    if (!(o.delay_seconds_value >= 0)) fail("--delay-seconds " + g.delay_seconds + " is refused: accepted seconds >= 0");
  }
  if (vm.count("clamp") && vm.count("no-clamp")) fail("--clamp and --no-clamp exclude each other: give one");
  // Given on the command line, the choice overrides the controller file's.
  if (vm.count("clamp") || vm.count("no-clamp")) o.clamp = true, o.clamp_value = vm.count("clamp") > 0;
}

Arguments parseArguments(int argc, char** argv) {
  Arguments args;
  Given g;
  const po::options_description d = describe(args, g);
  po::options_description all(d);
  all.add_options()("bag", po::value(&g.bags));
  po::positional_options_description bag;
  bag.add("bag", -1);
  po::variables_map vm;
  try {
    po::store(po::command_line_parser(joinOptionValues(argc, argv, d)).options(all).positional(bag).run(), vm);
    po::notify(vm);
  } catch (const po::error& e) {
    usageError(e.what(), d);
  }
  if (vm.count("help")) {
    std::cout << d;
    std::exit(0);
  }
  if (g.bags.empty()) usageError("a bag is required", d);
  if (g.bags.size() > 1) fail("one bag at a time ('" + g.bags[1] + "' is extra)");
  args.bag_path = g.bags[0];
  // Shipped files by NAME, as flight takes them (config/controllers/NAME.yaml, config/links/NAME.yaml).
  const std::string config = aurora_common::configDir();
  g.controller = aurora_control::shippedOrPath(g.controller, config, "controllers");
  args.link_path = aurora_control::shippedOrPath(args.link_path, config, "links");
  readOverrides(vm, g, args.o);
  return args;
}

void openBag(const std::string& bag_path, rosbag::Bag& bag) {
  if (!std::ifstream(bag_path).good()) {
    fail("bag '" + bag_path + "' does not exist or cannot be read" +
         (bag_path.size() > 7 && bag_path.compare(bag_path.size() - 7, 7, ".active") == 0
              ? std::string(" (an .active bag is still being recorded)") : std::string()));
  }
  try {
    bag.open(bag_path, rosbag::bagmode::Read);
  } catch (const rosbag::BagException& e) {
    fail("bag '" + bag_path + "' cannot be read (truncated, still recording, or not a bag?): " +
         e.what());
  }
}

// The drone's namespace in the bag: `ns`, or the one <ns>/state and
// <ns>/control pair the bag holds.
std::string droneNamespace(rosbag::Bag& bag, std::string ns) {
  // Find the drone's topics.
  std::set<std::string> topics;
  {
    rosbag::View all(bag);
    for (const rosbag::ConnectionInfo* c : all.getConnections()) topics.insert(c->topic);
  }
  if (ns.empty()) {
    std::vector<std::string> candidates;
    for (const std::string& t : topics) {
      const std::string suffix = "/control";
      if (t.size() > suffix.size() && t.compare(t.size() - suffix.size(), suffix.size(), suffix) == 0 &&
          topics.count(t.substr(0, t.size() - suffix.size()) + "/state")) {
        candidates.push_back(t.substr(0, t.size() - suffix.size()));
      }
    }
    if (candidates.size() != 1) {
      std::string present;
      for (const auto& t : topics) present += " " + t;
      fail(candidates.empty() ? "the bag has no <ns>/state and <ns>/control pair; present:" + present
                              : "the bag has several drones: choose one with --ns");
    }
    ns = candidates[0];
  }
  if (ns.front() != '/') ns = "/" + ns;
  for (const std::string t : {ns + "/state", ns + "/control"}) {
    if (!topics.count(t)) {
      std::string present;
      for (const auto& p : topics) present += " " + p;
      fail("the bag lacks " + t + "; present:" + present);
    }
  }

  return ns;
}

// The --controller file's law and gains, read once with its vehicle's
// sample time (the compensator's rate must divide it).
template <class Data>
void fileLaw(const Overrides& o, LawSettings<Data>& set) {
  if (!o.law) return;
  try {
    readLawMapping(YamlReader("controller file '" + o.controller_path + "': "), o.controller_mapping, "controller", set);
  } catch (const ConfigError& e) {
    fail(e.what());
  }
}

// The gain `name` of the law in force set to v; false when the law has no
// gain of that name.
template <class Data>
bool setGain(LawSettings<Data>& set, const std::string& name, double v) {
  double* gain = nullptr;
  set.withLawType([&](auto law) { gain = gainNamed(law, set.gains, name); });
  if (gain != nullptr) *gain = v;
  return gain != nullptr;
}

// The law whose gain `name` is (the first of the list with one).
inline std::string lawWithGain(const std::string& name) {
  std::string law;
  forEachLaw([&](auto l) {
    for (int i = 0; i < decltype(l)::kGainCount && law.empty(); ++i) {
      if (name == decltype(l)::gainRow(i).name) law = l.name();
    }
  });
  return law;
}

// The law and gains of the cycle of `c`: recorded, or the --controller
// file's (fileLaw's, kept), with --kp, --kd.
template <class Data>
void cycleLaw(const aurora_msgs::Control& c, const Overrides& o, LawSettings<Data>& set) {
  if (!o.law) recordedLaw(c, set);
  struct Given {
    bool on;
    const char* name;
    double value;
  };
  for (const Given& g : {Given{o.kp, "kp", o.kp_value}, Given{o.kd, "kd", o.kd_value}}) {
    if (!g.on || setGain(set, g.name, g.value)) continue;
    fail(std::string("--") + g.name + " is a gain of the " + lawWithGain(g.name) + " law, but the " +
         (o.law ? "--controller file's" : "bag's") + " controller is " + lawNameOf(set) + " (step " +
         std::to_string(c.step) + "): give its gains in a controller file with --controller FILE (e.g. "
         "config/controllers/" + lawNameOf(set) + ".yaml)");
  }
}

// The settings of the cycle of `c`: the recorded law, gains, delay and
// clamping, with the command line's overrides; refused as the node refuses.
template <class Settings>
void cycleSettings(const aurora_msgs::Control& c, const Overrides& o, long iterations, double task_duration,
                   Settings& set) {
  set.Ts = c.sample_time;
  cycleLaw(c, o, set);
  set.delay = o.delay ? o.delay_value : static_cast<long>(c.delay_samples);
  if (o.delay_seconds) {
    const std::string refusal = delayRefusal(o.delay_seconds_value, true, c.sample_time, set.delay);
    if (!refusal.empty()) fail("--delay-seconds " + YamlReader::fmt(o.delay_seconds_value) + " " + refusal);
  }
  if (task_duration > 0.0 && !delayShorterThanRun(set.delay, iterations)) {
    fail(std::string(o.delay ? "--delay" : o.delay_seconds ? "--delay-seconds" : "the recorded delay") +
         ": " + delayRunText(set.delay, iterations, c.sample_time));
  }
  set.clamp_commands = o.clamp ? o.clamp_value : static_cast<bool>(c.clamped);
}

// The states the controller received, by step.
struct BagStates {
  std::map<long, StateSample> by_step;
  std::set<long> recovered;  // steps the bag lacked, taken from Control.state_used
  std::set<long> stale;      // steps its source marked stale, which the node ignored
};

// Where the controller's history began, when the bag holds its first cycle
// (header.seq 0: roscpp numbers a publisher's messages from 0): the first of
// the delay + 1 - pending states it held then (delay + 1 once the delay was
// in force, all the delay rule reads). -1 when the bag starts later. With
// record:=true the controller takes its first state once the recorder
// listens to its control and cmd_vel, so the recorder's `state`
// subscription may hold a few states more, or fewer, at the start.
long historyStart(const aurora_msgs::Control& first) {
  if (first.header.seq != 0) return -1;
  const long held = static_cast<long>(first.delay_samples) + 1 - static_cast<long>(first.delay_pending);
  return static_cast<long>(first.step) - held + 1;
}

// A state the recorder dropped (a loaded machine) is in the control message
// of the cycle that used it: Control.state_used holds it whole (its step,
// stamp and the vehicle's states). Steps from the controller's first
// (historyStart; the bag's first recorded state when unknown) to the last
// recorded state.
void recoverDroppedStates(const std::vector<aurora_msgs::Control>& controls, BagStates& states) {
  if (states.by_step.empty() || controls.empty()) return;
  const long start = historyStart(controls.front());
  const long first = start >= 0 ? start : states.by_step.begin()->first, last = states.by_step.rbegin()->first;
  for (const aurora_msgs::Control& c : controls) {
    const long step = static_cast<long>(c.state_used.step);
    if (step < first || step >= last || states.by_step.count(step)) continue;
    states.by_step.emplace(step, sampleFromMsg(c.state_used));
    states.recovered.insert(step);
  }
}

// The drone's states (by step, the first of a re-sent one, none marked
// stale; those the recorder dropped from the control messages) and control
// messages in the bag.
void readDrone(rosbag::Bag& bag, const std::string& bag_path, const std::string& ns,
               BagStates& states, std::vector<aurora_msgs::Control>& controls) {
  try {
    rosbag::View view(bag, rosbag::TopicQuery(std::vector<std::string>{ns + "/state", ns + "/control"}));
    for (const rosbag::MessageInstance& m : view) {
      if (auto s = m.instantiate<aurora_msgs::DroneState>()) {
        if (s->stale) {  // the node ignores states its source marked stale
          states.stale.insert(static_cast<long>(s->step));
          continue;
        }
        const StateSample sample = sampleFromMsg(*s);
        states.by_step.emplace(sample.step, sample);  // keeps the first of a re-sent step
      } else if (auto c = m.instantiate<aurora_msgs::Control>()) {
        controls.push_back(*c);
      }
    }
  } catch (const std::exception& e) {
    fail(std::string("bag '") + bag_path + "' is damaged: " + e.what());
  }
  recoverDroppedStates(controls, states);
}

// The vehicle the law flies and inverts (--vehicle, else its shipped file).
template <class Vehicle>
typename Vehicle::template Params<double> vehicleFor(const std::string& path, const std::string& law) {
  try {
    const std::string file = path.empty() ? aurora_common::configDir() + "/vehicles/" + Vehicle::name() + ".yaml" : path;
    return aurora_sim::loadVehicleFile<Vehicle>(file, "the controller '" + law + "'");
  } catch (const std::runtime_error& e) {
    fail(std::string("--vehicle: ") + e.what());
  }
}

// --out: the recorded and replayed commands side by side, per cycle: the
// vehicle's `inputs` commands, u1 .. uN in Control.command_names' order (a
// Pioneer's two; four zero columns more looked like commands).
FILE* openCommandsCsv(const std::string& path, int inputs) {
  FILE* csv = std::fopen(path.c_str(), "w");
  if (!csv) fail("cannot write '" + path + "'");
  std::fprintf(csv, "step");
  for (const char* side : {"recorded", "replayed"}) {
    for (int i = 1; i <= inputs; ++i) std::fprintf(csv, ",%s_u%d", side, i);
  }
  std::fprintf(csv, ",max_abs_diff\n");
  return csv;
}

void writeCommandsRow(FILE* csv, const aurora_msgs::Control& c, const ControlOutput& out, int inputs, double diff) {
  std::fprintf(csv, "%lu", static_cast<unsigned long>(c.step));
  for (int i = 0; i < inputs; ++i) aurora_common::writeNumber(csv, c.command[i]);
  for (int i = 0; i < inputs; ++i) aurora_common::writeNumber(csv, out.U[i]);
  aurora_common::writeNumber(csv, diff);
  std::fprintf(csv, "\n");
}

// The controller core: the vehicle its law flies and inverts, the first
// cycle's settings (of `recorded`), and the link with that cycle's delay as
// its uplink delay, configured as the node configures it: after the delay
// is known and before the first state (a link configured with another delay
// receives other states from step 0 on).
template <class Settings>
std::unique_ptr<DelayedController<kCapacity, Settings>> makeCore(const Arguments& args,
                                                                 const aurora_msgs::Control& recorded,
                                                                 long iterations) {
  using Vehicle = typename Settings::Data::Vehicle;
  std::unique_ptr<DelayedController<kCapacity, Settings>> core(new DelayedController<kCapacity, Settings>());
  if (args.o.law && vehicleOfLaw(args.o.controller_name) != vehicleOfLaw(recorded.controller)) {
    fail("--controller " + args.o.controller_path + ": its law '" + args.o.controller_name + "' flies the " +
         vehicleOfLaw(args.o.controller_name) + ", but the bag's controller '" + recorded.controller + "' flew the " +
         vehicleOfLaw(recorded.controller) + ": give a controller file of a " + vehicleOfLaw(recorded.controller) +
         " law (config/controllers/)");
  }
  core->settings.vehicle = vehicleFor<Vehicle>(args.vehicle_path, args.o.law ? args.o.controller_name : recorded.controller);
  if (core->settings.vehicle.Ts != recorded.sample_time) {
    fail("the vehicle's sample time " + YamlReader::fmt(core->settings.vehicle.Ts) + " s differs from the recorded " +
         YamlReader::fmt(recorded.sample_time) + " s: give the flight's vehicle file with --vehicle FILE");
  }
  core->settings.Ts = recorded.sample_time;
  core->settings.law = lawIndexOf<typename Settings::Data>(recorded.controller);
  fileLaw(args.o, core->settings);
  cycleSettings(recorded, args.o, iterations, recorded.task_duration, core->settings);
  if (!args.link_path.empty()) {
    try {
      core->settings.link = readLinkFile(args.link_path);
    } catch (const ConfigError& e) {
      fail(e.what());
    }
    core->configureLink();
  }
  return core;
}

// Whether the node flew over an imperfect link (docs/links.md): a lost
// packet, a state that did not arrive, a command that differs from the one
// sent (not by the joystick) or a drone hovering on a stale command.
bool recordedOverALink(const std::vector<aurora_msgs::Control>& controls) {
  for (const aurora_msgs::Control& c : controls) {
    if (c.uplink_losses > 0 || c.downlink_losses > 0 || !c.state_arrived || c.drone_hovers) return true;
    if (!c.overridden && c.law_ran && c.command != c.command_sent) return true;
  }
  return false;
}



// The replayed command of cycle `c` against the recorded one: the largest
// difference, and whether every entry is identical. Where the joystick
// replaced the command, the law's own command (command_unclamped) is compared.
double commandDifference(const aurora_msgs::Control& c, const ControlOutput& out, int inputs, bool& same) {
  const double* mine = c.overridden ? out.U_unclamped : out.U;
  const double* theirs = c.overridden ? c.command_unclamped.data() : c.command.data();
  double diff = 0.0;
  for (int i = 0; i < inputs; ++i) {
    diff = std::max(diff, std::fabs(mine[i] - theirs[i]));
    same = same && mine[i] == theirs[i];
  }
  return diff;
}

// What the replay's configuration is against the recording's, for its summary.
const char* configurationText(const Arguments& args, const std::vector<aurora_msgs::Control>& controls) {
  if (args.o.any()) return " (changed configuration)";
  if (!args.link_path.empty()) return " (recorded configuration over the link given)";
  if (recordedOverALink(controls)) {
    return " (recorded law and delay, but the ideal link: the bag was flown over an imperfect link; give it with "
           "--link FILE)";
  }
  return " (recorded configuration)";
}

// The state predictor as the node ran it at cycle c (Control.predictor,
// docs/predictor.md): set up again where the recorded form changes, as the
// node's live switch does; its model the --predictor-model file or the
// vehicle file; its command delay the link's; its horizon what the recorded
// step it predicted says (prediction_step = step + command delay + horizon).
template <class Core>
void followPredictor(const Arguments& args, const aurora_msgs::Control& c, Core& core) {
  using Vehicle = typename Core::Vehicle;
  PredictorForm form = PredictorForm::kOff;
  if (!c.predictor.empty() && !predictorFormOf(c.predictor, form)) {
    fail("control message of step " + std::to_string(c.step) + ": predictor '" + c.predictor + "' is unknown");
  }
  if (form == core.settings.predictor) return;
  core.settings.predictor = form;
  PredictorRun<Vehicle, double> p;
  p.form = form;
  try {
    p.model = args.predictor_model_path.empty()
                  ? core.settings.vehicle
                  : aurora_sim::loadVehicleFile<Vehicle>(args.predictor_model_path, "replay --predictor-model");
  } catch (const ConfigError& e) {
    fail(e.what());
  }
  const long delay = core.settings.link.downlink.delay;
  const long horizon = form == PredictorForm::kOff ? 0 : static_cast<long>(c.prediction_step - c.step) - delay;
  if (horizon < 0) {
    fail("control message of step " + std::to_string(c.step) + ": it predicted step " +
         std::to_string(c.prediction_step) + ", before the command delay of " + std::to_string(delay) +
         " samples: give the flight's link with --link FILE");
  }
  p.path = CommandPath{delay, horizon, true};
  core.configurePredictor(p);
}

// Pushes the states the controller had received by cycle `c` (steps up to
// c.step) into the core. The node received every step from its first
// (firstStateTaken) on but those marked stale: its sources number their
// states one by one and its queue holds 100. A step the bag lacks (the recorder dropped it, and
// every control message that used it) still takes its place in the history
// and on the link, as it did in the node, with the state before it standing
// in for it; it goes to `missing`.
template <class Core>
void pushStatesUpTo(const aurora_msgs::Control& c, const BagStates& states, long& next_step, Core& core,
                    std::set<long>& missing) {
  for (; next_step <= static_cast<long>(c.step); ++next_step) {
    if (states.stale.count(next_step)) continue;
    auto it = states.by_step.find(next_step);
    if (it != states.by_step.end()) {
      core.push(it->second);
      continue;
    }
    StateSample stand_in = core.newest();  // the first step pushed is a recorded one
    stand_in.step = next_step;
    core.push(stand_in);
    missing.insert(next_step);
  }
}

// The step of the first state the controller took: where its history
// began (historyStart), else the bag's first state. A state recorded before
// it the controller never had (on a loaded machine replay then put the
// delay in force a few cycles early); one it had that the recorder missed
// came back from the control messages (recoverDroppedStates).
long firstStateTaken(const aurora_msgs::Control& first, const BagStates& states) {
  const long start = historyStart(first);
  const long from = start >= 0 ? start : states.by_step.begin()->first;
  const auto it = states.by_step.lower_bound(from);  // a recorded state: the first pushed has no stand-in
  return it == states.by_step.end() ? from : it->first;
}

struct ReplayCount {
  long cycles = 0, identical = 0;  // compared
  double max_diff = 0.0;
  long differ() const { return cycles - identical; }
  // Control messages the recorder dropped (a loaded machine): header.seq,
  // which roscpp numbers per publisher, skips them. A law with memory
  // cannot be replayed across a cycle it lacks, so the cycles from the
  // first gap on are replayed but not compared.
  long missing_controls = 0, first_gap_step = -1, not_compared = 0;
  long on_stand_in = 0;  // cycles whose law ran on a stand-in for a state the bag lacks (pushStatesUpTo)
  // A bag that starts late: its first control message is not the
  // controller's first (roscpp numbers a publisher's messages from 0), so
  // the states before it and the law's memory are not in it. Its cycles
  // are replayed, and compared from the second of two law cycles in a row
  // whose state is the recorded one (the delay history rebuilt, the law's
  // memory of one cycle refreshed), once the command the drone applies was
  // sent from then on (over a link's downlink it is an older one).
  long missed_at_start = 0, warming = 0, warm_from = -1;
  int warm_runs = 0;
  void warmUp(const aurora_msgs::Control& c, const ControlOutput& out) {
    if (missed_at_start == 0 || warm_from >= 0) return;
    const bool in_step = c.law_ran && out.used && out.used->step == static_cast<long>(c.state_used.step);
    warm_runs = in_step ? warm_runs + 1 : 0;
    if (warm_runs >= 2) warm_from = static_cast<long>(c.step);
  }
  bool warm(const aurora_msgs::Control& c) const {
    return missed_at_start == 0 || (warm_from >= 0 && static_cast<long>(c.step) - c.command_age >= warm_from);
  }
  uint32_t last_seq = 0;
  bool read_any = false;
  void read(const aurora_msgs::Control& c) {
    if (!read_any) missed_at_start = c.header.seq;
    if (read_any && c.header.seq > last_seq + 1) {
      missing_controls += c.header.seq - last_seq - 1;
      if (first_gap_step < 0) first_gap_step = static_cast<long>(c.step);
    }
    last_seq = c.header.seq;
    read_any = true;
  }
  void add(const aurora_msgs::Control& c, bool same, double diff) {
    if (!warm(c)) {
      ++warming;
      return;
    }
    if (first_gap_step >= 0) {
      ++not_compared;
      return;
    }
    ++cycles;
    identical += same;
    max_diff = std::max(max_diff, diff);
  }
};

// What replay says at the end; the exit status.
int replayVerdict(const Arguments& args, const std::string& ns, const ReplayCount& n, const BagStates& states,
                  const std::set<long>& missing, const std::vector<aurora_msgs::Control>& controls,
                  const ControlOutput& last_out) {
  const aurora_msgs::Control& last = controls.back();
  std::printf("replay: %s: %ld control cycles, %ld identical, %ld differ, max |dU| = %.6g%s\n", ns.c_str(),
              n.cycles, n.identical, n.differ(), n.max_diff, configurationText(args, controls));
  std::printf("replay: metrics recorded IAE %.10g ITAE %.10g IASC %.10g; replayed (open loop on "
              "the recorded states) IAE %.10g ITAE %.10g IASC %.10g\n",
              last.iae, last.itae, last.iasc, last_out.iae, last_out.itae, last_out.iasc);
  if (n.missed_at_start > 0) {
    std::printf("replay: the bag starts late: the controller's first %ld control messages are not in it (a recorder "
                "that connected after the loop started; record:=true waits for it): the %ld cycles before its inputs "
                "were in the bag (the delay history, the law's memory) were replayed but not compared\n",
                n.missed_at_start, n.warming);
  }
  if (!states.recovered.empty()) {
    std::printf("replay: %zu state steps missing from the bag (the recorder dropped them, first %ld) were taken "
                "from the control messages that used them (Control.state_used)\n",
                states.recovered.size(), *states.recovered.begin());
  }
  if (n.missing_controls > 0) {
    std::printf("replay: %ld control messages missing from the bag (the recorder dropped them, first before step "
                "%ld): a law's memory cannot be replayed across a cycle it lacks, so the %ld cycles from there on "
                "were replayed but not compared\n", n.missing_controls, n.first_gap_step, n.not_compared);
  }
  if (!missing.empty()) {
    std::printf("replay: %zu state steps missing from the bag and from its control messages (the recorder dropped "
                "them, first %ld) kept their places in the history and on the link, the state before each "
                "standing in; %ld replayed cycles ran the law on a stand-in%s\n", missing.size(), *missing.begin(),
                n.on_stand_in, n.on_stand_in > 0 ? " (their commands, and a law's memory after them, may differ)" : "");
  }
  if (args.out_path.empty() && n.differ() > 0) {
    std::printf("replay: write the commands side by side with --out FILE.csv\n");
  }
  return args.expect_identical && n.differ() > 0 ? 1 : 0;
}

// Replays the recorded cycles with the law of Settings; the exit status.
template <class Settings>
int replayCycles(const Arguments& args, const std::string& ns, const BagStates& states,
                 const std::vector<aurora_msgs::Control>& controls) {
  const std::string& out_path = args.out_path;
  const bool expect_identical = args.expect_identical;
  const Overrides& o = args.o;
  // The recorded task's length (Control.task_duration; one task per bag, as
  // the report assumes) bounds the delay as in the node and the sweep.
  const aurora_msgs::Control& recorded = controls.front();
  const long iterations = taskStepCount(recorded.task_duration, recorded.sample_time);
  const std::unique_ptr<DelayedController<kCapacity, Settings>> core = makeCore<Settings>(args, recorded, iterations);
  constexpr int kInputs = Settings::Data::Vehicle::kInputs;
  FILE* csv = out_path.empty() ? nullptr : openCommandsCsv(out_path, kInputs);
  ReplayCount n;
  std::set<long> missing;
  ControlOutput out{};
  long next_step = firstStateTaken(controls.front(), states);
  for (const aurora_msgs::Control& c : controls) {
    n.read(c);
    pushStatesUpTo(c, states, next_step, *core, missing);
    if (core->empty()) continue;
    cycleSettings(c, o, iterations, recorded.task_duration, core->settings);
    if (c.law_ran) followPredictor(args, c, *core);
    // The law ran when the node says it did.
    out = c.law_ran ? core->compute(referenceFromMsg(c)) : core->hover();
    n.warmUp(c, out);
    n.on_stand_in += c.law_ran && missing.count(out.used->step);
    bool same = true;
    const double diff = commandDifference(c, out, kInputs, same);
    n.add(c, same, diff);
    if (csv) writeCommandsRow(csv, c, out, kInputs, diff);
  }
  if (csv) std::fclose(csv);
  return replayVerdict(args, ns, n, states, missing, controls, out);
}

// Replays the bag of `args` and compares the commands; the exit status.
int run(const Arguments& args) {
  rosbag::Bag bag;
  openBag(args.bag_path, bag);
  const std::string ns = droneNamespace(bag, args.ns);
  BagStates states;
  std::vector<aurora_msgs::Control> controls;
  readDrone(bag, args.bag_path, ns, states, controls);
  if (controls.empty() || states.by_step.empty()) fail("no " + ns + "/control or " + ns + "/state messages");
  // The law: the --controller file's, else the recorded one (its vehicle's core).
  const std::string law = args.o.law ? args.o.controller_name : controls.front().controller;
  int status = 2;
  if (!withLawNamed(law, [&](auto l) { status = replayCycles<LawSettings<typename decltype(l)::Data>>(args, ns, states, controls); })) {
    fail("controller '" + law + "' is unknown: accepted controllers: " + knownLawNames());
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) { return run(parseArguments(argc, argv)); }
