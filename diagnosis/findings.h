#pragma once
// Findings (measured_data.h Finding): what papers, road tests and riders report of a mode without its
// eigenvalues, read strictly from the `findings:` list of a measured-data file, and their likelihood
// terms beside eigenvalue rows and responses (docs/diagnosis.md, Findings).
//
// A finding is predicted from its probe rows: the mode's eigenvalue lambda_i at the speeds v_i of its
// speed grid (getFindingSpeeds), and for a ChangeBelow finding also lambda'_i with its change applied.
// Its violation g (in the finding's unit) is, with h_i >= 0 the violation at v_i:
//   Stable            h_i = max(0, Re lambda_i)                                  1/s
//   Unstable          h_i = max(0, -Re lambda_i)                                 1/s
//   FrequencyWithin   h_i = max(0, f1 - f_i, f_i - f2),  f_i = |Im lambda_i| / (2 pi)     Hz
//   ChangeBelow       h_i = max(0, 100 |lambda'_i - lambda_i| / |lambda_i| - p)  percentage points
//   g = sqrt(mean_i h_i^2)          (one-sided, censored: zero wherever the finding holds)
//   MostStableNear    g = v* - v,  v* the speed of the lowest Re lambda_i, refined by the parabola
//                     through it and its neighbours (an interior minimum)                  m/s
// and its likelihood term is -2 ln L = (g / tau)^2 with tau the stated tolerance: a half-normal
// penalty beyond an interval's edge (a soft bound), a normal one about a stated speed.
#include <complex>
#include <vector>

#include "diagnosis/measured_data.h"
#include "io/yaml_map.h"
#include "scenario/scenario_source.h"

namespace motostab::diagnosis {

/// "stable", "unstable", "frequency_within", "most_stable_near", "change_below".
const char* getFindingKindName(FindingKind kind);

/// Reads one entry of `findings:` (docs/measured-data-format.md). Strict: an unknown key or kind, an
/// unknown mode label, a speed range outside [0, kMaxMeasuredSpeed] or empty, a frequency interval
/// with f1 > f2, a speed outside the range, a non-positive tolerance, a tolerance key of another kind,
/// or an unreadable change is an InputError at its line and column.
Finding readFinding(io::YamlMap m);

/// The speeds a finding is evaluated at (m/s): its range in equal steps of at most 1 m/s (3 to 101
/// points; one point for an empty range).
std::vector<double> getFindingSpeeds(const Finding& f);

/// Number of probe rows of `f`: its speeds, twice for ChangeBelow (without, then with the change).
size_t countProbeRows(const Finding& f);

/// The probe rows of every finding of `findings`, finding by finding (countProbeRows each): the mode
/// at each speed, the variant (and for the changed rows of ChangeBelow the change after it) as the
/// rows' `controller` overrides, so that the prediction's groups (controller_groups.h) predict them
/// with those applied.
std::vector<MeasuredEigenvalue> makeProbeRows(const std::vector<Finding>& findings);

/// The violation g of `f` (its unit, above) from its predicted probe rows `probes` (countProbeRows of
/// them, in makeProbeRows' order, imag >= 0).
double calcFindingViolation(const Finding& f, const std::complex<double>* probes);

/// Loads `source` with `base`, then each finding's variant, and its change after it: a variant or change
/// the scenario refuses is an InputError at the finding's `variant` or `change` key (its line and
/// column), with the scenario's reason.
void checkFindingChanges(const scenario::ScenarioSource& source, const scenario::ParameterOverrides& base,
                         const std::vector<Finding>& findings);

/// The key paths the findings' variants and changes set (e.g. swingarm.compliance), sorted and unique:
/// a candidate setting one of them would undo a finding's variant or change.
std::vector<std::string> getFindingPaths(const std::vector<Finding>& findings);

/// The unit of a finding's tolerance and violation ("1/s", "Hz", "m/s", "%").
const char* getFindingUnit(FindingKind kind);

}  // namespace motostab::diagnosis
