// The formation node's crews (formation_crew.h): each shape's
// FormationController behind FormationCrew, and the reader that builds the
// crew of a formation file as `flight --formation` builds its run.
#include "aurora_control/formation/formation_crew.h"


#include "aurora_control/formation/formation_checks.h"
#include "aurora_control/formation/formation_flight.h"
#include "aurora_control/formation/formation_yaml.h"
#include "aurora_control/formation/triangle_yaml.h"
#include "aurora_control/formation/uav_ugv_yaml.h"
#include "aurora_control/params/limits.h"
#include "aurora_sim/vehicle/sim_profile.h"

namespace aurora_control {

namespace {

// A robot's vehicle as the launch starts it, and its driver's command.
// What a robot's vehicle file says beyond its vehicle's constants: a
// Pioneer's model choice, which the formation file may change.
inline void fileChoices(const aurora_sim::Pioneer3dx::Params<double>& p, CrewRobot& r) {
  r.vehicle_overrides.emplace_back("kinematic_model", p.kinematic != 0.0 ? "true" : "false");
}
template <class Params>
void fileChoices(const Params&, CrewRobot&) {}

template <class Vehicle>
struct RobotVehicle {
  static void describe(const typename Vehicle::template Params<double>& p, CrewRobot& r) {
    fileChoices(p, r);
    r.vehicle = Vehicle::name();
    r.ground = !aurora_sim::SimProfile<Vehicle>::kFlies;
  }
  static aurora_sim::TwistCommand toDriver(const typename Vehicle::template Params<double>&, const double* U) {
    return Vehicle::toDriver(U);
  }
  static void limitSpeed(const typename Vehicle::template Params<double>&, double* U, double speed, double turn) {
    aurora_sim::SimProfile<Vehicle>::limitSpeed(U, speed, turn);
  }
};
// A mixed crew's robot: the vehicle its parameters chose.
template <class First, class Second>
struct RobotVehicle<aurora_sim::EitherVehicle<First, Second>> {
  using Params = typename aurora_sim::EitherVehicle<First, Second>::template Params<double>;
  static void describe(const Params& p, CrewRobot& r) {
    if (p.is_second) return RobotVehicle<Second>::describe(p.second, r);
    RobotVehicle<First>::describe(p.first, r);
  }
  static aurora_sim::TwistCommand toDriver(const Params& p, const double* U) {
    return p.is_second ? Second::toDriver(U) : First::toDriver(U);
  }
  static void limitSpeed(const Params& p, double* U, double speed, double turn) {
    if (p.is_second) return RobotVehicle<Second>::limitSpeed(p.second, U, speed, turn);
    RobotVehicle<First>::limitSpeed(p.first, U, speed, turn);
  }
};

template <class Shape, class Settings>
class CrewOf final : public FormationCrew {
  using Core = FormationController<kDelayHistory, Shape, Settings>;
  using Vehicle = typename Core::Vehicle;
  static constexpr int kN = Shape::kVariables, kRobots = Shape::kDrones;
  static_assert(kRobots <= kMaxCrew, "a crew holds the largest shape's robots");

 public:
  CrewOf(const typename Core::Run& run, const Settings& common, const std::string& shape, const std::string& law,
         const std::vector<std::string>& namespaces, const std::vector<std::string>& vehicle_files, long ticks)
      : core_(run, common) {
    shape_ = shape, law_name_ = law, Ts_ = run.drone[0].plant.Ts, ticks_ = ticks;
    for (int d = 0; d < kRobots; ++d) {
      CrewRobot r;
      r.name_space = namespaces[d];
      r.vehicle_file = vehicle_files[d];
      r.vehicle_overrides.emplace_back("sample_time", aurora_common::roundTripText(Ts_));
      RobotVehicle<Vehicle>::describe(run.drone[d].plant, r);
      r.delay = run.drone[d].delay;
      for (int i = 0; i < 3; ++i) r.start[i] = run.drone[d].start[i];
      robots_.push_back(r);
    }
  }

  int variables() const override { return kN; }
  const char* variableName(int i) const override { return Shape::variableName(i); }
  bool push(int d, const StateSample& s) override { return core_.push(d, s); }
  long commonStep() const override { return core_.commonStep(); }
  bool ready(int d) const override { return core_.ready(d); }
  const StateSample& newest(int d) const override { return core_.newest(d); }
  void newestPositions(double* X) const override { core_.newestPositions(X); }
  CrewTick tick(long k) override { return crewTick(core_.tick(k)); }
  void startFrom(const double* X0) override { core_.startFrom(X0); }
  ControlOutput hold(int d, const double p[3]) override { return core_.hold(d, p); }
  ControlOutput hover(int d) override { return core_.hover(d); }
  const double* Q() const override { return core_.layer().Q(); }
  const double* Qd() const override { return core_.layer().Qd(); }
  const double* Qtil() const override { return core_.layer().Qtil(); }
  const double* heldPosition(int d) const override { return core_.layer().position(d); }
  void variablesOf(const double* X, double* Q) const override { Shape::variables(X, Q); }
  void positionsOf(const double* Q, double* X) const override { Shape::positions(Q, X); }
  void errors(const double* X, const double* Xd, double& position, double& shape) const override {
    formationErrors<Shape>(X, Xd, position, shape);
  }
  aurora_sim::TwistCommand toDriver(int d, const double* U) const override {
    return RobotVehicle<Vehicle>::toDriver(core_.run().drone[d].plant, U);
  }
  void limitSpeed(int d, double* U, double max_speed, double max_turn_rate) const override {
    RobotVehicle<Vehicle>::limitSpeed(core_.run().drone[d].plant, U, max_speed, max_turn_rate);
  }

