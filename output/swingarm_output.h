#pragma once
// Files written by `motostab identify static|frf|swingarm|cog|inertia` (docs/swingarm-identification.md):
// the JSON and CSV results of each lab test and their plots (gnuplot script + png + svg). The twist-axis
// plots show the reference plate, its sensors, the force point and the axes in the x-z plane (as seed
// Fig. 3, 5 and 8). Each file is complete or absent (io/atomic_file.h).
#include <filesystem>

#include "swingarm/identification/decomposition.h"
#include "swingarm/identification/hammer_frf.h"
#include "swingarm/identification/mass_properties.h"
#include "swingarm/identification/static_laser.h"

namespace motostab::output {

/// Writes DIR/static.json (keys k_lat_N_per_m, a_tw_m, k_tw_Nm_per_rad, beta_deg, axis_point_m,
/// axis_direction, their *_stderr, and details) and the plot DIR/static_axis.png/.svg.
void writeStaticOutputs(const swingarm::identification::StaticTest& test,
                        const swingarm::identification::StaticResult& result, const std::filesystem::path& dir);

/// Writes DIR/frf.csv (per channel H1, coherence and the fitted modal model up to the band's top plus a
/// fifth of its width), DIR/modes.csv, DIR/stabilisation.csv, DIR/frf.json and the plots
/// frf_magnitude_phase, coherence, stabilisation and modal_axes (png + svg).
void writeFrfOutputs(const swingarm::identification::FrfTest& test, const swingarm::identification::FrfResult& result,
                     const std::filesystem::path& dir);

/// Writes DIR/swingarm.yaml (swingarm::identification::formatSwingarmYaml) and the plot
/// DIR/swingarm_axes.png/.svg (static, bending, torsion axes).
void writeSwingarmOutputs(const swingarm::identification::SwingarmIdentification& id,
                          const swingarm::identification::StaticTest& stat,
                          const swingarm::identification::FrfTest& frf, const std::filesystem::path& dir);

/// Writes DIR/cog.json, DIR/cog_fit.csv and the plot DIR/cog_fit.png/.svg.
void writeCogOutputs(const swingarm::identification::CogTest& test, const swingarm::identification::CogResult& result,
                     const std::filesystem::path& dir);

/// Writes DIR/inertia.json, DIR/inertia_setups.csv and the plot DIR/inertia_setups.png/.svg.
void writeInertiaOutputs(const swingarm::identification::InertiaTest& test,
                         const swingarm::identification::InertiaResult& result, const std::filesystem::path& dir);

}  // namespace motostab::output
