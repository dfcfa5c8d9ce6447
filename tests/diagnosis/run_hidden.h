#pragma once
// Test helper: diagnoses hidden-effect data (hidden_effect.h) written into a fresh temporary folder.
#include <unistd.h>

#include <filesystem>
#include <string>

#include "diagnosis/diagnosis.h"
#include "hidden_effect.h"
#include "io/csv.h"

namespace motostab::testing {

using diagnosis::DiagnosisOptions;
using diagnosis::DiagnosisResult;
using diagnosis::MeasuredData;
using diagnosis::loadMeasuredData;
using diagnosis::runDiagnosis;
using io::splitFields;



inline std::filesystem::path makeHiddenDir(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("motostab-hidden-" + std::to_string(::getpid()) + "-" + name);
}

/// Writes the hidden effect's data (eigenvalue rows if `eigen`, response runs at `runs` with noise
/// `runNoise`), diagnoses h.scenario with the comma-separated `candidates` on `threads` threads
/// (DiagnosisOptions::candidateTableCv as given), removes the folder.
inline DiagnosisResult runHidden(const HiddenEffect& h, const std::string& name, bool eigen, const std::vector<double>& runs,
                                 const std::string& candidates, int maxCauses, double runNoise = 0.002, int threads = 2,
                                 bool candidateTableCv = true) {
  const std::filesystem::path dir = makeHiddenDir(name);
  const MeasuredData data = loadMeasuredData(writeHiddenEffectData(h, dir, eigen, runs, runNoise));
  DiagnosisOptions opt;
  if (!candidates.empty()) opt.candidates = splitFields(candidates, ',');  // empty: every default candidate
  opt.maxCauses = maxCauses;
  opt.threads = threads;
  opt.candidateTableCv = candidateTableCv;
  DiagnosisResult r = runDiagnosis(h.scenario, data, opt);
  r.data = nullptr;  // `data` dies here
  std::filesystem::remove_all(dir);
  return r;
}

}  // namespace motostab::testing
