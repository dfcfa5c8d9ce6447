#pragma once
// What the hammer-test analysis tried and why a mode is missing, in words a user can act on: indicator
// peaks left without a stable mode (with the setting to try), a missing bending or torsion mode (which,
// why, where to hit instead), the attempt (band, orders, peaks) when nothing is found, and the
// stabilisation summary printed by `--verbose`.
#include <string>

#include "swingarm/identification/hammer_frf.h"

namespace motostab::swingarm::identification {

/// Fills result.diagnostics: each indicator peak (>= 1 % of the largest, coherence > 0.99) with no
/// stable mode, and, with >= 3 channels, a missing bending or torsion mode: which one, why (the modes
/// found and their axis angles, the indicator peaks), and where to hit to excite it more.
void diagnoseFrf(const FrfTest& test, FrfResult& result);

/// The attempt in one paragraph: hits, band and its reason, orders and their reason, indicator peaks,
/// stable-pole clusters rejected for too few orders.
std::string describeFrfAttempt(const FrfResult& result);

/// The settings to try next (processing.band_hz, processing.model_order, hitting elsewhere).
std::string suggestFrfSettings(const FrfResult& result);

/// Stabilisation summary: per order the poles and the stable ones, then every cluster of stable poles
/// with the number of orders it is stable at and whether it became a mode.
std::string formatStabilisationSummary(const FrfResult& result);

/// Throws ResultError (exit 3) with describeFrfAttempt + suggestFrfSettings if no mode was found.
void requireModes(const FrfResult& result);

/// Throws ResultError (exit 3) with the diagnostics if the bending or torsion mode is missing.
void requireBendingAndTorsion(const FrfResult& result);

}  // namespace motostab::swingarm::identification
