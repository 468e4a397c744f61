#include "protocols/format/units.h"

#include <array>
#include <charconv>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "protocols/format/edit_distance.h"

namespace protocols {

namespace {

using D = Dimension;

// Conversion factors are exact definitions (SI brochure, 9th ed.; CGS units: 1 P = 0.1 Pa s,
// 1 St = 1e-4 m^2/s, 1 dyn/cm = 1e-3 N/m); standard gravity g = 9.80665 m/s^2 (CGPM 1901).
constexpr std::array kUnits = {
    Unit{"m", D::kLength, 1.0},
    Unit{"cm", D::kLength, 1e-2},
    Unit{"mm", D::kLength, 1e-3},
    Unit{"um", D::kLength, 1e-6},
    Unit{"\u00b5m", D::kLength, 1e-6},
    Unit{"s", D::kDuration, 1.0},
    Unit{"ms", D::kDuration, 1e-3},
    Unit{"min", D::kDuration, 60.0},
    Unit{"h", D::kDuration, 3600.0},
    Unit{"d", D::kDuration, 86400.0},
    Unit{"kg/m^3", D::kDensity, 1.0},
    Unit{"kg/m\u00b3", D::kDensity, 1.0},
    Unit{"g/cm^3", D::kDensity, 1e3},
    Unit{"g/cm\u00b3", D::kDensity, 1e3},
    Unit{"g/mL", D::kDensity, 1e3},
    Unit{"Pa s", D::kDynamicViscosity, 1.0},
    Unit{"Pa\u00b7s", D::kDynamicViscosity, 1.0},
    Unit{"mPa s", D::kDynamicViscosity, 1e-3},
    Unit{"mPa\u00b7s", D::kDynamicViscosity, 1e-3},
    Unit{"cP", D::kDynamicViscosity, 1e-3},
    Unit{"m^2/s", D::kKinematicViscosity, 1.0},
    Unit{"m\u00b2/s", D::kKinematicViscosity, 1.0},
    Unit{"mm^2/s", D::kKinematicViscosity, 1e-6},
    Unit{"mm\u00b2/s", D::kKinematicViscosity, 1e-6},
    Unit{"cSt", D::kKinematicViscosity, 1e-6},
    Unit{"St", D::kKinematicViscosity, 1e-4},
    Unit{"N/m", D::kSurfaceTension, 1.0},
    Unit{"mN/m", D::kSurfaceTension, 1e-3},
    Unit{"dyn/cm", D::kSurfaceTension, 1e-3},
    Unit{"Pa", D::kPressure, 1.0},
    Unit{"kPa", D::kPressure, 1e3},
    Unit{"MPa", D::kPressure, 1e6},
    Unit{"deg", D::kAngle, 3.14159265358979323846 / 180.0},
    Unit{"\u00b0", D::kAngle, 3.14159265358979323846 / 180.0},
    Unit{"rad", D::kAngle, 1.0},
    Unit{"%", D::kFraction, 1e-2},
    Unit{"m/s^2", D::kAcceleration, 1.0},
    Unit{"m/s\u00b2", D::kAcceleration, 1.0},
    Unit{"g", D::kAcceleration, 9.80665},
};

bool isSpace(char c) { return c == ' ' || c == '\t'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
  while (!s.empty() && isSpace(s.back())) s.remove_suffix(1);
  return s;
}

// Collapses runs of blanks to one space, so "Pa  s" reads as "Pa s".
std::string normaliseUnit(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (isSpace(c)) {
      if (!out.empty() && out.back() != ' ') out += ' ';
    } else {
      out += c;
    }
  }
  return out;
}

std::vector<std::string_view> symbolsOf(std::span<const Dimension> dimensions) {
  std::vector<std::string_view> symbols;
  for (const Unit& u : kUnits)
    for (Dimension d : dimensions)
      if (u.dimension == d) symbols.push_back(u.symbol);
  return symbols;
}

std::string unitsHint(std::span<const Dimension> allowed) {
  std::string text;
  for (Dimension d : allowed) {
    if (!text.empty()) text += "; ";
    text += std::string(dimensionName(d)) + " units: " + unitSymbols(d);
  }
  return text;
}

std::string dimensionsText(std::span<const Dimension> allowed) {
  std::string text;
  for (std::size_t k = 0; k < allowed.size(); ++k) {
    if (k > 0) text += k + 1 == allowed.size() ? " or " : ", ";
    text += dimensionName(allowed[k]);
  }
  return text;
}

std::string withArticle(const std::string& noun) {
  const bool vowel =
      !noun.empty() && std::string_view("aeiou").find(noun.front()) != std::string_view::npos;
  return (vowel ? "an " : "a ") + noun;
}

}  // namespace

std::span<const Unit> knownUnits() { return kUnits; }

const Unit* findUnit(std::string_view symbol) {
  for (const Unit& u : kUnits)
    if (u.symbol == symbol) return &u;
  return nullptr;
}

