#include "apps/commands.h"

namespace motostab::cli {

void registerSwingarmIdentifyCommands(CLI::App& app) {}

}  // namespace motostab::cli
