#pragma once
// The figures the study report sets against each finding of the seed paper's sec. 4, computed from
// a StudyResult (no formatting, no files; output/study_output.h formats them).
#include <string>
#include <vector>

#include "studies/study.h"

namespace motostab::studies {

/// Wobble over the nominal variants, from kWobbleMinSpeed up.
struct WobbleFindings {
  double minSpeed = 0;          ///< m/s; below it the wobble veers with a tyre relaxation oscillation
  double minFrequencyHz = 0;    ///< smallest |imag| / (2 pi), Hz
  double maxFrequencyHz = 0;    ///< largest, Hz
  double maxRealPart = 0;       ///< 1/s
  double maxRelativeShift = 0;  ///< largest |lambda - lambda_rigid| / |lambda_rigid| (fraction)
};

/// Weave of the rigid variant (present only if the study has one with a weave).
struct WeaveFindings {
  bool present = false;
  double minFrequencyHz = 0, maxFrequencyHz = 0;  ///< Hz, over the speeds where it oscillates
  double mostStableRealPart = 0;                  ///< 1/s, lowest real part from 10 m/s up
  double mostStableSpeed = 0;                     ///< m/s, where it is lowest
};

/// One row of the table of Figs. 10 and 11: the weave real part of a compliant variant and its
/// change against the rigid one (%), at identified and at scaled stiffness (NaN where absent).
struct ComplianceEffectRow {
  double speed = 0;  ///< m/s
  std::string variant;
  double identified = 0, identifiedVsRigidPercent = 0;
  double halved = 0, halvedVsRigidPercent = 0;
};

/// A swingarm mode's frequency at the first and last speed of the sweep.
struct SwingarmModeFinding {
  std::string variant, label;
  double firstSpeed = 0, lastSpeed = 0;                   ///< m/s
  double firstFrequencyHz = 0, lastFrequencyHz = 0;       ///< imag / (2 pi), Hz
};

struct StudyFindings {
  WobbleFindings wobble;
  WeaveFindings weave;
  std::vector<ComplianceEffectRow> complianceEffect;  ///< speeds 12, 17, 20, 23, 26, 35 m/s
  std::string mostStable = "-", leastStable = "-";   ///< by mean weave real part over 17-26 m/s
  std::vector<SwingarmModeFinding> swingarmModes;
};

/// The figures of the study report (seed sec. 4 and Figs. 10-11) from `study`.
StudyFindings calcStudyFindings(const StudyResult& study);

/// Real part (1/s) of the weave (upper member) of `variant` at the grid speed nearest `speed`; NaN
/// when it has no weave.
double getWeaveRealPart(const StudyVariant& variant, double speed);

}  // namespace motostab::studies
