// Fuzz target: the strict CSV reader (io/csv.h, readCsv) and its column look-up.
#include "io/csv.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto dir = motostab::fuzz::resetScratchDir();
  const auto file = motostab::fuzz::writeScratchFile(dir, "table.csv", std::string(reinterpret_cast<const char*>(data), size));
  motostab::fuzz::expectInputErrorOnly([&] {
    const motostab::io::CsvTable t = motostab::io::readCsv(file);
    for (const auto& name : t.header) t.getColumn(name);
  });
  return 0;
}
