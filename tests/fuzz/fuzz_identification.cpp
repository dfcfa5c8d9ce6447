// Fuzz target: the identification test loaders (swingarm/identification): a multi-file input
// (fuzz_support.h) whose first file names the test: static*.yaml (readStaticTest + readStaticReadings),
// frf*.yaml (readFrfTest + readHits), cog*.yaml (readCogTest), inertia*.yaml (readInertiaTest).
#include "swingarm/identification/hammer_frf.h"
#include "swingarm/identification/mass_properties.h"
#include "swingarm/identification/static_laser.h"
#include "tests/fuzz/fuzz_support.h"

namespace id = motostab::swingarm::identification;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto files = motostab::fuzz::splitFiles(data, size);
  if (files.empty()) return 0;
  const auto dir = motostab::fuzz::resetScratchDir();
  for (const auto& [name, content] : files) motostab::fuzz::writeScratchFile(dir, name, content);
  const std::string& first = files.front().first;
  const auto path = dir / first;
  motostab::fuzz::expectInputErrorOnly([&] {
    if (first.rfind("static", 0) == 0) {
      id::readStaticReadings(id::readStaticTest(path));
    } else if (first.rfind("frf", 0) == 0) {
      id::readHits(id::readFrfTest(path));
    } else if (first.rfind("cog", 0) == 0) {
      id::readCogTest(path);
    } else if (first.rfind("inertia", 0) == 0) {
      id::readInertiaTest(path);
    }
  });
  return 0;
}
