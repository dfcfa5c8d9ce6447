#pragma once
// Stability map over speed x roll angle: one constant-roll sweep about steady turns per roll angle
// (analysis/sweep.h with SweepOptions::trim.roll). Labels come from each operating point's modes
// (labelModes), so they follow the modes across roll as across speed.
#include <string>
#include <vector>

#include "analysis/sweep.h"

namespace motostab::analysis {

struct TurnMapOptions {
  SweepOptions sweep;          ///< speeds (all > 0), trim, linearisation, threads; trim.roll is set per roll
  std::vector<double> rolls;   ///< rad, ascending, each strictly inside (-89, 89) deg
  /// m/s, of every roll's critical speeds (replaces sweep.criticalSpeedTolerance: a map brackets many
  /// crossings, and Brent's method needs about three times the evaluations for 1e-9 as for 1e-6).
  double criticalSpeedTolerance = 1e-6;
};

/// A roll angle none of whose speeds trimmed.
struct FailedRoll {
  double roll = 0;       ///< rad
  std::string message;   ///< the first failure's message
};

/// sweeps[j]: the sweep at rolls[j], each over the speeds of the grid that trimmed at that roll (the
/// others listed in its failures); failedRolls: the roll angles where no speed trimmed.
struct TurnMapResult {
  std::vector<double> rolls;
  std::vector<SweepResult> sweeps;
  std::vector<FailedRoll> failedRolls;

  /// Points of the grid (roll x speed) that did not trim.
  size_t countFailedPoints() const;
};

/// Runs the sweep of every roll angle (each starting from its neighbour's trim, or from straight
/// running stepped up in roll at its first speed) and brackets each sweep's critical speeds. Points that
/// do not trim are left out and listed (SweepOptions::keepFailedSpeeds).
TurnMapResult runTurnMap(const vehicle::VehicleModel& model, const TurnMapOptions& options);

}  // namespace motostab::analysis
