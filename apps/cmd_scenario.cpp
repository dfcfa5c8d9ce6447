#include "apps/commands.h"

namespace motostab::cli {

void registerScenarioCommands(CLI::App& app) {}

}  // namespace motostab::cli
