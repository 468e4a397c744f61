// "Only when it matters": the tissue deformation estimate and the elastic/rigid decision.
#include <catch2/catch.hpp>

#include "sim/core/error.h"
#include "sim/solid/tissue_deformation.h"

using namespace sim;

TEST_CASE("tissue deformation estimate is the thin-shell membrane displacement",
          "[unit][elasticity]") {
  // u = p R^2 / (2 E t): 235 Pa (water column of a 24 mm eye, 1000 * 9.81 * 0.024) on a 12 mm
  // cavity with a 1 mm shell. Hand value: 235 * 1.44e-4 / (2 * E * 1e-3).
  const Real p = 235.0, R = 0.012, t = 0.001;
  CHECK(estimateTissueDeformation(p, R, t, 1.8e6) == Approx(235.0 * 1.44e-4 / 3.6e3));
  // Linear in the load, inverse in modulus and thickness.
  CHECK(estimateTissueDeformation(2 * p, R, t, 1e4) ==
        Approx(2 * estimateTissueDeformation(p, R, t, 1e4)));
  CHECK(estimateTissueDeformation(p, R, 2 * t, 1e4) ==
        Approx(0.5 * estimateTissueDeformation(p, R, t, 1e4)));
  CHECK(estimateTissueDeformation(0.0, R, t, 1e4) == 0.0);
}

TEST_CASE("an anchored layer's estimate is its compression through the thickness",
          "[unit][elasticity]") {
  // u = p t / E (uniaxial, nu = 0). Hand value: 235 Pa on 0.42 mm of 10 kPa sclera held at its
  // outer surface: 235 * 4.2e-4 / 1e4 = 9.87e-6 m, 170x less than the free membrane's
  // p R^2 / (2 E t) = 235 * 1.44e-4 / (2e4 * 4.2e-4) = 4.03e-3 m: the ratio is 2 t^2 / R^2.
  const Real p = 235.0, R = 0.012, t = 0.42e-3;
  CHECK(estimateAnchoredLayerCompression(p, t, 1e4) == Approx(9.87e-6));
  CHECK(estimateAnchoredLayerCompression(p, t, 1e4) / estimateTissueDeformation(p, R, t, 1e4) ==
        Approx(2.0 * t * t / (R * R)));
  // At d = 1.2 mm the anchored 10 kPa sclera is rigid by the rule, the free one elastic.
  CHECK_FALSE(decideElastic(estimateAnchoredLayerCompression(p, t, 1e4), 1.2e-3).elastic);
  CHECK(decideElastic(estimateTissueDeformation(p, R, t, 1e4), 1.2e-3).elastic);
  CHECK(estimateAnchoredLayerCompression(0.0, t, 1e4) == 0.0);
  CHECK_THROWS_WITH(estimateAnchoredLayerCompression(p, 0.0, 1e4), Catch::Contains("thickness"));
  CHECK_THROWS_WITH(estimateAnchoredLayerCompression(p, t, 0.0), Catch::Contains("modulus"));
  CHECK_THROWS_WITH(estimateAnchoredLayerCompression(-1.0, t, 1e4), Catch::Contains("pressure"));
}

TEST_CASE("physiological sclera is rigid, the paper's soft sclera and fat are elastic",
          "[unit][elasticity]") {
  const Real p = 235.0, R = 0.012, d = 5e-4;  // [Pa], [m], [m] a 0.5 mm particle spacing
  // Human sclera, 1.8 MPa, 1 mm: u ~ 9.4e-6 m = 0.019 d -> rigid.
  const TissueDecision sclera = decideElastic(estimateTissueDeformation(p, R, 0.001, 1.8e6), d);
  CHECK_FALSE(sclera.elastic);
  CHECK_FALSE(sclera.forced);
  CHECK_THAT(sclera.reason, Catch::Contains("rigid"));
  // The paper's 10 kPa sclera: u ~ 1.7e-3 m = 3.4 d -> elastic.
  const TissueDecision soft = decideElastic(estimateTissueDeformation(p, R, 0.001, 1e4), d);
  CHECK(soft.elastic);
  CHECK_THAT(soft.reason, Catch::Contains("elastic"));
  // Orbital fat, 870 Pa, 5 mm thick: elastic.
  CHECK(decideElastic(estimateTissueDeformation(p, R, 0.005, 870.0), d).elastic);
}

TEST_CASE("the decision threshold is a tenth of the particle spacing", "[unit][elasticity]") {
  const Real d = 1e-3;
  CHECK(decideElastic(0.1 * d, d).elastic);
  CHECK_FALSE(decideElastic(0.0999 * d, d).elastic);
}

TEST_CASE("a protocol can force either choice, and the reason says so", "[unit][elasticity]") {
  const Real d = 1e-3;
  const TissueDecision forcedOn = decideElastic(1e-6, d, TissueChoice::kElastic);
  CHECK(forcedOn.elastic);
  CHECK(forcedOn.forced);
  CHECK_THAT(forcedOn.reason, Catch::Contains("forced elastic"));
  const TissueDecision forcedOff = decideElastic(1e-2, d, TissueChoice::kRigid);
  CHECK_FALSE(forcedOff.elastic);
  CHECK(forcedOff.forced);
  CHECK_THAT(forcedOff.reason, Catch::Contains("forced rigid"));
  // Forcing what the rule chooses anyway is not reported as forced.
  const TissueDecision agree = decideElastic(1e-2, d, TissueChoice::kElastic);
  CHECK(agree.elastic);
  CHECK_FALSE(agree.forced);
}

TEST_CASE("bad inputs to the tissue decision are rejected with the quantity named",
          "[unit][elasticity]") {
  CHECK_THROWS_WITH(estimateTissueDeformation(100, 0.012, 0.001, 0.0),
                    Catch::Contains("Young's modulus"));
  CHECK_THROWS_WITH(estimateTissueDeformation(100, -1, 0.001, 1e4),
                    Catch::Contains("cavity radius"));
  CHECK_THROWS_WITH(estimateTissueDeformation(100, 0.012, 0, 1e4), Catch::Contains("thickness"));
  CHECK_THROWS_WITH(estimateTissueDeformation(-1, 0.012, 0.001, 1e4),
                    Catch::Contains("load pressure"));
  CHECK_THROWS_AS(decideElastic(1e-3, 0.0), SimError);
  CHECK_THROWS_WITH(decideElastic(-1e-3, 1e-3), Catch::Contains("estimated displacement"));
}