std::string_view dimensionName(Dimension dimension) {
  switch (dimension) {
    case D::kLength: return "length";
    case D::kDuration: return "duration";
    case D::kDensity: return "density";
    case D::kDynamicViscosity: return "dynamic viscosity";
    case D::kKinematicViscosity: return "kinematic viscosity";
    case D::kSurfaceTension: return "surface tension";
    case D::kPressure: return "pressure";
    case D::kAngle: return "angle";
    case D::kFraction: return "fraction";
    case D::kAcceleration: return "acceleration";
  }
  return "?";
}

std::string_view siUnit(Dimension dimension) {
  switch (dimension) {
    case D::kLength: return "m";
    case D::kDuration: return "s";
    case D::kDensity: return "kg/m^3";
    case D::kDynamicViscosity: return "Pa s";
    case D::kKinematicViscosity: return "m^2/s";
    case D::kSurfaceTension: return "N/m";
    case D::kPressure: return "Pa";
    case D::kAngle: return "rad";
    case D::kFraction: return "";
    case D::kAcceleration: return "m/s^2";
  }
  return "?";
}

std::string unitSymbols(Dimension dimension) {
  const std::array dims = {dimension};
  return joinNames(symbolsOf(dims));
}

UnitError::UnitError(std::string what, std::string fix)
    : std::invalid_argument(fix.empty() ? what : what + " \u2014 " + fix),
      problem_(std::move(what)),
      fix_(std::move(fix)) {}

Quantity parseQuantity(std::string_view text, std::span<const Dimension> allowed) {
  const std::string quoted = fmt::format("\"{}\"", text);
  const std::string_view body = trim(text);
  // std::from_chars takes the longest number prefix ("12mm" -> 12, rest "mm"); it accepts no
  // leading '+', which we allow by skipping it.
  std::string_view digits = body;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  double number = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), number);
  const std::string example = "e.g. \"12 " + std::string(symbolsOf(allowed).front()) + "\"";
  if (ec != std::errc() || !std::isfinite(number))
    throw UnitError(quoted + " does not start with a finite number",
                    "write a number then a unit, " + example);
  const std::string unit =
      normaliseUnit(trim(std::string_view(end, digits.data() + digits.size())));

  if (unit.empty()) {
    // A bare number is unambiguous only for a fraction, and only in [0, 1]: "90" might mean 90 %.
    for (Dimension d : allowed) {
      if (d != D::kFraction) continue;
      if (number < 0.0 || number > 1.0)
        throw UnitError(
            quoted + " is not a fraction in [0, 1]",
            "write a fraction like 0.9, or a percentage like \"" + std::string(body) + " %\"");
      return {number, D::kFraction};
    }
    throw UnitError(
        quoted + " has no unit, and " + withArticle(dimensionsText(allowed)) + " needs one",
        "add a unit, " + example + " (" + unitsHint(allowed) + ")");
  }

  const Unit* u = findUnit(unit);
  if (u == nullptr) {
    std::vector<std::string_view> candidates = symbolsOf(allowed);
    std::string suggestion = didYouMean(unit, candidates);
    if (suggestion.empty()) {  // maybe a unit of another dimension was misspelt
      std::vector<std::string_view> all;
      for (const Unit& k : kUnits) all.push_back(k.symbol);
      suggestion = didYouMean(unit, all);
    }
    throw UnitError(
        "unknown unit '" + unit + "' in " + quoted,
        (suggestion.empty() ? std::string() : suggestion + " ") + "(" + unitsHint(allowed) + ")");
  }
  for (Dimension d : allowed)
    if (u->dimension == d) return {number * u->toSi, d};
  throw UnitError("'" + unit + "' in " + quoted + " is a unit of " +
                      std::string(dimensionName(u->dimension)) + ", but " +
                      withArticle(dimensionsText(allowed)) + " is expected",
                  unitsHint(allowed));
}

double parseQuantity(std::string_view text, Dimension expected) {
  const std::array allowed = {expected};
  return parseQuantity(text, allowed).value;
}

std::string formatQuantity(double siValue, Dimension dimension) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), siValue);
  std::string text(buffer.data(), result.ptr);
  const std::string_view unit = siUnit(dimension);
  if (!unit.empty()) text += fmt::format(" {}", unit);
  return text;
}

std::string formatIn(double siValue, std::string_view unitSymbol) {
  const Unit* u = findUnit(unitSymbol);
  const double value = u != nullptr ? siValue / u->toSi : siValue;
  std::array<char, 32> buffer{};
  // %g-style with 6 significant digits: messages should read "23.5 mm", not "23.499999999 mm".
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                    std::chars_format::general, 6);
  std::string text(buffer.data(), result.ptr);
  if (!unitSymbol.empty()) text += fmt::format("{}{}", unitSymbol == "%" ? "" : " ", unitSymbol);
  return text;
}

}  // namespace protocols
