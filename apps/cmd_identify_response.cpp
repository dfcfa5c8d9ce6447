#include "apps/commands.h"

namespace motostab::cli {

void registerResponseIdentifyCommands(CLI::App& app) {}

}  // namespace motostab::cli
