#include "apps/commands.h"

namespace motostab::cli {

void registerStabilityCommands(CLI::App& app) {}

}  // namespace motostab::cli
