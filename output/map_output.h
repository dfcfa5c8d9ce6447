#pragma once
// Files written by `motostab sweep --roll-deg A:B:STEP` (docs/cornering.md).
#include <filesystem>
#include <string>

#include "analysis/turn_map.h"

namespace motostab::output {

/// DIR/map.csv (roll_deg,speed_mps,mode,real,imag,frequency_hz,damping_ratio; every branch, 17 digits),
/// DIR/map_summary.json (critical speeds per roll), DIR/roll_<deg>/ with each roll's sweep outputs,
/// and the plots of the weave and wobble (those the map has): damping_map (damping ratio over speed x
/// roll), root_loci (one curve per roll) and real_part_vs_speed (one curve per roll).
void writeTurnMapOutputs(const std::filesystem::path& dir, const std::string& scenarioName, const analysis::TurnMapResult& map);

/// A short table: per roll angle, the weave and wobble damping ratios at a few speeds and the critical speeds.
std::string formatTurnMapTable(const analysis::TurnMapResult& map);

}  // namespace motostab::output
