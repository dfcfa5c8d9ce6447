#pragma once
// Hammer test: H1 FRFs averaged over hits, hit checks, LSCF modal parameters with a stabilisation
// diagram (band and orders chosen from the data unless given), half-power quick estimates, and modal
// (dynamic) twist axes from the 3-point ODS (seed sec. 2.1-2.2).
#include <filesystem>
#include <string>
#include <vector>

#include "modal/automatic_settings.h"
#include "modal/lscf.h"
#include "modal/peak_picking.h"
#include "modal/spectra.h"
#include "swingarm/identification/plate_motion.h"

namespace motostab::swingarm::identification {

/// An accelerometer on the plate measuring along y.
struct FrfChannel {
  std::string name;    ///< channel name
  std::string column;  ///< CSV column (default "<name>_mps2")
  PlatePoint position; ///< m
};

/// The hammer test description (docs/swingarm-identification.md, "Hammer test").
struct FrfTest {
  std::filesystem::path file;
  std::string frame;
  PlatePoint forcePoint;
  std::vector<FrfChannel> channels;
  std::vector<std::filesystem::path> hits;
  std::string timeColumn = "time_s", forceColumn = "force_N";
  // Optional processing settings (key `processing`).
  double bandMinHz = 0, bandMaxHz = 0;   ///< Hz; both 0 = automatic (modal/automatic_settings.h)
  int minOrder = 0, maxOrder = 0;        ///< LSCF orders swept; both 0 = automatic from the indicator peaks
  double exponentialEndValue = 0;        ///< exponential window at the record end; 0 = automatic
  bool forceWindow = true;
  double doubleHitFraction = 0.1;
  double forceRange = 0, responseRange = 0;  ///< N, m/s^2; 0 = not given
  double bendingModeHz = 0, torsionModeHz = 0;  ///< mode selection hints; 0 = automatic
  bool axesFromModalModel = false;  ///< modal_axes_from: ods (default) or modal_model (LSFD residues)
};

/// Reads and checks a hammer test YAML (strict keys; InputError on any problem). Three or more channels
/// must not be collinear.
FrfTest readFrfTest(const std::filesystem::path& file);

/// Reads every hit CSV: columns present, time strictly increasing and uniform (5 %), equal lengths and
/// sampling across hits. InputError naming the file, line and column otherwise.
std::vector<modal::ImpactRecord> readHits(const FrfTest& test);

/// One identified mode with its uncertainties and modal twist axis.
struct ModeResult {
  double frequencyHz = 0, frequencyStderrHz = 0;  ///< undamped natural frequency |lambda|/(2 pi)
  double dampingRatio = 0, dampingStderr = 0;     ///< viscous ratio zeta
  double lossFactor = 0, lossFactorStderr = 0;    ///< hysteretic eta = 2 zeta (seed section 3.2)
  double halfPowerFrequencyHz = 0, halfPowerDampingRatio = 0;  ///< quick estimate (NaN if none)
  int order = 0, stableCount = 0;
  bool hasAxis = false;
  TwistAxis axis;                   ///< from the ODS (rotation in ODS units)
  double armStderr = 0, betaStderrDeg = 0;
  double mpc = 0;                   ///< modal phase collinearity of the ODS, 0..1
  double coherence = 0;             ///< lowest channel coherence at the resonance bin
  std::string label;                ///< "bending", "torsion" or ""
};

/// Everything the hammer test yields.
struct FrfResult {
  modal::FrfEstimate frf;
  std::vector<std::string> usedHits, rejectedHits;  ///< rejected: "file: reason"
  modal::LscfOptions options;
  modal::BandChoice band;                          ///< the band used and where it came from
  modal::WindowChoice window;                      ///< the exponential window used and why
  bool automaticBand = true, automaticOrders = true;
  std::string orderReason;                         ///< why these orders ("from 2 indicator peaks: 2n .. 4n + 24")
  std::vector<modal::IndicatorPeak> indicatorPeaks;  ///< mode indicator peaks in the band
  std::vector<modal::StabilisationPole> diagram;
  std::vector<modal::ModalEstimate> rejectedClusters;  ///< stable-pole clusters at too few orders
  std::vector<std::string> diagnostics;  ///< indicator peaks without a stable mode; a missing bending/torsion mode
  std::vector<modal::PeakEstimate> peaks;
  std::vector<ModeResult> modes;
  std::vector<modal::ModalModel> models;  ///< per channel, 1/|H|-weighted LSFD, for the overlay
  int bendingIndex = -1, torsionIndex = -1;
};

/// Runs the chain in named stages (docs/swingarm-identification.md, "Processing chain"): hit checks
/// (double hit, overload: rejected), force + exponential windows, H1 and coherence, band and model orders
/// (processing keys, else from the data: modal/automatic_settings.h), LSCF stabilisation diagram and
/// stable-mode selection (Peeters et al. 2004; uncertainty = jackknife over hits combined with the scatter
/// over model orders), half-power estimates, ODS twist axes (seed sec. 2.1: the quadrature part Im(H1) of the
/// ODS at the bin nearest each damped natural frequency, fitted by the plate plane; or, with
/// modal_axes_from: modal_model, the quadrature part of the LSFD residues), bending/torsion labels (hints,
/// else the most strongly excited mode whose axis is within 45 deg of normal to x is bending, of x torsion)
/// and diagnostics (swingarm/identification/frf_diagnosis.h). Frequencies in Hz, damping ratios viscous.
FrfResult identifyFrf(const FrfTest& test, const std::vector<modal::ImpactRecord>& hits);

}  // namespace motostab::swingarm::identification
