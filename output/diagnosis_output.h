#pragma once
// Writers of a diagnosis: diagnosis.json (pinned keys), report.md, residuals.csv,
// extended.yaml and gnuplot plots. They format what runDiagnosis computed.
#include <filesystem>
#include <string>

#include "diagnosis/diagnosis.h"
#include "nlohmann/json.hpp"

namespace motostab::output {

/// The diagnosis.json document.
nlohmann::json makeDiagnosisJson(const diagnosis::DiagnosisResult& result);
/// report.md: the data; what the model gets wrong; candidates; the cause and what it cannot be told
/// apart from; the extension; the gain.
std::string makeDiagnosisReport(const diagnosis::DiagnosisResult& result);
/// Writes every output into the existing folder `dir` (each file atomically; the CLI passes an
/// OutputFolder, io/output_folder.h, so the folder is replaced as a whole); plots need gnuplot.
void writeDiagnosisOutputs(const std::filesystem::path& dir, const diagnosis::DiagnosisResult& result);

}  // namespace motostab::output
