#pragma once
// Files written by `motostab identify response` and `motostab simulate --identify`: modes.json, the
// record and the fitted model as CSV, and the fit plot; the modes table both commands print.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "response/mode_identification.h"
#include "response/response_csv.h"

namespace motostab::output {

/// modes.json content: {"signals", "modes": [{real, imag, frequency_hz, damping_ratio, amplitude[], phase_rad[]}],
/// "offset", "order", "fit": {r_squared, rms_residual[], normalised_rms_residual[]}, "window", ...}.
/// Per-signal arrays follow `signalNames`. Units: 1/s, rad/s, Hz, s, rad, signal units.
nlohmann::json makeModesJson(const response::IdentificationResult& result, const std::vector<std::string>& signalNames);

/// A fixed-width text table of the modes (one line per mode) and the fit quality, for terminals.
std::string formatModesTable(const response::IdentificationResult& result, const std::vector<std::string>& signalNames);

/// Writes DIR/modes.json (makeModesJson() plus `extra` merged in), DIR/response_data.csv,
/// DIR/response_fit.csv (the model on a dense grid over the window) and the plot DIR/response_fit.{gp,png,svg}
/// (one panel per signal, record and fitted model). Throws std::runtime_error if gnuplot fails (modes.json
/// is written first).
void writeResponseReport(const std::filesystem::path& dir, const response::ResponseRecord& record,
                         const response::IdentificationResult& result, const nlohmann::json& extra = nlohmann::json::object());

}  // namespace motostab::output
