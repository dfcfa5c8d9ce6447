// Fuzz target: the measured-data loader of `motostab diagnose` (diagnosis/measured_data.h,
// loadMeasuredData) on a multi-file input (fuzz_support.h): the first file is the measurement YAML,
// the others the CSV files it names. Built only when the diagnosis library exists (tests/fuzz/CMakeLists.txt).
#include "diagnosis/measured_data.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto files = motostab::fuzz::splitFiles(data, size);
  if (files.empty()) return 0;
  const auto dir = motostab::fuzz::resetScratchDir();
  for (const auto& [name, content] : files) motostab::fuzz::writeScratchFile(dir, name, content);
  motostab::fuzz::expectInputErrorOnly([&] { motostab::diagnosis::loadMeasuredData((dir / files.front().first).string()); });
  return 0;
}
