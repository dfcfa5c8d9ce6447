#pragma once
// Which eigenvalue of a candidate model is a measured row's mode. The candidate's linear models come
// from the sweep's own chain at the measured speeds (analysis/sweep.h runSweep), so its modes carry
// the sweep's labels (analysis/modes.h labelBranches: from each branch's content, not its place in
// the spectrum). A row's mode is looked for among the candidate's branches with the row's label, and
// among all eigenvalues only where the candidate has no such branch at that speed. Within that set,
// the match follows two match costs (calcMatchCost): against the base scenario's labelled branch at
// the nearest reference speed, and against the mode's eigenvalue at the candidate's previous speed,
// so that a strong change (stiff fork compliance moving the wobble past another mode, a large steer
// damper) is followed by content and continuity, not by ordering. A real eigenvalue goes to one label
// only; a complex pair may carry two (capsize and castor joined at low speed).
//
// A pair mode (weave, wobble) split into two real roots at a speed (both roots still on the label's
// two branches) is predicted by the mean of the two roots with zero imaginary part: the real part of
// the pair is continuous through the branch point, either root alone jumps there.
#include <complex>
#include <string>
#include <vector>

#include "analysis/sweep.h"
#include "diagnosis/measured_data.h"

namespace motostab::diagnosis {

/// One labelled mode of the rows, followed through a candidate's sweep.
struct ModeTrack {
  analysis::ModeLabel mode = analysis::ModeLabel::Other;
  std::vector<int> index;  ///< eigenvalue per candidate speed (-1: no such mode in the base sweep there)
};

class ModeMatcher {
 public:
  /// `reference`: the base scenario's labelled sweep; `rows`: the measured eigenvalue rows.
  ModeMatcher(const analysis::SweepResult& reference, const std::vector<MeasuredEigenvalue>& rows);
  /// The rows' labelled modes in `candidate` (a sweep at the measured speeds), speed by speed.
  std::vector<ModeTrack> track(const analysis::SweepResult& candidate) const;
  /// The row's eigenvalue (imag >= 0, 1/s) in `candidate` at speed index k: its mode's, or for an
  /// unlabelled row the eigenvalue nearest the measured one. InputError at the row when the
  /// candidate has no such mode there.
  std::complex<double> pick(const analysis::SweepResult& candidate, size_t k, const MeasuredEigenvalue& row,
                            const std::vector<ModeTrack>& tracks) const;

 private:
  Eigen::VectorXd calcCosts(analysis::ModeLabel mode, const analysis::SweepResult& candidate, size_t k, int prevIndex) const;
  std::vector<int> findLabelled(const analysis::SweepResult& candidate, analysis::ModeLabel mode, size_t k) const;

  const analysis::SweepResult& reference_;
  const std::vector<MeasuredEigenvalue>& rows_;
};

}  // namespace motostab::diagnosis
