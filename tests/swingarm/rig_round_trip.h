#pragma once
// The virtual rig's static and hammer tests written in the documented formats, read back and identified
// by the whole chain (static axis, FRF modes, bending/torsion decomposition).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "output/virtual_rig_output.h"
#include "swingarm/identification/decomposition.h"
#include "swingarm/identification/virtual_rig.h"

/// What the chain identified from the rig's test files.
struct IdentifiedRig {
  motostab::swingarm::identification::StaticTest staticTest;
  motostab::swingarm::identification::FrfTest frfTest;
  motostab::swingarm::identification::StaticResult stat;
  motostab::swingarm::identification::FrfResult frf;
  motostab::swingarm::identification::SwingarmIdentification id;
};

/// Static test loaded 0-4000-0 N in 250 N steps (draws from `seed`), three hammer hits (`seed` + 7) with
/// the `processing` section, written into `dir` and identified.
inline IdentifiedRig identifyRigTests(const motostab::swingarm::identification::VirtualSwingarm& rig,
                                      const motostab::swingarm::identification::RigNoise& noise, std::uint64_t seed,
                                      const std::filesystem::path& dir, const std::string& processing) {
  namespace id = motostab::swingarm::identification;
  std::vector<double> loads;
  for (int i = 0; i <= 32; ++i) loads.push_back(250.0 * (i <= 16 ? i : 32 - i));  // 0-4000-0 N
  motostab::output::writeStaticTestFiles(dir, rig, id::simulateStaticReadings(rig, loads, noise, seed),
                                         noise.laserResolution);
  motostab::output::writeFrfTestFiles(dir, rig, id::simulateHammerHits(rig, {}, noise, seed + 7), processing);
  IdentifiedRig r;
  r.staticTest = id::readStaticTest(dir / "static.yaml");
  r.frfTest = id::readFrfTest(dir / "frf.yaml");
  r.stat = id::identifyStatic(r.staticTest, id::readStaticReadings(r.staticTest));
  r.frf = id::identifyFrf(r.frfTest, id::readHits(r.frfTest));
  r.id = id::identifySwingarm(r.stat, r.frf);
  return r;
}
