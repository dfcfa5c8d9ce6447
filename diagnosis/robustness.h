#pragma once
// Robustness of the named causes: the same stepwise search on other preparations of the same data.
// Each data source is left out in turn (each eigenvalue file, each response run), and the eigenvalue
// rows measured over a speed range are taken at their mid speed (the range dropped). A variant that
// would leave no data, or that equals the original (no row has a range), is skipped. Each rerun takes
// as many steps as the search named causes on all the data (one when it named none).
//
// Verdict per variant, on the first cause (what the engineer acts on):
// - same: the same first cause, each parameter's value consistent with the full data's (their 95 %
//   intervals overlap: the full data's profile interval, the variant's estimate +/- 1.96 stderr);
// - lost power: the variant names nothing where the full data named a cause. Less data may simply not
//   reach the evidence thresholds (the informative source was left out); that is no contradiction
//   (Meinshausen & Buhlmann 2010, Stability selection, JRSS B 72:417, read selection on subsamples as
//   a probability, not a verdict on each);
// - indistinguishable: the variant names a candidate the full data listed as indistinguishable from
//   its cause (the data cannot tell them apart; the report names both already);
// - other cause: another first cause, or one where the full data named none;
// - value differs: the same first cause with a value outside the full data's interval;
// - failed: the search failed on the variant (no verdict).
// The causes are fragile when some variant gives "other cause" or "value differs".
#include <string>
#include <vector>

#include "diagnosis/diagnosis.h"
#include "diagnosis/measured_data.h"

namespace motostab::diagnosis {

/// One preparation of the data: a description ("eigenvalues: <file>", "response run 1: <file>",
/// "speed ranges -> mid speeds") and the data without that source.
struct DataVariant {
  std::string leftOut;
  MeasuredData data;
};

/// The variants of `data` the robustness reruns diagnose.
std::vector<DataVariant> makeRobustnessVariants(const MeasuredData& data);

/// The verdict on a rerun `run` given the full data's causes (see above).
RobustnessVerdict judgeRobustness(const std::vector<Cause>& full, const RobustnessRun& run);

/// Text of a verdict: "same", "lost power", "indistinguishable", "other cause", "value differs", "failed".
const char* getVerdictName(RobustnessVerdict v);

/// Reruns the search (options `opt`, candidates `pool`) on every variant of `data`, each judged.
std::vector<RobustnessRun> runRobustness(const std::string& scenarioFile, const MeasuredData& data, const DiagnosisOptions& opt,
                                         const std::vector<const Candidate*>& pool, const std::vector<Cause>& causes);

}  // namespace motostab::diagnosis
