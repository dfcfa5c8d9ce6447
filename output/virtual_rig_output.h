#pragma once
// Files written by `motostab identify virtual-rig`: the virtual rig's synthetic lab tests in the input
// formats of docs/swingarm-identification.md (static, hammer, tilting-rig and trifilar tests), so that
// `motostab identify ...` and the tests read them as they read measured data. Each file is complete or
// absent (io/atomic_file.h).
#include <filesystem>
#include <string>
#include <vector>

#include "swingarm/identification/virtual_rig.h"

namespace motostab::output {

/// Writes DIR/static.yaml and DIR/static.csv (laser readings, m, per load, N).
void writeStaticTestFiles(const std::filesystem::path& dir, const swingarm::identification::VirtualSwingarm& rig,
                          const swingarm::identification::StaticReadings& readings, double laserResolution);

/// Writes DIR/frf.yaml and DIR/hitN.csv; `processing` is extra YAML (indented under `processing:`), or "".
void writeFrfTestFiles(const std::filesystem::path& dir, const swingarm::identification::VirtualSwingarm& rig,
                       const std::vector<modal::ImpactRecord>& hits, const std::string& processing = "");

/// Writes DIR/cog.yaml, DIR/cog.csv and DIR/cog_tare.csv (cell loads, N, per tilt, deg).
void writeCogTestFiles(const std::filesystem::path& dir, const swingarm::identification::CogRigReadings& readings);

/// Writes DIR/inertia.yaml (pendulum, part mass, periods in s of the plate alone and of each set-up).
void writeInertiaTestFiles(const std::filesystem::path& dir, const swingarm::identification::InertiaTest& test);

}  // namespace motostab::output
