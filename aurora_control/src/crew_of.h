// What every shape's crew (formation_crew.h) is built from: CrewOf, a
// shape's FormationController behind FormationCrew; RobotVehicle, a robot's
// vehicle as the launch starts it; requestedDelays, the node's delays over
// the file's. Private to the crews' sources (formation_crew.cpp and each
// shape's own crew file).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "aurora_common/number_text.h"
#include "aurora_control/formation/formation_checks.h"
#include "aurora_control/formation/formation_crew.h"
#include "aurora_control/formation/formation_flight.h"
#include "aurora_control/params/limits.h"
#include "aurora_sim/vehicle/vehicle_type.h"  // every vehicle with its SimProfile

namespace aurora_control {

namespace crew_detail {

// What a robot's vehicle file says beyond its vehicle's constants, which
// the formation file may change: its vehicle's fileChoices (a Pioneer's
// model), where it declares them.
template <class Vehicle>
auto fileChoices(const typename Vehicle::template Params<double>& p, CrewRobot& r, int)
    -> decltype(Vehicle::fileChoices(p), void()) {
  for (const auto& choice : Vehicle::fileChoices(p)) r.vehicle_overrides.push_back(choice);
}
template <class Vehicle>
void fileChoices(const typename Vehicle::template Params<double>&, CrewRobot&, long) {}

// A robot's vehicle as the launch starts it, and its driver's command.

template <class Vehicle>
struct RobotVehicle {
  static void describe(const typename Vehicle::template Params<double>& p, CrewRobot& r) {
    fileChoices<Vehicle>(p, r, 0);
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

}  // namespace crew_detail

}  // namespace aurora_control
