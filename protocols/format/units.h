// Quantities with units, the way clinicians write them ("12 mm", "1000 cSt", "40 mN/m",
// "100 kPa"), converted to SI (docs/developer-guide.md principle 5: SI inside, clinical units at
// the edge).
//
// Dynamic and kinematic viscosity are DIFFERENT dimensions: users of other SPH codes are
// regularly unsure which one a number means, so a protocol says it with the unit and
// a kinematic value is turned into a dynamic one with the density later (mu = rho nu).
#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace protocols {

enum class Dimension {
  kLength,              // [m]
  kDuration,            // [s]
  kDensity,             // [kg/m^3]
  kDynamicViscosity,    // [Pa s]
  kKinematicViscosity,  // [m^2/s]
  kSurfaceTension,      // [N/m]
  kPressure,            // [Pa] (also elastic moduli)
  kAngle,               // [rad]
  kFraction,            // [1], a bare number or a percentage
  kAcceleration,        // [m/s^2]
};

struct Unit {
  std::string_view symbol;  // as written in a protocol, case-sensitive ("mPa s" is not "MPa s")
  Dimension dimension;
  double toSi;  // SI value of one of this unit
};

// Every unit a protocol may use, grouped by dimension; the docs' unit table is generated from it.
std::span<const Unit> knownUnits();
const Unit* findUnit(std::string_view symbol);

std::string_view dimensionName(Dimension dimension);  // "length", "dynamic viscosity", ...
std::string_view siUnit(Dimension dimension);         // "m", "Pa s", "1", ...
// The unit symbols of one dimension, comma separated: "m, cm, mm, um".
std::string unitSymbols(Dimension dimension);

// A quantity text that cannot be read. what() is "what is wrong — how to fix it"; the parts are
// kept apart so the protocol loader can prefix the key and file position.
class UnitError : public std::invalid_argument {
 public:
  UnitError(std::string what, std::string fix);
  const std::string& problem() const { return problem_; }
  const std::string& fix() const { return fix_; }

 private:
  std::string problem_;
  std::string fix_;
};

struct Quantity {
  double value;  // [SI unit of dimension]
  Dimension dimension;
};

// Reads "<number> [unit]" into SI. A bare number is accepted only for kFraction (in [0, 1]); a
// unit of another dimension, an unknown unit (with the nearest known ones suggested) or a
// missing number throw UnitError.
double parseQuantity(std::string_view text, Dimension expected);
// Same, when several dimensions are acceptable and the unit decides which one it is (viscosity).
Quantity parseQuantity(std::string_view text, std::span<const Dimension> allowed);

// "0.0235 m", "0.9", "1.2e+06 Pa": a SI value with its SI unit, shortest round-trip digits.
std::string formatQuantity(double siValue, Dimension dimension);
// The value in a given unit, for messages in the user's units: "23.5 mm".
std::string formatIn(double siValue, std::string_view unitSymbol);

}  // namespace protocols
