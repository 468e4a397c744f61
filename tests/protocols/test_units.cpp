// Units: clinical quantities to SI, and the messages for the ones that cannot be read.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <string>

#include "protocols/format/edit_distance.h"
#include "protocols/format/units.h"

using protocols::Dimension;
using protocols::parseQuantity;
using protocols::UnitError;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct GoodQuantity {
  const char* text;
  Dimension dimension;
  double si;  // expected value in SI
};

// Expected values are the exact definitions of the units (SI brochure; 1 cP = 1 mPa s,
// 1 cSt = 1 mm^2/s, 1 dyn/cm = 1 mN/m, g = 9.80665 m/s^2).
const GoodQuantity kGood[] = {
    {"12 mm", Dimension::kLength, 0.012},
    {"12mm", Dimension::kLength, 0.012},
    {"  23.5   mm ", Dimension::kLength, 0.0235},
    {"1.5 cm", Dimension::kLength, 0.015},
    {"300 um", Dimension::kLength, 300e-6},
    {"+2 m", Dimension::kLength, 2.0},
    {"0.5 s", Dimension::kDuration, 0.5},
    {"250 ms", Dimension::kDuration, 0.25},
    {"10 min", Dimension::kDuration, 600.0},
    {"2 h", Dimension::kDuration, 7200.0},
    {"7 d", Dimension::kDuration, 604800.0},
    {"1e-4 s", Dimension::kDuration, 1e-4},
    {"970 kg/m^3", Dimension::kDensity, 970.0},
    {"1.06 g/cm^3", Dimension::kDensity, 1060.0},
    {"0.97 g/mL", Dimension::kDensity, 970.0},
    {"970 mPa s", Dimension::kDynamicViscosity, 0.97},
    {"970 mPa\u00b7s", Dimension::kDynamicViscosity, 0.97},
    {"5 Pa s", Dimension::kDynamicViscosity, 5.0},
    {"5 Pa\u00b7s", Dimension::kDynamicViscosity, 5.0},
    {"1400 cP", Dimension::kDynamicViscosity, 1.4},
    {"1000 cSt", Dimension::kKinematicViscosity, 1e-3},
    {"5000 mm^2/s", Dimension::kKinematicViscosity, 5e-3},
    {"1e-3 m^2/s", Dimension::kKinematicViscosity, 1e-3},
    {"10 St", Dimension::kKinematicViscosity, 1e-3},
    {"40 mN/m", Dimension::kSurfaceTension, 0.04},
    {"40 dyn/cm", Dimension::kSurfaceTension, 0.04},
    {"0.05 N/m", Dimension::kSurfaceTension, 0.05},
    {"100 kPa", Dimension::kPressure, 1e5},
    {"2 MPa", Dimension::kPressure, 2e6},
    {"500 Pa", Dimension::kPressure, 500.0},
    {"180 deg", Dimension::kAngle, kPi},
    {"18 \u00b0", Dimension::kAngle, 18.0 * kPi / 180.0},
    {"1 rad", Dimension::kAngle, 1.0},
    {"90 %", Dimension::kFraction, 0.9},
    {"90%", Dimension::kFraction, 0.9},
    {"0.9", Dimension::kFraction, 0.9},
    {"1", Dimension::kFraction, 1.0},
    {"1 g", Dimension::kAcceleration, 9.80665},
    {"9.81 m/s^2", Dimension::kAcceleration, 9.81},
};

struct BadQuantity {
  const char* text;
  Dimension dimension;
  std::array<const char*, 2> fragments;  // both must be in the message
};

