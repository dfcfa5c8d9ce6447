#pragma once
// Files written by `motostab trim` (docs/cornering.md).
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/trim.h"
#include "nlohmann/json.hpp"

namespace motostab::output {

/// The trim's pinned keys: speed_mps (rear contact point's speed along its path = path_radius_m x
/// |yaw_rate_radps|), roll_rad, steer_rad, pitch_rad (rear frame, > 0 nose down), steer_torque_Nm,
/// drive_torque_Nm, yaw_rate_radps (> 0 left), path_radius_m (rear contact point; null when straight),
/// lateral_acceleration_mps2 (speed x yaw rate, > 0 left), residual, iterations, and `tyres`: the
/// contact model's outputs by name (forces, slip and camber angles), empty for rolling constraints.
nlohmann::json makeTrimJson(const vehicle::VehicleModel& model, const analysis::TrimResult& trim);

/// DIR/trim.json (makeTrimJson), written atomically.
void writeTrimJson(const std::filesystem::path& dir, const vehicle::VehicleModel& model, const analysis::TrimResult& trim);

/// A short table of the trim for the terminal (degrees where readable).
std::string formatTrimTable(const vehicle::VehicleModel& model, const analysis::TrimResult& trim);

/// trim.json of `trim --hands-free`: the keys of makeTrimJson for the default turn turns[defaultIndex],
/// and `hands_free_turns`, every turn sorted by speed with the same keys and
/// `continues_from_straight_running` (analysis::HandsFreeTurn) and `default`.
nlohmann::json makeHandsFreeJson(const vehicle::VehicleModel& model, const std::vector<analysis::HandsFreeTurn>& turns,
                                 size_t defaultIndex);

/// DIR/trim.json (makeHandsFreeJson), written atomically.
void writeHandsFreeJson(const std::filesystem::path& dir, const vehicle::VehicleModel& model,
                        const std::vector<analysis::HandsFreeTurn>& turns, size_t defaultIndex);

/// One row per hands-free turn: speed, steer, steer torque, path radius, whether it continues from
/// straight running, the default marked.
std::string formatHandsFreeTable(const vehicle::VehicleModel& model, const std::vector<analysis::HandsFreeTurn>& turns,
                                 size_t defaultIndex);

}  // namespace motostab::output
