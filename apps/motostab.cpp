// motostab: stability of motorcycles and bicycles. Subcommands are registered by apps/cmd_*.cpp.
#include <iostream>

#include "apps/commands.h"
#include "io/input_error.h"
#include "io/result_error.h"
#include "io/field.h"
#include "plugins/builtin.h"
#include "plugins/plugin_api.h"

// Exit codes (docs/commands.md): 0 done; 2 bad input (io::InputError, CLI11's parse errors); 3 valid input
// without a result (io::ResultError, or memory exhausted by a valid request); 1 a bug.
int main(int argc, char** argv) {
  CLI::App app{"motostab: stability of motorcycles and bicycles (Simbody multibody models from YAML scenarios)"};
  app.set_version_flag("--version", std::string("motostab ") + MOTOSTAB_VERSION + " (plugin API " +
                                        std::to_string(MOTOSTAB_PLUGIN_API_VERSION) + ")");
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
  } catch (const motostab::io::OutputError& e) {
    std::cerr << "motostab: cannot write output: " << e.what() << "\n";
    return 2;
  } catch (const motostab::io::InputError& e) {
    // A key no reader knows: what its section declares (the built-in declarations).
    const bool unknown = e.getProblem() == motostab::io::InputProblem::UnknownKey;
    const std::string hint = unknown ? motostab::io::describeDeclaredKeys(
                                           motostab::plugins::listSectionFields(motostab::plugins::makeBuiltinRegistry()),
                                           e.getLocation().key)
                                     : "";
    std::cerr << "motostab: input error: " << e.what() << hint << "\n";
    return 2;
  } catch (const motostab::io::ResultError& e) {
    std::cerr << "motostab: no result: " << e.what() << "\n";
    return 3;
  } catch (const std::bad_alloc&) {
    std::cerr << "motostab: no result: the computation ran out of memory; ask for less (fewer speeds, samples or "
                 "candidates)\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "motostab: internal error (a bug; please report it with the command line): " << e.what() << "\n";
    return 1;
  }
  return 0;
}