 private:
  static CrewTick crewTick(const typename Core::Tick& t) {
    CrewTick c;
    c.k = t.k, c.layer_ran = t.layer_ran, c.not_finite = t.not_finite;
    for (int d = 0; d < kRobots; ++d) c.ref[d] = t.ref[d], c.out[d] = t.out[d];
    return c;
  }

  Core core_;
};

// Robot r's delay in force: the request's when it gives one (>= 0), else
// the file's; refused naming the key when the run cannot hold it.
template <class Setup>
void requestedDelays(const CrewRequest& q, int robots, double Ts, long ticks, Setup&& robot) {
  for (size_t r = robots; r < q.delays.size(); ++r) {
    if (q.delays[r] >= 0) {
      throw ConfigError("parameter '" + q.delay_keys[r] + "' = " + std::to_string(q.delays[r]) +
                        " is refused: this formation has " + std::to_string(robots) + " robots (give -1)");
    }
  }
  for (int r = 0; r < robots; ++r) {
    long& delay = robot(r).delay;
    if (static_cast<size_t>(r) < q.delays.size() && q.delays[r] >= 0) delay = q.delays[r];
    try {
      refuseRobotDelay(robot(r).link, delay, r, ticks, Ts);
    } catch (const ConfigError& e) {
      const std::string key = static_cast<size_t>(r) < q.delay_keys.size() ? q.delay_keys[r] : "the file's delay";
      throw ConfigError("parameter '" + key + "' = " + std::to_string(delay) + ": " + e.what());
    }
  }
}

// The vehicle file each robot's entry names (formation.robots[i].vehicle,
// or the triangle's one formation.robots.vehicle), in the config folder;
// the shape's reader has checked them.
std::vector<std::string> namedVehicleFiles(const CrewRequest& q, int robots) {
  const YAML::Node n = YAML::LoadFile(q.file)["formation"]["robots"];
  std::vector<std::string> files;
  for (int r = 0; r < robots; ++r) {
    files.push_back(formation_detail::inConfig((n.IsSequence() ? n[r] : n)["vehicle"].as<std::string>(), q.config_dir));
  }
  return files;
}

std::unique_ptr<FormationCrew> lineCrew(const CrewRequest& q) {
  const FormationFile f = readFormationFile(q.file, q.config_dir);
  ArdroneLineRun run = formationRun(f, q.line_vehicle);
  const double Ts = q.line_vehicle.Ts;
  requestedDelays(q, 2, Ts, formationTicks(run.reference.duration, Ts), [&](int r) -> FormationDrone<double, aurora_control::ArdroneLawData>& {
    return run.drone[r];
  });
  const LawType law = f.drones[0].controller.law;
  return std::unique_ptr<FormationCrew>(new CrewOf<LineFormation<double>, ControllerSettings>(
      run, flyingLaw(law), "line", std::string(formationLawName(f.law)) + ", drones: " + aurora_control::lawName(law),
      {f.drones[0].name_space, f.drones[1].name_space}, {q.line_vehicle_file, q.line_vehicle_file},
      formationTicks(run.reference.duration, Ts)));
}

// The UAV-UGV line's robots: robot 1 the Pioneer, robot 2 the drone, in
// their file's namespaces (pioneer1, ardrone2 unless it names others).
std::unique_ptr<FormationCrew> uavUgvCrew(const CrewRequest& q) {
  UavUgvLineSetup setup = readUavUgvLineFile(q.file, q.config_dir);
  UavUgvRun run = uavUgvRun(setup);
  requestedDelays(q, 2, setup.tick, setup.ticks(), [&](int r) -> FormationDrone<double, UavUgvRobots::Data>& {
    return run.drone[r];
  });
  return std::unique_ptr<FormationCrew>(new CrewOf<UavUgvShape, LawSettings<UavUgvRobots>>(
      run, LawSettings<UavUgvRobots>(), "uav_ugv_line", "without integration; pioneer_dynamic and underactuated",
      {setup.name_space[0], setup.name_space[1]}, namedVehicleFiles(q, 2), setup.ticks()));
}

// The triangle's three AR.Drones (robots.namespaces; ardrone1 .. ardrone3
// unless the file names others); kinematic robots
// (the file names no vehicle) have no vehicle to simulate or drive.
std::unique_ptr<FormationCrew> triangleCrew(const CrewRequest& q) {
  const TriangleSetup setup = readTriangleFile(q.file, q.config_dir);
  if (setup.kinematic) {
    throw ConfigError("formation file '" + q.file + "': formation.robots names no vehicle: its robots are kinematic "
                      "(each at its reference), which only `flight --formation` flies; the formation node flies "
                      "vehicles: give robots.vehicle (config/formations/triangle_ardrones.yaml)");
  }
  TriangleRun<TriangleDroneLaw> run = triangleRun<TriangleDroneLaw>(setup);
  const long steps = triangleSteps(setup);
  requestedDelays(q, 3, setup.drone.Ts, steps, [&](int r) -> FormationDrone<double, aurora_control::ArdroneLawData>& { return run.drone[r]; });
  return std::unique_ptr<FormationCrew>(new CrewOf<Triangle, ControllerSettings>(
      run, flyingLaw(LawType::kUnderactuated), "triangle",
      std::string(triangleLawName(setup.law)) + ", drones: underactuated", {setup.name_space[0], setup.name_space[1], setup.name_space[2]},
      namedVehicleFiles(q, 3), steps));
}

}  // namespace

std::unique_ptr<FormationCrew> loadFormationCrew(const CrewRequest& q) {
  const std::string shape = formationShapeOf(q.file);
  if (shape == "uav_ugv_line") return uavUgvCrew(q);
  if (shape == "triangle") return triangleCrew(q);
  return lineCrew(q);  // its reader refuses an unknown shape
}

}  // namespace aurora_control
