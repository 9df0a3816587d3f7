// The lists by axis (docs/architecture.md, "Vehicles", "Shapes"): what is
// made from a list follows its entries, a test-only entry included. A list
// of vehicles with the test's point mass keeps a parameter set for it and
// finds it by name; a list of shapes with a test-only entry names it, and
// places it; the sweep's shapes, their names and their parameter tables are
// one per entry of the shapes' list.
#include <gtest/gtest.h>

#include <string>

#include "aurora_control/formation/shapes.h"
#include "aurora_sim/vehicle/vehicle_type.h"
#include "aurora_sweep/parameters.h"
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

}  // namespace
