// Material library: all required fields with sources, values equal to the reference data
// (reference-data.md sections 1, 2, 5, as copied into
// data/materials/materials.csv), the shipped file equals the built-in table, bad rows rejected.
#include <catch2/catch.hpp>

#include <string>

#include "anatomy/anatomy_error.h"
#include "anatomy/material_library.h"

using namespace anatomy;

namespace {

struct Expected {
  const char* name;
  MaterialKind kind;
  double density;        // [kg/m^3]
  double viscosity;      // [Pa s], 0 = not applicable
  double tension;        // [N/m], 0 = not applicable
  double contactAngle;   // [deg] through the aqueous, 0 = not applicable
  double youngsModulus;  // [Pa], 0 = not applicable
  double poissonRatio;   // [1], 0 = not applicable
};

// Reference values (reference-data.md): 1.1 table defaults, 2 Fawcett 1994, 5 tissue table.
constexpr Expected kExpected[] = {
    {"aqueous", MaterialKind::kFluid, 1004, 0.72e-3, 0, 0, 0, 0},
    {"silicone_oil_1000", MaterialKind::kFluid, 970, 1.0, 0.040, 18.2, 0, 0},
    {"silicone_oil_5000", MaterialKind::kFluid, 970, 5.0, 0.040, 18.2, 0, 0},
    {"densiron_68", MaterialKind::kFluid, 1060, 1.4, 0.040, 18, 0, 0},
    {"oxane_hd", MaterialKind::kFluid, 1030, 3.8, 0.042, 18, 0, 0},
    {"perfluoro_n_octane", MaterialKind::kFluid, 1766, 0.8e-3, 0.050, 18, 0, 0},
    {"sclera", MaterialKind::kTissue, 1050, 0, 0, 0, 1.8e6, 0.47},
    {"orbital_fat", MaterialKind::kTissue, 920, 0, 0, 0, 870, 0.49},
};

void checkValue(const std::optional<SourcedValue>& v, double expected, const char* field) {
  INFO(field);
  if (expected == 0.0) {
    CHECK_FALSE(v.has_value());
    return;
  }
  REQUIRE(v.has_value());
  CHECK(v->value == expected);  // exact: the same decimal literal
  CHECK(v->source.size() > 10);
}

bool sameValue(const std::optional<SourcedValue>& a, const std::optional<SourcedValue>& b) {
  if (a.has_value() != b.has_value()) return false;
  return !a || (a->value == b->value && a->flag == b->flag && a->source == b->source);
}

}  // namespace

TEST_CASE("every material has its required fields, a source and the reference value",
          "[unit][materials]") {
  const MaterialLibrary& library = MaterialLibrary::builtin();
  CHECK(library.materials().size() == std::size(kExpected));
  for (const Expected& e : kExpected) {
    INFO(e.name);
    REQUIRE(library.contains(e.name));
    const MaterialRecord& m = library.find(e.name);
    CHECK(m.kind == e.kind);
    checkValue(m.density, e.density, "density");
    checkValue(m.dynamicViscosity, e.viscosity, "dynamic viscosity");
    checkValue(m.interfacialTension, e.tension, "interfacial tension");
    checkValue(m.contactAngle, e.contactAngle, "contact angle");
    checkValue(m.youngsModulus, e.youngsModulus, "Young's modulus");
    checkValue(m.poissonRatio, e.poissonRatio, "Poisson ratio");
  }
  // Kinematic viscosity of SO 1000: 1.0 Pa s / 970 kg/m^3 = 1.03e-3 m^2/s (reference-data 1.1).
  CHECK(library.find("silicone_oil_1000").kinematicViscosity() == Approx(1.0309e-3).epsilon(1e-4));
  // Provenance flags as in the reference: Fawcett's angle sourced, heavy-oil tension unsourced.
  CHECK(library.find("silicone_oil_1000").contactAngle->flag == Provenance::kSourced);
  CHECK(library.find("densiron_68").interfacialTension->flag == Provenance::kUnsourced);
  CHECK(library.find("orbital_fat").youngsModulus->flag == Provenance::kDerived);
  CHECK_THROWS_WITH(library.find("silicone_oil_2000"),
                    Catch::Contains("no material named 'silicone_oil_2000'") &&
                        Catch::Contains("silicone_oil_1000"));
  CHECK_THROWS_AS(library.find("sclera").kinematicViscosity(), AnatomyError);
}

TEST_CASE("the shipped data file is the built-in table", "[unit][materials]") {
  const MaterialLibrary file = MaterialLibrary::loadCsv(TAMPONADE_MATERIALS_CSV);
  const MaterialLibrary& builtin = MaterialLibrary::builtin();
  REQUIRE(file.materials().size() == builtin.materials().size());
  for (size_t i = 0; i < file.materials().size(); ++i) {
    const MaterialRecord& a = file.materials()[i];
    const MaterialRecord& b = builtin.materials()[i];
    CHECK(a.name == b.name);
    CHECK(sameValue(a.density, b.density));
    CHECK(sameValue(a.dynamicViscosity, b.dynamicViscosity));
    CHECK(sameValue(a.interfacialTension, b.interfacialTension));
    CHECK(sameValue(a.contactAngle, b.contactAngle));
    CHECK(sameValue(a.youngsModulus, b.youngsModulus));
    CHECK(sameValue(a.poissonRatio, b.poissonRatio));
  }
}

TEST_CASE("bad material rows are rejected with file:line and the reason", "[unit][materials]") {
  const std::string good =
      "oil,fluid,density,970,kg/m^3,S,Lucke 1990\n"
      "oil,fluid,dynamic_viscosity,1.0,Pa*s,S,Rossi 2021\n";
  CHECK(MaterialLibrary::parseCsv(good, "t.csv").find("oil").density->value == 970.0);
  const auto fails = [&](const std::string& extra, const std::string& message) {
    INFO(extra);
    CHECK_THROWS_WITH(MaterialLibrary::parseCsv(good + extra, "t.csv"), Catch::Contains(message));
  };
  fails("oil,fluid,surface_tension,0.04,N/m,S,x y z\n",
        "t.csv:3: unknown property 'surface_tension'");
  fails("oil,fluid,interfacial_tension,40,mN/m,S,x y z\n",
        "t.csv:3: interfacial_tension must be given in N/m");
  fails("oil,fluid,contact_angle,abc,deg,S,x y z\n", "t.csv:3: value 'abc' is not a number");
  fails("oil,fluid,contact_angle,200,deg,S,x y z\n", "out of the physical range");
  fails("oil,fluid,contact_angle,20,deg,X,x y z\n", "t.csv:3: flag 'X' must be S, D or U");
  fails("oil,fluid,contact_angle,20,deg,S,\n", "t.csv:3: every value needs a source");
  fails("oil,fluid,density,971,kg/m^3,S,again\n", "t.csv:3: material 'oil' gives density twice");
  fails("oil,tissue,youngs_modulus,1e6,Pa,S,x y z\n", "t.csv:3: material 'oil' was declared fluid");
  fails("Oil,fluid,density,970,kg/m^3,S,x\n", "lower_snake_case");
  fails("fat,tissue,density,920,kg/m^3,U,x\n", "t.csv: material 'fat' has no youngs_modulus");
  fails("oil,fluid,density\n", "t.csv:3: expected 7 columns");
  CHECK_THROWS_WITH(MaterialLibrary::loadCsv("/nonexistent/m.csv"),
                    Catch::Contains("/nonexistent/m.csv: cannot open"));
}
