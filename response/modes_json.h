#pragma once
// The modes.json format shared by `motostab identify response` and `motostab simulate --identify`.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "response/mode_identification.h"

namespace motostab::response {

/// modes.json content: {"signals", "modes": [{real, imag, frequency_hz, damping_ratio, amplitude[], phase_rad[]}],
/// "offset", "order", "fit": {r_squared, rms_residual[], normalised_rms_residual[]}, "window", ...}.
/// Per-signal arrays follow `signalNames`. Units: 1/s, rad/s, Hz, s, rad, signal units.
nlohmann::json makeModesJson(const IdentificationResult& result, const std::vector<std::string>& signalNames);

/// A fixed-width text table of the modes (one line per mode) and the fit quality, for terminals.
std::string formatModesTable(const IdentificationResult& result, const std::vector<std::string>& signalNames);

}  // namespace motostab::response
