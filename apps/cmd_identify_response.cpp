// motostab identify response CSV --signal COLUMN ...: modes (frequency, damping) of a transient record.
#include <filesystem>
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "apps/common_options.h"
#include "io/output_folder.h"
#include "output/response_output.h"
#include "response/response_csv.h"

namespace motostab::cli {

using io::OutputFolder;

namespace {

struct ResponseArgs {
  response::CsvIdentificationRequest request;
  std::string csv;
  std::string window;
  std::string out;
  bool noOffset = false;
  bool noPolish = false;
};

void runResponseIdentify(ResponseArgs args) {
  auto& request = args.request;
  request.csv = args.csv;
  request.options.fitOffset = !args.noOffset;
  request.options.polish = !args.noPolish;
  if (!args.window.empty()) response::setWindowFromText(args.window, args.csv, request.options);
  response::ResponseRecord record;
  const auto result = response::identifyModesFromCsv(request, &record);
  const std::filesystem::path out =
      getOutputFolder(args.out, std::filesystem::path(args.csv).stem().string(), "identify-response");
  std::cout << output::formatModesTable(result, record.signalColumns);
  OutputFolder folder(out);
  output::writeResponseReport(folder.getPath(), record, result);
  folder.commit();
  std::cout << "wrote " << (out / "modes.json").string() << " and " << (out / "response_fit.png").string() << "\n";
}

}  // namespace

void registerResponseIdentifyCommands(CLI::App& identify) {
  auto args = std::make_shared<ResponseArgs>();
  CLI::App* cmd = identify.add_subcommand(
      "response", "Modes (frequency, damping) of a transient response in a CSV: matrix pencil + least squares");
  cmd->add_option("csv", args->csv, "CSV file with a header row (# lines are comments)")->required();
  cmd->add_option("--signal", args->request.signalColumns,
                  "Signal column to fit (repeat for a joint fit with shared modes)")
      ->required();
  cmd->add_option("--time", args->request.timeColumn, "Time column in s (default: the first column)");
  cmd->add_option("--window", args->window, "Fit window T0:T1 in s (default: the whole record)");
  cmd->add_option("--out", args->out,
                  "Output folder (default: CSV's stem-identify-response in the working folder; replaced whole only if "
                  "motostab wrote it)");
  cmd->add_option("--max-order", args->request.options.maxOrder,
                  "Largest model order tried (complex pair = 2, real exponential = 1)")
      ->capture_default_str()
      ->check(CLI::Range(1, 40));
  cmd->add_option("--order", args->request.options.fixedOrder, "Fixed model order instead of automatic selection")
      ->check(CLI::Range(1, 40));
  cmd->add_flag("--no-offset", args->noOffset, "Fit without a constant offset");
  cmd->add_flag("--no-polish", args->noPolish, "Keep the matrix-pencil poles (no nonlinear least squares)");
  cmd->callback([args]() { runResponseIdentify(*args); });
}

}  // namespace motostab::cli
