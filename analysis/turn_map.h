#pragma once
// Stability map over speed x roll angle: one constant-roll sweep about steady turns per roll angle
// (analysis/sweep.h with SweepOptions::trim.roll), and the modes tracked across roll as well as speed.
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

/// sweeps[j]: the sweep at rolls[j], every sweep over the same speeds, its branches labelled
/// consistently across roll (trackModesAcrossRoll).
struct TurnMapResult {
  std::vector<double> rolls;
  std::vector<SweepResult> sweeps;
};

/// Runs the sweep of every roll angle (each starting from straight running, stepped up in roll at its
/// first speed), tracks the modes across roll, then brackets each sweep's critical speeds.
TurnMapResult runTurnMap(const vehicle::VehicleModel& model, const TurnMapOptions& options);

/// Mode identity across roll: starting from the roll angle nearest upright, whose labels come from the
/// modes' content (labelBranches), each neighbouring roll's branches are matched to the branches of
/// the roll before it (outwards in both directions) by the sum over speeds of calcMatchCost (MAC and
/// eigenvalue distance), cheapest pairs first, and take their labels. The order of the branches is kept.
void trackModesAcrossRoll(TurnMapResult& map);

}  // namespace motostab::analysis
