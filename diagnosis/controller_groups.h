#pragma once
// Measured data taken with different controller settings (the `controller:` mapping of an eigenvalue
// file or response run, or `steer_controller.<key>` columns; docs/measured-data-format.md): the rows
// and runs are split into groups of equal settings, each predicted by the scenario with its group's
// `steer_controller.*` overrides after the base overrides and before a candidate's, so that one
// diagnosis fits every setting's data together (a candidate such as `steer_controller_gain` then acts
// on all groups alike).
#include <string>
#include <vector>

#include "diagnosis/measured_data.h"

namespace motostab::diagnosis {

/// The rows and runs of one controller setting, as a MeasuredData of their own (no controller).
struct ControllerGroup {
  std::vector<std::string> overrides;  ///< the setting's steer_controller.* overrides
  MeasuredData data;                   ///< the group's rows and runs, in the original order
  std::vector<size_t> rows, runs;      ///< their indices in the original data
};

/// The groups of `data` in order of first appearance; empty when no row or run names a controller.
std::vector<ControllerGroup> splitByController(const MeasuredData& data);

/// The key paths the data's controller settings set (e.g. steer_controller.roll_rate_Nms_per_rad),
/// sorted and unique: a `parameter:` candidate on one of them would override every group's setting.
std::vector<std::string> getControllerPaths(const MeasuredData& data);

}  // namespace motostab::diagnosis
