// The panel's circulation settings round-trip through the scenario: unchanged controls leave it
// bit for bit as it was (a restart from the panel runs what `heartsim run` runs), edited ones
// land in the lumped circulation's keys in SI units, and the section shows only with it.
#include <gtest/gtest.h>

#include "cardiac/circulation/clinical_units.h"
#include "io/scenario/scenario_file.h"
#include "viewer/panels/circulation_controls.h"

namespace hs::viewer {
namespace {

cardiac::Scenario lumpedNormal() {
  cardiac::Scenario s = io::loadScenario("normal");
  s.circulation.lumped = true;
  return s;
}

TEST(ViewerCirculationControls, ShownOnlyWithTheLumpedCirculation) {
  EXPECT_TRUE(circulationControlsFrom(lumpedNormal()).lumped);
  cardiac::Scenario plain = io::loadScenario("normal");
  plain.circulation.lumped = false;
  EXPECT_FALSE(circulationControlsFrom(plain).lumped);
  EXPECT_FALSE(circulationControlsFrom(io::loadScenario("dam-break")).lumped);
}

TEST(ViewerCirculationControls, ReadInClinicalUnits) {
  cardiac::Scenario s = lumpedNormal();
  s.circulation.atrialPressureMmHg = 12;
  s.circulation.lumpedParameters.peripheralResistance = cardiac::resistanceFromClinical(1.5);
  const CirculationControls c = circulationControlsFrom(s);
  EXPECT_DOUBLE_EQ(c.atrialPressureMmHg, 12);
  EXPECT_NEAR(c.resistance, 1.5, 1e-12);
  EXPECT_NEAR(c.compliance, 1.4, 1e-12);  // the model's defaults (lumped_circulation.h)
  EXPECT_NEAR(c.contractility, 2.7, 1e-12);
}

TEST(ViewerCirculationControls, UnchangedControlsLeaveTheScenarioAsItWas) {
  const cardiac::Scenario original = lumpedNormal();
  cardiac::Scenario s = original;
  applyCirculationControls(circulationControlsFrom(original), s);
  const cardiac::LumpedParameters& p = s.circulation.lumpedParameters;
  const cardiac::LumpedParameters& q = original.circulation.lumpedParameters;
  EXPECT_EQ(s.circulation.atrialPressureMmHg, original.circulation.atrialPressureMmHg);
  EXPECT_EQ(p.peripheralResistance, q.peripheralResistance);
  EXPECT_EQ(p.arterialCompliance, q.arterialCompliance);
  EXPECT_EQ(p.contractility, q.contractility);
}

TEST(ViewerCirculationControls, EditedControlsLandInTheScenarioInSiUnits) {
  cardiac::Scenario s = lumpedNormal();
  CirculationControls c = circulationControlsFrom(s);
  c.atrialPressureMmHg = 20;
  c.resistance = 2;
  c.compliance = 0.5;
  c.contractility = 4;
  applyCirculationControls(c, s);
  const cardiac::LumpedParameters& p = s.circulation.lumpedParameters;
  EXPECT_FLOAT_EQ(float(s.circulation.atrialPressureMmHg), 20.0f);
  EXPECT_NEAR(p.peripheralResistance, 2 * cardiac::kPascalPerMmHg / cardiac::kCubicMetresPerMl, 1e-3);
  EXPECT_NEAR(p.arterialCompliance, 0.5 * cardiac::kCubicMetresPerMl / cardiac::kPascalPerMmHg, 1e-18);
  EXPECT_NEAR(p.contractility, 4 * cardiac::kPascalPerMmHg / cardiac::kCubicMetresPerMl, 1e-3);
  // The rest of the model stays.
  EXPECT_EQ(p.unstressedVolume, lumpedNormal().circulation.lumpedParameters.unstressedVolume);
}

TEST(ViewerCirculationControls, EverySliderRangeIsOneTheModelAccepts) {
  for (const bool top : {false, true}) {
    cardiac::Scenario s = lumpedNormal();
    CirculationControls c = circulationControlsFrom(s);
    const auto pick = [&](CirculationRange r) { return top ? r.hi : r.lo; };
    c.atrialPressureMmHg = pick(kAtrialPressureRange);
    c.resistance = pick(kResistanceRange);
    c.compliance = pick(kComplianceRange);
    c.contractility = pick(kContractilityRange);
    applyCirculationControls(c, s);
    cardiac::LumpedParameters p = s.circulation.lumpedParameters;
    p.pulmonaryVenousPressure = double(s.circulation.atrialPressureMmHg) * cardiac::kPascalPerMmHg;
    EXPECT_NO_THROW(cardiac::validateLumpedParameters(p)) << (top ? "top" : "bottom");
  }
}

}  // namespace
}  // namespace hs::viewer
