#pragma once
// Each group of `motostab` subcommands registers itself here; apps/motostab.cpp only wires them.
#include <CLI/CLI.hpp>

namespace motostab::cli {

void registerScenarioCommands(CLI::App& app);   ///< check, fields, import (apps/cmd_scenario.cpp)
void registerStabilityCommands(CLI::App& app);  ///< sweep, linearize, study (apps/cmd_stability.cpp); compare
void registerCompareCommands(CLI::App& app);    ///< compare (apps/cmd_compare.cpp), registered by registerStabilityCommands
void registerTurnCommands(CLI::App& app);       ///< trim (apps/cmd_turn.cpp)
void registerSimulateCommands(CLI::App& app);   ///< simulate (apps/cmd_simulate.cpp)
void registerUncertaintyCommands(CLI::App& app);  ///< uncertainty (apps/cmd_uncertainty.cpp)
void registerDiagnoseCommands(CLI::App& app);   ///< diagnose (apps/cmd_diagnose.cpp)
void registerTyreCommands(CLI::App& app);       ///< tyre (apps/cmd_tyre.cpp)
/// identify static|frf|swingarm|cog|inertia (apps/cmd_identify_swingarm.cpp); `identify` is the parent.
void registerSwingarmIdentifyCommands(CLI::App& identify);
/// identify response (apps/cmd_identify_response.cpp); `identify` is the parent.
void registerResponseIdentifyCommands(CLI::App& identify);

}  // namespace motostab::cli