const BadQuantity kBad[] = {
    {"12", Dimension::kLength, {"has no unit", "length units: m, cm, mm"}},
    {"18", Dimension::kAngle, {"has no unit", "deg"}},
    {"12 kPa",
     Dimension::kLength,
     {"'kPa' in \"12 kPa\" is a unit of pressure", "but a length is expected"}},
    {"1000 cSt",
     Dimension::kDynamicViscosity,
     {"is a unit of kinematic viscosity", "but a dynamic viscosity is expected"}},
    {"970 mPa s", Dimension::kKinematicViscosity, {"unit of dynamic viscosity", "kinematic"}},
    {"90 %", Dimension::kLength, {"unit of fraction", "length"}},
    {"12 mmm", Dimension::kLength, {"unknown unit 'mmm'", "did you mean 'mm'?"}},
    {"40 mn/m", Dimension::kSurfaceTension, {"unknown unit 'mn/m'", "did you mean 'mN/m'"}},
    {"100 kpa", Dimension::kPressure, {"unknown unit 'kpa'", "did you mean 'kPa'"}},
    {"12 parsecs", Dimension::kLength, {"unknown unit 'parsecs'", "length units"}},
    {"mm", Dimension::kLength, {"does not start with a finite number", "e.g. \"12 m\""}},
    {"", Dimension::kLength, {"does not start with a finite number", "write a number then a unit"}},
    {"inf mm", Dimension::kLength, {"finite number", "unit"}},
    {"1e999 mm", Dimension::kLength, {"finite number", "unit"}},
    {"90", Dimension::kFraction, {"not a fraction in [0, 1]", "\"90 %\""}},
    {"-0.1", Dimension::kFraction, {"not a fraction in [0, 1]", "0.9"}},
};

}  // namespace

TEST_CASE("quantities with units convert to SI", "[unit][units]") {
  for (const GoodQuantity& q : kGood) {
    INFO(q.text);
    // One multiplication of a decimal number by an exact factor: a few ulp at most.
    CHECK(parseQuantity(q.text, q.dimension) == Approx(q.si).epsilon(1e-12));
  }
}

TEST_CASE("unreadable quantities say what is wrong and how to fix it", "[unit][units]") {
  for (const BadQuantity& q : kBad) {
    INFO(q.text);
    try {
      (void)parseQuantity(q.text, q.dimension);
      FAIL("accepted \"" << q.text << "\"");
    } catch (const UnitError& e) {
      const std::string message = e.what();
      INFO(message);
      for (const char* fragment : q.fragments) CHECK(message.find(fragment) != std::string::npos);
    }
  }
}

TEST_CASE("viscosity: the unit decides dynamic or kinematic", "[unit][units]") {
  const std::array allowed = {Dimension::kDynamicViscosity, Dimension::kKinematicViscosity};
  const auto kinematic = parseQuantity("1000 cSt", allowed);
  CHECK(kinematic.dimension == Dimension::kKinematicViscosity);
  CHECK(kinematic.value == Approx(1e-3).epsilon(1e-12));
  const auto dynamic = parseQuantity("970 mPa s", allowed);
  CHECK(dynamic.dimension == Dimension::kDynamicViscosity);
  CHECK(dynamic.value == Approx(0.97).epsilon(1e-12));
  CHECK_THROWS_WITH(parseQuantity("1000", allowed), Catch::Contains("has no unit"));
  CHECK_THROWS_WITH(parseQuantity("40 mN/m", allowed),
                    Catch::Contains("dynamic viscosity or kinematic viscosity is expected"));
}

TEST_CASE("every unit converts back to itself and belongs to one dimension", "[unit][units]") {
  for (const protocols::Unit& u : protocols::knownUnits()) {
    INFO(u.symbol);
    CHECK(protocols::findUnit(u.symbol) == &u);  // symbols are unique
    CHECK(u.toSi > 0.0);
    CHECK(parseQuantity("2 " + std::string(u.symbol), u.dimension) ==
          Approx(2.0 * u.toSi).epsilon(1e-15));
  }
}

TEST_CASE("edit distance and did-you-mean", "[unit][units]") {
  CHECK(protocols::editDistance("kitten", "sitting") == 3);  // the textbook example
  CHECK(protocols::editDistance("", "abc") == 3);
  CHECK(protocols::editDistance("same", "same") == 0);
  const std::array<std::string_view, 3> names = {"axial_length", "side", "kind"};
  CHECK(protocols::didYouMean("axial_lenght", names) == "did you mean 'axial_length'?");
  CHECK(protocols::didYouMean("completely_different", names).empty());
  const std::array<std::string_view, 2> sides = {"OD", "OS"};
  CHECK(protocols::didYouMean("od", sides) == "did you mean 'OD'?");
  CHECK(protocols::didYouMean("OX", sides) == "did you mean 'OD' or 'OS'?");
}
