// The lists by axis (docs/architecture.md, "Vehicles", "Shapes"): what is
// made from a list follows its entries, a test-only entry included. A list
// of vehicles with the test's point mass keeps a parameter set for it and
// finds it by name; a list of shapes with a test-only entry names it, and
// places it; the sweep's shapes, their names and their parameter tables are
// one per entry of the shapes' list.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "aurora_control/formation/shapes.h"
#include "aurora_sim/vehicle/vehicle_type.h"
#include "aurora_sweep/parameters.h"
#include "aurora_sweep/robot_gains.h"
#include "aurora_sweep/sweep_spec.h"
#include "point_mass.h"

namespace {

using namespace aurora_sweep;

// A shape entry defined here only: its name and robots (what the lists read).
struct FourInARowEntry {
  static constexpr int kRobots = 4;
  static const char* name() { return "four_in_a_row"; }
};

TEST(Registry, AVehicleListWithATestVehicleKeepsItsParametersByName) {
  using Vehicles = aurora_common::TypeList<aurora_sim::Ardrone2, point_mass::PointMass>;
  aurora_sim::VehicleParamsOf<Vehicles> set{};
  set.of<point_mass::PointMass>().Ts = 0.5;
  set.of<aurora_sim::Ardrone2>().Ts = 0.2;
  double Ts = 0.0;
  EXPECT_TRUE(set.withType("point_mass", [&](const auto& p) { Ts = p.Ts; }));
  EXPECT_DOUBLE_EQ(Ts, 0.5);
  EXPECT_TRUE(set.withType("ardrone2", [&](const auto& p) { Ts = p.Ts; }));
  EXPECT_DOUBLE_EQ(Ts, 0.2);
  EXPECT_FALSE(set.withType("bebop2", [](const auto&) { ADD_FAILURE() << "bebop2 is not in the test's list"; }));
  std::string names;
  aurora_common::forEachType(Vehicles(), [&](auto v) { names += std::string(v.name()) + " "; });
  EXPECT_EQ(names, "ardrone2 point_mass ");
}

TEST(Registry, AShapeListWithATestShapeNamesAndPlacesIt) {
  using Shapes = aurora_common::TypeList<aurora_control::LineShapeEntry, FourInARowEntry>;
  EXPECT_EQ(aurora_common::typeIndexIn<FourInARowEntry>(Shapes()), 1);
  EXPECT_EQ(aurora_common::typeIndexIn<aurora_control::LineShapeEntry>(Shapes()), 0);
  EXPECT_EQ(aurora_common::typeIndexIn<aurora_control::TriangleShapeEntry>(Shapes()), -1);
  const auto each = [](auto&& f) { aurora_common::forEachType(Shapes(), f); };
  EXPECT_EQ(aurora_common::entryNames(each), "line, four_in_a_row");
  int robots = 0;
  EXPECT_TRUE(aurora_common::withEntryNamed(each, "four_in_a_row", [&](auto e) { robots = decltype(e)::kRobots; }));
  EXPECT_EQ(robots, 4);
  EXPECT_FALSE(aurora_common::isEntryName(each, "triangle"));
}

// Each entry of the shapes' list is a sweep shape of its own: its name in
// the records, its robots' delays and its gains in its table, its
// formation_law only where it has laws a sweep varies.
TEST(Registry, TheSweepsShapesAreTheShapesList) {
  EXPECT_EQ(kSweepShapeCount, 1 + int(aurora_control::KnownShapes::kCount));
  EXPECT_STREQ(sweepShapeName(SweepShape::kNone), "none");
  int entries = 0;
  aurora_control::forEachShape([&](auto e) {
    using E = decltype(e);
    const SweepShape shape = sweepShapeOf<E>();
    EXPECT_EQ(static_cast<int>(shape), ++entries);
    EXPECT_STREQ(sweepShapeName(shape), E::name());
    SweepSpec spec;
    spec.shape = shape;
    const ShapeLayout at = spec.layout();
    EXPECT_EQ(at.robots, int(E::kRobots)) << E::name();
    for (int d = 0; d < at.robots; ++d) {
      EXPECT_EQ(paramInfo(at.delay(d), shape).name, "delay_" + std::to_string(d + 1)) << E::name();
    }
    EXPECT_EQ(paramInfo(kParamFormationLaw, shape).group == ParamGroup::kFormationLaw, E::kSweepLaws > 0) << E::name();
    EXPECT_EQ(spec.variesFormationLaw(), E::kSweepLaws > 0) << E::name();
    bool flown = false;
    spec.withFormation([&](const auto& run, auto) {
      flown = static_cast<const void*>(&run) == static_cast<const void*>(&spec.run<E>());
    });
    EXPECT_TRUE(flown) << E::name() << ": withFormation flies another entry's run";
  });
  EXPECT_EQ(entries, int(aurora_control::KnownShapes::kCount));
}

// A law appended to the laws' list (here the test's point-mass law) takes
// its gains' block after every parameter there was: no law's block, no
// formation parameter, no robot gain moves (records and definition hashes
// stay); its rows as a formation robot are its own declaration's.
template <class... L>
using Appended = aurora_common::TypeList<L..., point_mass::PointPd>;
template <class... L>
Appended<L...> appendTo(aurora_common::TypeList<L...>) {
  return {};
}
using LawsAndPoint = decltype(appendTo(aurora_control::KnownLaws()));

TEST(Registry, ALawAppendedToTheListTakesItsGainsAfterEveryOlderParameter) {
  const int first = lawGainFirst<point_mass::PointPd>(LawsAndPoint());
  EXPECT_GE(first, kParamRobotGainEnd);  // after the robots' gains
  EXPECT_EQ(first, kParamCount);         // the room a build with it would add
  EXPECT_EQ(lawGainPlace(LawsAndPoint(), 0), kParamCount + point_mass::PointPd::kGainCount);
  aurora_control::forEachLaw([&](auto law) {  // the AR.Drone's two as every other
    using Law = decltype(law);
    EXPECT_EQ(lawGainFirst<Law>(LawsAndPoint()), LawGainBlock<Law>::kFirst) << Law::name();
    for (int i = 0; i < Law::kGainCount; ++i) {  // each row where the table names it
      EXPECT_EQ(paramInfo(LawGainBlock<Law>::kFirst + i, SweepShape::kNone).name, Law::gainRow(i).name);
      EXPECT_EQ(paramInfo(LawGainBlock<Law>::kFirst + i, SweepShape::kNone).law, Law::name());
    }
  });
  EXPECT_EQ(lawGainFirst<point_mass::PointPd>(aurora_control::KnownLaws()), -1);
  const auto rows = RobotGains<point_mass::PointPd>::rows(point_mass::Params<double>{});
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_STREQ(rows[0].name, "kp");
  EXPECT_STREQ(rows[1].name, "kd");
  point_mass::Gains<double> g{1.0, 2.0};
  const double block[2] = {5.0, std::nan("")};  // a gain the sweep does not give keeps its value
  RobotGains<point_mass::PointPd>::set(g, point_mass::Params<double>{}, block);
  EXPECT_EQ(g.kp, 5.0);
  EXPECT_EQ(g.kd, 2.0);
}

// The laws' own blocks where the records of every shipped study have them
// (the AR.Drone's kp, kd before the delay and its underactuated law's 12
// after it; the Bebop 2 compensator's from the first law gain, then the
// Pioneer's).
TEST(Registry, TheListedLawsBlocksAreWhereTheirRecordsHaveThem) {
  using aurora_control::ArdroneLaw;
  using aurora_control::LawType;
  EXPECT_EQ(LawGainBlock<ArdroneLaw<LawType::kPdSaturated>>::kFirst, kParamKp);
  EXPECT_EQ(LawGainBlock<ArdroneLaw<LawType::kPdSaturated>>::kFirst + 1, kParamKd);
  EXPECT_EQ(LawGainBlock<ArdroneLaw<LawType::kUnderactuated>>::kFirst, kParamFirstUnderactuatedGain);
  EXPECT_EQ(LawGainBlock<ArdroneLaw<LawType::kUnderactuated>>::kCount, kUnderactuatedGainCount);
  EXPECT_EQ(LawGainBlock<aurora_control::Bebop2Compensator>::kFirst, kParamFirstLawGain);
  EXPECT_EQ(LawGainBlock<aurora_control::PioneerDynamic>::kFirst, kParamFirstLawGain + 10);
  EXPECT_EQ(LawGainBlock<aurora_control::PioneerKinematic>::kFirst, kParamFirstLawGain + 16);
  EXPECT_EQ(kParamFormationLaw, kParamFirstLawGain + 18);
  EXPECT_EQ(kParamFirstRobotGain, 92);
  EXPECT_EQ(kParamCount, 128);
}

}  // namespace
