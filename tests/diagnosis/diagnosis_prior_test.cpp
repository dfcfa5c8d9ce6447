// The prior of a parameter candidate is the scenario's `uncertainty:` sigma (in the key's unit) where
// the scenario states one, else motostab's default: a benchmark copy
// states sigmas drawn here for two keys; a third key keeps the default (10 mm for a length,
// scenario/parameter_paths.h).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/portable_random.h"
#include "diagnosis/diagnosis.h"
#include "io/csv.h"

namespace motostab::diagnosis {

using core::PortableRandom;
using io::formatNumber;

namespace {

namespace fs = std::filesystem;

TEST(DiagnosisPrior, UncertaintySectionSetsTheSigma) {
  PortableRandom rng(20261124);
  const double sigmaTrail = rng.drawUniform(0.001, 0.02), sigmaMass = rng.drawUniform(0.01, 2.0);
  const fs::path dir = fs::temp_directory_path() / ("motostab-prior-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ifstream in(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml");
  std::stringstream scenario;
  scenario << in.rdbuf() << "\nuncertainty:\n  geometry.trail_m: " << formatNumber(sigmaTrail)
           << "\n  rear_frame.mass_kg: {sigma: " << formatNumber(sigmaMass) << ", distribution: normal}\n";
  std::ofstream(dir / "s.yaml") << scenario.str();
  // Benchmark-like weave rows (Meijaard 2007 Table 2 region); their values only need a finite fit.
  std::ofstream(dir / "e.csv") << "speed_mps,mode,real,imag\n4.5,weave,-0.3,4.2\n5,weave,-0.8,4.5\n"
                                  "5.5,weave,-1.2,4.9\n6,weave,-1.7,5.3\n6.5,weave,-2.1,5.8\n";
  std::ofstream(dir / "m.yaml") << "eigenvalues:\n  - file: e.csv\n";
  const MeasuredData data = loadMeasuredData((dir / "m.yaml").string());
  DiagnosisOptions opt;
  opt.candidates = {"parameter:geometry.trail_m", "parameter:rear_frame.mass_kg", "parameter:geometry.wheelbase_m"};
  opt.maxCauses = 1;
  const DiagnosisResult r = runDiagnosis((dir / "s.yaml").string(), data, opt);
  fs::remove_all(dir);
  ASSERT_EQ(r.candidates.size(), 3u);
  for (const FitSummary& f : r.candidates) {
    ASSERT_EQ(f.parameters.size(), 1u);
    const double expected = f.name == "parameter:geometry.trail_m" ? sigmaTrail
                            : f.name == "parameter:rear_frame.mass_kg" ? sigmaMass : 0.010;
    EXPECT_NEAR(f.parameters[0].priorSigma, expected, 1e-12 * expected) << f.name;
  }
}

}  // namespace
}  // namespace motostab::diagnosis
