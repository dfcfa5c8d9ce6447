// motostab: stability of motorcycles and bicycles. Subcommands are registered by apps/cmd_*.cpp.
#include <iostream>

#include "apps/commands.h"
#include "io/input_error.h"
#include "io/result_error.h"

int main(int argc, char** argv) {
  CLI::App app{"motostab: stability of motorcycles and bicycles (Simbody multibody models from YAML scenarios)"};
  app.require_subcommand(1);
  motostab::cli::registerScenarioCommands(app);
  motostab::cli::registerStabilityCommands(app);
  motostab::cli::registerTurnCommands(app);
  motostab::cli::registerSimulateCommands(app);
  motostab::cli::registerUncertaintyCommands(app);
  motostab::cli::registerDiagnoseCommands(app);
  motostab::cli::registerTyreCommands(app);
  CLI::App* identify = app.add_subcommand("identify", "Identify model parameters from lab tests or responses");
  identify->require_subcommand(1);
  motostab::cli::registerSwingarmIdentifyCommands(*identify);
  motostab::cli::registerResponseIdentifyCommands(*identify);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; every parse or validation error is bad input: 2, not CLI11's code.
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const motostab::io::InputError& e) {
    std::cerr << "motostab: input error: " << e.what() << "\n";
    return 2;
  } catch (const motostab::io::ResultError& e) {
    std::cerr << "motostab: no result: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "motostab: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
