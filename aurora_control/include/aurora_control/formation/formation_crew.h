// Any formation file's robots as the formation node flies them, ROS-free
// (docs/formation.md, "In the ROS loop"): the two-drone line, the UAV-UGV
// line (a Pioneer P3-DX with an AR.Drone) and the triangle of three
// AR.Drones, each a FormationController of its shape and crew behind one
// interface. The node, its flight sequence and its tests see robots, their
// namespaces and vehicles, the shape's variables, and each tick.
#pragma once

#include <memory>
#include <string>
#include <typeinfo>
#include <vector>

#include "aurora_control/formation/formation_controller.h"
#include "aurora_control/formation/formation_document.h"
#include "aurora_control/formation/shapes.h"  // kMaxCrew: the list's largest shape's robots
#include "aurora_sim/command_mapping.h"

namespace aurora_control {

// What tick k gave each robot (FormationController::Tick of any shape).
struct CrewTick {
  long k = 0;
  bool layer_ran = false;
  int not_finite = -1;  // the first robot whose law gave a non-finite command: every robot hovers instead
  Reference<double> ref[kMaxCrew];
  ControlOutput out[kMaxCrew];  // each robot's command, its vehicle's kInputs first
};

// A robot as the launch starts it: its namespace, its vehicle (the type
// name of its vehicle file, e.g. ardrone2, pioneer3dx), that file and what
// the formation file changes in it (every robot steps at the formation's
// tick; a Pioneer's kinematic_model), whether it drives on the floor, and
// its start [m].
struct CrewRobot {
  std::string name_space, vehicle, vehicle_file;
  std::vector<std::pair<std::string, std::string>> vehicle_overrides;  // key, YAML value
  bool ground = false;
  long delay = 0;  // [samples] its uplink delay in force
  double start[3] = {0, 0, 0};
};

class FormationCrew {
 public:
  virtual ~FormationCrew() = default;

  const std::string& shape() const { return shape_; }      // line, uav_ugv_line, triangle
  const std::string& lawName() const { return law_name_; }  // the layer's law, and the robots' laws
  int robots() const { return static_cast<int>(robots_.size()); }
  const CrewRobot& robot(int d) const { return robots_[d]; }
  double sampleTime() const { return Ts_; }  // [s] the robots' step
  long ticks() const { return ticks_; }      // the formation's ticks are 0 .. ticks() - 1 (flight --formation's)

  virtual int variables() const = 0;
  virtual const char* variableName(int i) const = 0;
  virtual bool push(int d, const StateSample& s) = 0;
  virtual long commonStep() const = 0;
  virtual bool ready(int d) const = 0;
  virtual const StateSample& newest(int d) const = 0;
  virtual void newestPositions(double* X) const = 0;  // 3 per robot (every robot ready)
  virtual CrewTick tick(long k) = 0;
  virtual void startFrom(const double* X0) = 0;
  virtual ControlOutput hold(int d, const double p[3]) = 0;
  virtual ControlOutput hover(int d) = 0;
  // The layer: Q of the positions it saw at its last run, Qd held, Qtil.
  virtual const double* Q() const = 0;
  virtual const double* Qd() const = 0;
  virtual const double* Qtil() const = 0;
  virtual const double* heldPosition(int d) const = 0;  // robot d's reference [m]
  // The shape's formulas on positions (3 per robot): Q of X, the positions
  // of Q, and the formation checks' errors of X against Xd [m].
  virtual void variablesOf(const double* X, double* Q) const = 0;
  virtual void positionsOf(const double* Q, double* X) const = 0;
  virtual void errors(const double* X, const double* Xd, double& position, double& shape) const = 0;
  // Robot d's command as its driver's cmd_vel.
  virtual aurora_sim::TwistCommand toDriver(int d, const double* U) const = 0;
  // A real robot's speed limits on U, as its safety file gives them (its
  // vehicle's: a ground robot's forward speed and turn rate; a drone's none).
  virtual void limitSpeed(int d, double* U, double max_speed, double max_turn_rate) const = 0;

 protected:
  std::string shape_, law_name_;
  std::vector<CrewRobot> robots_;
  double Ts_ = 1.0 / 30.0;
  long ticks_ = 0;
};

// The vehicle given to the robots of a shape whose file names none (its
// entry's UnnamedVehicle, shapes.h: the two-drone line's AR.Drones): its
// parameters as the node (~vehicle) or formation_robot (--vehicle) loaded
// them, and the file they came from ("" for the node's parameters).
class GivenVehicle {
 public:
  template <class Vehicle>
  void set(const typename Vehicle::template Params<double>& p, const std::string& file = "") {
    params_ = std::make_shared<const typename Vehicle::template Params<double>>(p);
    type_ = &typeid(Vehicle);
    name_ = Vehicle::name();
    file_ = file;
  }
  // Refused when none, or another vehicle's, was given.
  template <class Vehicle>
  const typename Vehicle::template Params<double>& get(const std::string& shape) const {
    if (!params_ || *type_ != typeid(Vehicle)) {
      throw ConfigError("the " + shape + " formation's file names no vehicle: its robots fly the " +
                        std::string(Vehicle::name()) + " vehicle file given to the formation node (~vehicle) or to "
                        "formation_robot (--vehicle), and " + (params_ ? "a " + name_ + "'s" : std::string("none")) +
                        " was given");
    }
    return *static_cast<const typename Vehicle::template Params<double>*>(params_.get());
  }
  const std::string& file() const { return file_; }

 private:
  std::shared_ptr<const void> params_;
  const std::type_info* type_ = nullptr;
  std::string name_, file_;
};

// What the node gives the reader: the formation file, the config folder
// its paths are in, the vehicle of robots whose file names none, each
// robot's delay (-1: the file's) and the parameter keys they came from
// (named in refusals).
struct CrewRequest {
  std::string file, config_dir;
  GivenVehicle vehicle;
  std::vector<long> delays;
  std::vector<std::string> delay_keys;
};

// The file's robots as a crew; refuses (ConfigError, naming the key) a
// file that cannot fly in the ROS loop (the triangle's kinematic robots),
// a delay for a robot the shape has not, or a delay the run cannot hold.
// The second form reads request.file; the first takes it read (the node
// reads its shape first: formation_document.h).
std::unique_ptr<FormationCrew> loadFormationCrew(const CrewRequest& request, const FormationDocument& file);
std::unique_ptr<FormationCrew> loadFormationCrew(const CrewRequest& request);

}  // namespace aurora_control
