#include "studies/study_findings.h"

#include <cmath>

namespace motostab::studies {

using analysis::ModeBranch;
using analysis::ModeLabel;

namespace {

constexpr double kWobbleMinSpeed = 10.0;  // m/s

const StudyVariant* findVariant(const std::vector<StudyVariant>& list, const std::string& name) {
  for (const auto& v : list)
    if (v.name == name) return &v;
  return nullptr;
}

WobbleFindings calcWobbleFindings(const StudyResult& st) {
  const StudyVariant* rigid = findVariant(st.nominal, "rigid");
  WobbleFindings out;
  out.minSpeed = kWobbleMinSpeed;
  double fMin = INFINITY, fMax = 0, reMax = -INFINITY, shift = 0;
  for (const auto& v : st.nominal) {
    const ModeBranch* w = findBranch(v.sweep, ModeLabel::Wobble);
    const ModeBranch* w0 = rigid ? findBranch(rigid->sweep, ModeLabel::Wobble) : nullptr;
    if (!w) continue;
    for (size_t k = 0; k < w->eigenvalue.size(); ++k) {
      if (v.sweep.speeds[k] < kWobbleMinSpeed) continue;
      const double f = std::abs(w->eigenvalue[k].imag()) / (2 * M_PI);
      fMin = std::min(fMin, f), fMax = std::max(fMax, f), reMax = std::max(reMax, w->eigenvalue[k].real());
      if (w0) shift = std::max(shift, std::abs(w->eigenvalue[k] - w0->eigenvalue[k]) / std::abs(w0->eigenvalue[k]));
    }
  }
  out.minFrequencyHz = fMin, out.maxFrequencyHz = fMax, out.maxRealPart = reMax, out.maxRelativeShift = shift;
  return out;
}

WeaveFindings calcWeaveFindings(const StudyResult& st) {
  WeaveFindings out;
  const StudyVariant* rigid = findVariant(st.nominal, "rigid");
  const ModeBranch* w = rigid ? findBranch(rigid->sweep, ModeLabel::Weave) : nullptr;
  if (!w) return out;
  double fLo = INFINITY, fHi = 0, best = INFINITY, bestV = 0;
  for (size_t k = 0; k < w->eigenvalue.size(); ++k) {
    const double f = std::abs(w->eigenvalue[k].imag()) / (2 * M_PI);
    if (f > 0) fLo = std::min(fLo, f), fHi = std::max(fHi, f);
    if (rigid->sweep.speeds[k] >= 10 && w->eigenvalue[k].real() < best) best = w->eigenvalue[k].real(), bestV = rigid->sweep.speeds[k];
  }
  out.present = true;
  out.minFrequencyHz = fLo, out.maxFrequencyHz = fHi, out.mostStableRealPart = best, out.mostStableSpeed = bestV;
  return out;
}

std::vector<ComplianceEffectRow> calcComplianceEffect(const StudyResult& st) {
  std::vector<ComplianceEffectRow> rows;
  const StudyVariant* rigid = findVariant(st.nominal, "rigid");
  const StudyVariant* rigidHalf = findVariant(st.halved, "rigid");
  for (double speed : {12.0, 17.0, 20.0, 23.0, 26.0, 35.0}) {
    for (const auto& v : st.nominal) {
      if (!rigid || v.name == "rigid") continue;
      const StudyVariant* h = findVariant(st.halved, v.name);
      const double a = getWeaveRealPart(v, speed), a0 = getWeaveRealPart(*rigid, speed);
      const double b = h ? getWeaveRealPart(*h, speed) : NAN, b0 = rigidHalf ? getWeaveRealPart(*rigidHalf, speed) : NAN;
      rows.push_back({speed, v.name, a, 100 * (a - a0) / std::abs(a0), b, 100 * (b - b0) / std::abs(b0)});
    }
  }
  return rows;
}

// The nominal variants with the lowest and the highest mean weave real part over 17-26 m/s.
void findMostAndLeastStable(const StudyResult& st, StudyFindings& out) {
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& v : st.nominal) {
    double mean = 0;
    int n = 0;
    for (double speed = 17; speed <= 26; speed += 1) mean += getWeaveRealPart(v, speed), ++n;
    mean /= n;
    if (mean < lo) lo = mean, out.mostStable = v.name;
    if (mean > hi) hi = mean, out.leastStable = v.name;
  }
}

std::vector<SwingarmModeFinding> calcSwingarmModes(const StudyResult& st) {
  std::vector<SwingarmModeFinding> out;
  for (const auto& v : st.nominal)
    for (const auto& b : v.sweep.branches)
      if ((b.label == ModeLabel::SwingarmBending || b.label == ModeLabel::SwingarmTorsion || b.label == ModeLabel::SwingarmTwist) &&
          b.eigenvalue.back().imag() > 0)
        out.push_back({v.name, analysis::toString(b.label), v.sweep.speeds.front(), v.sweep.speeds.back(),
                       b.eigenvalue.front().imag() / (2 * M_PI), b.eigenvalue.back().imag() / (2 * M_PI)});
  return out;
}

}  // namespace

double getWeaveRealPart(const StudyVariant& v, double speed) {
  const ModeBranch* b = findBranch(v.sweep, ModeLabel::Weave);
  if (!b) return NAN;
  size_t k = 0;
  for (size_t i = 0; i < v.sweep.speeds.size(); ++i)
    if (std::abs(v.sweep.speeds[i] - speed) < std::abs(v.sweep.speeds[k] - speed)) k = i;
  return b->eigenvalue[k].real();
}

StudyFindings calcStudyFindings(const StudyResult& study) {
  StudyFindings out;
  out.wobble = calcWobbleFindings(study);
  out.weave = calcWeaveFindings(study);
  out.complianceEffect = calcComplianceEffect(study);
  findMostAndLeastStable(study, out);
  out.swingarmModes = calcSwingarmModes(study);
  return out;
}

}  // namespace motostab::studies
