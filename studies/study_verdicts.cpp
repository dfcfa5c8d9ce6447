#include "studies/study_verdicts.h"

#include <algorithm>
#include <chrono>
#include <complex>

#include "diagnosis/candidates.h"
#include "diagnosis/diagnosis.h"
#include "diagnosis/findings.h"
#include "io/csv.h"
#include "io/input_error.h"
#include "plugins/builtin.h"

namespace motostab::studies {

using diagnosis::DiagnosisOptions;
using diagnosis::DiagnosisResult;
using diagnosis::Finding;
using diagnosis::FindingKind;
using diagnosis::FitSummary;
using diagnosis::MeasuredData;
using io::formatNumber;

namespace {

// The model-extension candidates of `all` (not the one-parameter `parameter:<path>` ones), comma-separated.
std::string listCandidateNames(const std::vector<diagnosis::Candidate>& all) {
  std::string out;
  for (const auto& c : all)
    if (c.name.rfind("parameter:", 0) != 0) out += (out.empty() ? "" : ", ") + c.name;
  return out.empty() ? "none" : out;
}

std::string num(double x, int digits = 3) { return formatNumber(x, digits); }

std::string signedNum(double x, int digits = 3) { return (x > 0 ? "+" : "") + num(x, digits); }

std::string speedRange(const Finding& f) {
  return f.speedMax > f.speedMin ? num(f.speedMin) + "-" + num(f.speedMax) + " m/s" : num(f.speedMin) + " m/s";
}

// The speeds of `f` where `holds` is false, as "a-b m/s" (the first and last such speed), or "".
template <class Pred>
std::string findFailingRange(const std::vector<double>& v, const std::complex<double>* l, Pred holds) {
  double lo = NAN, hi = NAN;
  for (size_t i = 0; i < v.size(); ++i)
    if (!holds(l[i])) lo = std::isnan(lo) ? v[i] : lo, hi = v[i];
  if (std::isnan(lo)) return "";
  return lo == hi ? num(lo) + " m/s" : num(lo) + "-" + num(hi) + " m/s";
}

CauseFit summariseFit(const FitSummary& f) {
  CauseFit c;
  c.name = f.name;
  c.deltaBic = f.deltaBic;
  c.pValue = f.pValue;
  c.failed = f.failed;
  for (const auto& e : f.parameters)
    c.values.push_back({e.name, e.value, e.hasProfile ? e.profileLow : e.value, e.hasProfile ? e.profileHigh : e.value, e.note});
  return c;
}

}  // namespace

std::vector<std::string> selectStudyCandidates(const scenario::ScenarioSource& source, const VerdictOptions& opt,
                                               std::vector<std::string>& unavailable) {
  std::vector<std::string> why;
  const auto sections = plugins::listSectionFields(plugins::makeScenarioRegistry(source.load(opt.overrides)));
  const auto all = diagnosis::listCandidates(source.makeTree(opt.overrides), {}, &why, {}, sections);
  std::vector<std::string> out;
  for (const auto& name : opt.candidates) {
    if (std::any_of(all.begin(), all.end(), [&](const auto& c) { return c.name == name; })) {
      out.push_back(name);
      continue;
    }
    const auto reason = std::find_if(why.begin(), why.end(), [&](const auto& w) { return w.rfind(name + ":", 0) == 0; });
    if (reason == why.end() && opt.candidatesGiven)
      throw io::InputError({"--candidates", 0, 0, name}, "is not a candidate cause this scenario admits (offered: " +
                                                             listCandidateNames(all) + ")");
    unavailable.push_back(reason != why.end() ? *reason : name + ": not offered for this scenario");
  }
  return out;
}

namespace {

// runDiagnosis on the checkable findings: a finding the scenario cannot evaluate (no such mode, a
// variant or change it refuses) is an InputError at the finding's entry; it is marked and left out.
DiagnosisResult diagnoseCheckable(std::shared_ptr<const scenario::ScenarioSource> source, MeasuredData& data,
                                  const DiagnosisOptions& opt, std::vector<FindingVerdict>& verdicts, std::vector<int>& kept) {
  for (;;) {
    try {
      return diagnosis::runDiagnosis(source, data, opt);
    } catch (const io::InputError& e) {
      size_t k = 0;
      while (k < data.findings.size() && !(data.findings[k].where.line == e.getLocation().line &&
                                          data.findings[k].where.file == e.getLocation().file))
        ++k;
      if (k == data.findings.size() || data.findings.size() == 1) throw;
      verdicts[kept[k]].reason = e.getReason();
      data.findings.erase(data.findings.begin() + k);
      kept.erase(kept.begin() + k);
    }
  }
}

}  // namespace

const char* toString(Verdict v) {
  switch (v) {
    case Verdict::Agrees: return "agrees";
    case Verdict::Disagrees: return "disagrees";
    case Verdict::CannotBeChecked: return "cannot be checked";
  }
  return "";
}

std::string describeFinding(const Finding& f) {
  const std::string mode = analysis::toString(f.mode);
  std::string s;
  switch (f.kind) {
    case FindingKind::Stable: s = mode + " stable over " + speedRange(f); break;
    case FindingKind::Unstable: s = mode + " unstable over " + speedRange(f); break;
    case FindingKind::FrequencyWithin:
      s = mode + " at " + num(f.frequencyMin) + "-" + num(f.frequencyMax) + " Hz over " + speedRange(f);
      break;
    case FindingKind::MostStableNear: s = mode + " most stable near " + num(f.speed) + " m/s (of " + speedRange(f) + ")"; break;
    case FindingKind::ChangeBelow: {
      std::string change;
      for (const auto& c : f.change) change += (change.empty() ? "" : ", ") + c;
      s = mode + " moved less than " + num(f.percent) + " % by " + change + " over " + speedRange(f);
      break;
    }
  }
  if (!f.variant.empty()) {
    std::string v;
    for (const auto& c : f.variant) v += (v.empty() ? "" : ", ") + c;
    s += " (with " + v + ")";
  }
  return s + ", tolerance " + num(f.tolerance) + " " + diagnosis::getFindingUnit(f.kind);
}

FindingFigure calcFindingFigure(const Finding& f, const std::complex<double>* l) {
  const std::vector<double> v = diagnosis::getFindingSpeeds(f);
  FindingFigure out;
  out.violation = diagnosis::calcFindingViolation(f, l);
  out.verdict = std::abs(out.violation) <= f.tolerance ? Verdict::Agrees : Verdict::Disagrees;
  size_t k = 0;
  switch (f.kind) {
    case FindingKind::Stable:
    case FindingKind::Unstable: {
      const bool stable = f.kind == FindingKind::Stable;
      for (size_t i = 1; i < v.size(); ++i)
        if (stable ? l[i].real() > l[k].real() : l[i].real() < l[k].real()) k = i;
      out.value = l[k].real(), out.atSpeed = v[k];
      out.text = std::string(stable ? "largest" : "smallest") + " real part " + signedNum(out.value) + " 1/s at " + num(v[k]) + " m/s";
      const std::string bad = findFailingRange(v, l, [&](auto x) { return stable ? x.real() <= 0 : x.real() >= 0; });
      out.text += bad.empty() ? "" : std::string("; ") + (stable ? "unstable" : "stable") + " at " + bad;
      break;
    }
    case FindingKind::FrequencyWithin: {
      out.value = INFINITY, out.valueHigh = 0;
      for (size_t i = 0; i < v.size(); ++i) {
        const double hz = std::abs(l[i].imag()) / (2 * M_PI);
        out.value = std::min(out.value, hz), out.valueHigh = std::max(out.valueHigh, hz);
      }
      out.text = num(out.value) + "-" + num(out.valueHigh) + " Hz";
      break;
    }
    case FindingKind::MostStableNear:
      out.value = f.speed + out.violation;
      out.atSpeed = out.value;
      out.text = "most stable at " + num(out.value) + " m/s";
      break;
    case FindingKind::ChangeBelow: {
      out.value = -1;
      for (size_t i = 0; i < v.size(); ++i) {
        const double p = 100 * std::abs(l[v.size() + i] - l[i]) / std::max(std::abs(l[i]), 1e-300);
        if (p > out.value) out.value = p, out.atSpeed = v[i];
      }
      out.text = "largest change " + num(out.value) + " % at " + num(out.atSpeed) + " m/s";
      break;
    }
  }
  return out;
}

StudyVerdicts runStudyVerdicts(std::shared_ptr<const scenario::ScenarioSource> source, const VerdictOptions& opt) {
  StudyVerdicts out;
  out.findingsFile = opt.findingsFile;
  MeasuredData data = diagnosis::loadMeasuredData(opt.findingsFile);
  if (data.findings.empty()) throw io::InputError({opt.findingsFile, 0, 0, "findings"}, "the file states no findings");
  std::vector<int> kept;
  for (size_t k = 0; k < data.findings.size(); ++k) {
    FindingVerdict fv;
    fv.index = static_cast<int>(k) + 1;
    fv.finding = data.findings[k];
    fv.statement = describeFinding(data.findings[k]);
    out.findings.push_back(fv);
    kept.push_back(static_cast<int>(k));
  }
  DiagnosisOptions dopt;
  dopt.candidates = out.candidates = selectStudyCandidates(*source, opt, out.unavailable);
  dopt.maxCauses = opt.maxCauses;
  dopt.threads = opt.threads;
  dopt.overrides = opt.overrides;
  dopt.candidateTableCv = false;  // the causes are the same; the table needs no extra folds
  const auto start = std::chrono::steady_clock::now();
  const DiagnosisResult r = diagnoseCheckable(source, data, dopt, out.findings, kept);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  size_t probe = data.eigenvalues.size();
  for (size_t k = 0; k < data.findings.size(); ++k) {
    FindingVerdict& fv = out.findings[kept[k]];
    fv.base = calcFindingFigure(data.findings[k], &r.before.eigenvalues[probe]);
    fv.extended = calcFindingFigure(data.findings[k], &r.after.eigenvalues[probe]);
    probe += diagnosis::countProbeRows(data.findings[k]);
  }
  out.numChecked = static_cast<int>(data.findings.size());
  out.unavailable.insert(out.unavailable.end(), r.unavailable.begin(), r.unavailable.end());
  for (const auto& c : r.causes) {
    NamedCause n{summariseFit(c.fit), {}};
    for (const auto& a : c.indistinguishable) n.alike.push_back(summariseFit(a));
    out.causes.push_back(n);
  }
  for (const auto& c : r.candidates) out.ranked.push_back(summariseFit(c));
  out.devianceBefore = r.baseline.deviance, out.devianceAfter = r.extended.deviance;
  out.bicBefore = r.baseline.bic, out.bicAfter = r.extended.bic;
  out.extendedOverrides = r.extendedOverrides;
  return out;
}

}  // namespace motostab::studies
