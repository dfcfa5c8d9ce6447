#pragma once
// Files written by `motostab identify response` and `motostab simulate --identify`: modes.json, the
// record and the fitted model as CSV, and the fit plot.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "response/mode_identification.h"
#include "response/response_csv.h"

namespace motostab::output {

/// Writes DIR/modes.json (makeModesJson() plus `extra` merged in), DIR/response_data.csv,
/// DIR/response_fit.csv (the model on a dense grid over the window) and the plot DIR/response_fit.{gp,png,svg}
/// (one panel per signal, record and fitted model). Throws std::runtime_error if gnuplot fails (modes.json
/// is written first).
void writeResponseReport(const std::filesystem::path& dir, const response::ResponseRecord& record,
                         const response::IdentificationResult& result, const nlohmann::json& extra = nlohmann::json::object());

}  // namespace motostab::output
