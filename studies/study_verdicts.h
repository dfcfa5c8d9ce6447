#pragma once
// The seed paper's findings (diagnosis/findings.h) set against a motorcycle: a verdict per finding
// (agrees, disagrees, cannot be checked) with the paper's statement and motostab's figure side by side,
// the cause diagnosis names for the disagreements (or the look-alikes it cannot tell apart), the gain,
// and the extended motorcycle's verdicts. Computing only: output/study_verdicts_output.h formats it.
//
// Verdict of a finding with violation g and stated tolerance tau (findings.h): agrees when g <= tau
// (its likelihood term (g/tau)^2 <= 1), disagrees when g > tau, cannot be checked when the motorcycle
// has no such mode over the finding's speeds or refuses its variant or change.
#include <cmath>
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "diagnosis/measured_data.h"
#include "scenario/parameter_overrides.h"
#include "scenario/scenario_source.h"

namespace motostab::studies {

enum class Verdict { Agrees, Disagrees, CannotBeChecked };

/// "agrees", "disagrees", "cannot be checked".
const char* toString(Verdict v);

/// One motorcycle's figure for one finding, from the mode's eigenvalues at the finding's speeds.
struct FindingFigure {
  Verdict verdict = Verdict::CannotBeChecked;
  double violation = NAN;  ///< g, in the finding's unit (findings.h)
  /// The figure in the finding's terms: stable / unstable: the largest / smallest real part (1/s);
  /// frequency_within: the lowest and highest frequency (Hz); most_stable_near: the speed of the
  /// lowest real part (m/s); change_below: the largest change (%).
  double value = NAN, valueHigh = NAN;
  double atSpeed = NAN;    ///< m/s where `value` is reached (not for frequency_within)
  std::string text;        ///< the figure in words, e.g. "largest real part +4.62 1/s at 50 m/s"
};

struct FindingVerdict {
  int index = 0;               ///< 1-based position in the findings file
  diagnosis::Finding finding;
  std::string statement;       ///< the paper's statement with its tolerance
  std::string reason;          ///< why it cannot be checked (empty otherwise)
  FindingFigure base, extended;
};

/// A fitted value with its 95 % profile-likelihood interval (key unit).
struct FittedValue {
  std::string name;
  double value = 0, low = 0, high = 0;
  std::string note;
};

/// A candidate's fit against the findings: a named cause, or an alternative.
struct CauseFit {
  std::string name;
  std::vector<FittedValue> values;
  double deltaBic = 0;      ///< against the base motorcycle
  double pValue = 1;
  std::vector<std::string> failed;  ///< criteria not met (empty for a named cause)
};

struct NamedCause {
  CauseFit fit;
  /// Candidates the findings cannot tell from it (BIC within 2, or the same change of the residuals).
  std::vector<CauseFit> alike;
};

struct StudyVerdicts {
  std::string findingsFile;
  std::vector<FindingVerdict> findings;
  std::vector<std::string> candidates;      ///< offered to the diagnosis
  std::vector<std::string> unavailable;     ///< not offered, with why
  std::vector<NamedCause> causes;           ///< in the order named
  std::vector<CauseFit> ranked;             ///< every first-step candidate, best (lowest BIC) first
  double devianceBefore = 0, devianceAfter = 0, bicBefore = 0, bicAfter = 0;
  int numChecked = 0;                       ///< findings in the likelihood (checkable ones)
  std::vector<std::string> extendedOverrides;  ///< what makes extended.yaml from the scenario
  double seconds = 0;                       ///< wall time of the diagnosis
};

struct VerdictOptions {
  std::string findingsFile;
  /// Candidate names offered where the scenario admits them (others are listed as unavailable): the
  /// seed's own list of what FastBike models carry and Table 6 does not give.
  std::vector<std::string> candidates{"steer_damper", "rider_arms", "fork_compliance", "tyre_relaxation"};
  /// True when the user named the candidates (--candidates): a name this build does not offer for the
  /// scenario without a reason why (a misspelling) is then an InputError at --candidates.
  bool candidatesGiven = false;
  int maxCauses = 2;
  int threads = 2;
  scenario::ParameterOverrides overrides;   ///< applied to the scenario first (the study's --set)
};

/// The candidate names of `options` the scenario admits, in order; the others go to `unavailable` with
/// why (e.g. "rider_arms: the rear frame (80 kg) is lighter than a 80 kg rider ..."). With
/// `candidatesGiven`, a name offered nowhere and unavailable for no stated reason is an InputError.
std::vector<std::string> selectStudyCandidates(const scenario::ScenarioSource& source, const VerdictOptions& options,
                                               std::vector<std::string>& unavailable);

/// The verdicts, the diagnosis of the disagreements and the extended motorcycle's verdicts.
StudyVerdicts runStudyVerdicts(std::shared_ptr<const scenario::ScenarioSource> source, const VerdictOptions& options);

/// The paper's statement of `f` with its tolerance, e.g. "wobble stable over 0-50 m/s (+/- 0.5 1/s)".
std::string describeFinding(const diagnosis::Finding& f);

/// The figure of `f` from its probe eigenvalues `probes` (diagnosis/findings.h makeProbeRows order).
FindingFigure calcFindingFigure(const diagnosis::Finding& f, const std::complex<double>* probes);

}  // namespace motostab::studies
