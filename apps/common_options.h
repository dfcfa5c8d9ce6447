#pragma once
#include <string>

namespace motostab::cli {

/// Parses "START:STOP:STEP" (m/s); throws InputError naming the option on bad input.
void parseSpeedRange(const std::string& text, double& start, double& stop, double& step);

}  // namespace motostab::cli
