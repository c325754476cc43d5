#pragma once
// Clinical units at the edges, SI inside: mmHg, mL and their compounds to Pa and m^3.
namespace hs::cardiac {

inline constexpr double kPascalPerMmHg = 133.322;
inline constexpr double kCubicMetresPerMl = 1e-6;

// Elastance mmHg/mL -> Pa/m^3; resistance mmHg s/mL -> Pa s/m^3; compliance mL/mmHg -> m^3/Pa.
constexpr double elastanceFromClinical(double mmHgPerMl) { return mmHgPerMl * kPascalPerMmHg / kCubicMetresPerMl; }
constexpr double resistanceFromClinical(double mmHgSPerMl) { return mmHgSPerMl * kPascalPerMmHg / kCubicMetresPerMl; }
constexpr double complianceFromClinical(double mlPerMmHg) { return mlPerMmHg * kCubicMetresPerMl / kPascalPerMmHg; }
constexpr double elastanceToClinical(double paPerM3) { return paPerM3 * kCubicMetresPerMl / kPascalPerMmHg; }
constexpr double resistanceToClinical(double paSPerM3) { return paSPerM3 * kCubicMetresPerMl / kPascalPerMmHg; }
constexpr double complianceToClinical(double m3PerPa) { return m3PerPa * kPascalPerMmHg / kCubicMetresPerMl; }

}  // namespace hs::cardiac
