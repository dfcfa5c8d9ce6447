#include "output/study_verdicts_output.h"

#include <cmath>
#include <sstream>

#include "diagnosis/diagnosis.h"
#include "diagnosis/findings.h"
#include "output/writer_tools.h"

namespace motostab::output {

using nlohmann::json;
using studies::CauseFit;
using studies::FindingFigure;
using studies::FindingVerdict;
using studies::StudyVerdicts;
using studies::Verdict;

namespace {

std::string num(double x, int digits = 3) { return std::isfinite(x) ? formatNumber(x, digits) : "-"; }

json finiteOrNull(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

std::string formatValues(const CauseFit& c) {
  std::string s;
  for (const auto& v : c.values) {
    s += (s.empty() ? "" : ", ") + v.name + " " + num(v.value, 4);
    if (v.low != v.value || v.high != v.value) s += " (95 % profile interval " + num(v.low, 4) + "-" + num(v.high, 4) + ")";
  }
  return s;
}

std::string formatFailed(const CauseFit& c) {
  std::string s;
  for (const auto& f : c.failed) s += (s.empty() ? "" : "; ") + f;
  return s.empty() ? "meets every criterion" : s;
}

// The findings that disagree before and agree after (or the reverse with `worse`).
std::vector<int> findChanged(const StudyVerdicts& v, bool worse) {
  std::vector<int> out;
  for (const auto& f : v.findings)
    if (f.base.verdict == (worse ? Verdict::Agrees : Verdict::Disagrees) &&
        f.extended.verdict == (worse ? Verdict::Disagrees : Verdict::Agrees))
      out.push_back(f.index);
  return out;
}

int countVerdict(const StudyVerdicts& v, Verdict which, bool extended) {
  int n = 0;
  for (const auto& f : v.findings) n += (extended ? f.extended.verdict : f.base.verdict) == which;
  return n;
}

std::string listIndices(const std::vector<int>& k) {
  std::string s;
  for (int i : k) s += (s.empty() ? "" : ", ") + std::to_string(i);
  return s.empty() ? "none" : s;
}

void appendTable(std::ostream& o, const StudyVerdicts& v) {
  o << "| # | paper (statement, tolerance) | motostab | violation | verdict | extended motostab | violation | verdict |\n"
       "|---|---|---|---|---|---|---|---|\n";
  for (const auto& f : v.findings) {
    const std::string unit = diagnosis::getFindingUnit(f.finding.kind);
    o << "| " << f.index << " | " << f.statement << " | ";
    if (f.base.verdict == Verdict::CannotBeChecked) {
      o << f.reason << " | - | **cannot be checked** | - | - | cannot be checked |\n";
      continue;
    }
    o << f.base.text << " | " << num(f.base.violation) << " " << unit << " | **" << toString(f.base.verdict) << "** | "
      << f.extended.text << " | " << num(f.extended.violation) << " " << unit << " | " << toString(f.extended.verdict) << " |\n";
  }
  o << "\nSources: ";
  for (const auto& f : v.findings) o << (f.index > 1 ? "; " : "") << f.index << ": " << f.finding.source;
  o << ".\n\n";
}

void appendCauses(std::ostream& o, const StudyVerdicts& v) {
  o << "### Why: the cause diagnosis names\n\nCandidates offered (the seed's own list of what FastBike's models carry and "
       "Table 6 does not give): ";
  for (size_t i = 0; i < v.candidates.size(); ++i) o << (i ? ", " : "") << "`" << v.candidates[i] << "`";
  o << ". Not offered: " << (v.unavailable.empty() ? "none" : "") << "\n";
  for (const auto& u : v.unavailable) o << "- " << u << "\n";
  o << "\n";
  if (v.causes.empty())
    o << "No candidate meets every criterion of a cause (docs/diagnosis.md): the findings do not name one. "
         "The candidates, best first:\n\n";
  for (const auto& c : v.causes) {
    o << "- **" << c.fit.name << "**: " << formatValues(c.fit) << "; delta BIC " << num(c.fit.deltaBic, 4) << ", p "
      << num(c.fit.pValue, 2) << ".\n";
    if (c.alike.empty()) o << "  No other candidate fits the findings alike.\n";
    for (const auto& a : c.alike)
      o << "  - cannot be told apart from `" << a.name << "` (" << formatValues(a) << "; delta BIC " << num(a.deltaBic, 4)
        << ", " << num(a.deltaBic - c.fit.deltaBic, 3) << " from the cause; " << formatFailed(a) << ")\n";
  }
  if (v.causes.empty())
    for (size_t i = 0; i < v.ranked.size() && i < 6; ++i)
      o << "- `" << v.ranked[i].name << "`: " << formatValues(v.ranked[i]) << "; delta BIC " << num(v.ranked[i].deltaBic, 4)
        << "; " << formatFailed(v.ranked[i]) << "\n";
}

void appendGain(std::ostream& o, const StudyVerdicts& v) {
  o << "\n### The gain\n\nDeviance of the " << v.numChecked << " checked findings (sum of (g/tolerance)^2) "
    << num(v.devianceBefore, 4) << " -> " << num(v.devianceAfter, 4) << "; BIC " << num(v.bicBefore, 4) << " -> "
    << num(v.bicAfter, 4) << ". Agree: " << countVerdict(v, Verdict::Agrees, false) << " -> "
    << countVerdict(v, Verdict::Agrees, true) << " of " << v.findings.size() << "; now agree: findings "
    << listIndices(findChanged(v, false)) << "; now disagree: " << listIndices(findChanged(v, true)) << ".\n\n"
    << "`extended.yaml` (this folder) is the motorcycle with the named causes: ";
  if (v.extendedOverrides.empty()) o << "none named, so it equals the scenario.";
  for (size_t i = 0; i < v.extendedOverrides.size(); ++i) o << (i ? ", " : "") << "`" << v.extendedOverrides[i] << "`";
  o << "\n\nFindings state what holds, not where: a finding that holds adds nothing to the likelihood, so they bound a "
       "change rather than locate it, and every value inside the bounds fits alike (the profile interval above is that "
       "range). Candidates that make every finding hold cannot be told apart by them. Diagnosis took "
    << num(v.seconds, 3) << " s.\n\n";
}

json makeFigureJson(const FindingFigure& f) {
  return {{"verdict", toString(f.verdict)}, {"violation", finiteOrNull(f.violation)}, {"value", finiteOrNull(f.value)},
          {"value_high", finiteOrNull(f.valueHigh)}, {"at_speed_mps", finiteOrNull(f.atSpeed)}, {"text", f.text}};
}

json makeCauseJson(const CauseFit& c) {
  json values = json::array();
  for (const auto& x : c.values)
    values.push_back({{"name", x.name}, {"value", finiteOrNull(x.value)}, {"low", finiteOrNull(x.low)},
                      {"high", finiteOrNull(x.high)}, {"note", x.note}});
  return {{"name", c.name}, {"delta_bic", finiteOrNull(c.deltaBic)}, {"p_value", finiteOrNull(c.pValue)},
          {"values", values}, {"failed", c.failed}};
}

}  // namespace

std::string makeVerdictSection(const StudyVerdicts& v) {
  std::ostringstream o;
  o << "## The paper's findings: verdicts\n\nEach finding of the seed's section 4 (`" << v.findingsFile
    << "`) against this motorcycle: it agrees when its violation g (the distance by which motostab's figure misses the "
       "statement, in the finding's unit; docs/diagnosis.md, Findings) is within the stated tolerance, disagrees "
       "otherwise. Beside it the extended motorcycle (`extended.yaml`, with the causes named below).\n\n";
  appendTable(o, v);
  appendCauses(o, v);
  appendGain(o, v);
  return o.str();
}

std::string makeVerdictSummary(const StudyVerdicts& v) {
  std::ostringstream o;
  o << "Seed findings (" << v.findingsFile << "): agree " << countVerdict(v, Verdict::Agrees, false) << ", disagree "
    << countVerdict(v, Verdict::Disagrees, false) << ", cannot be checked " << countVerdict(v, Verdict::CannotBeChecked, false)
    << " of " << v.findings.size() << "\n";
  for (const auto& f : v.findings) {
    o << "  " << f.index << ". " << f.statement << "\n     motostab: "
      << (f.base.verdict == Verdict::CannotBeChecked ? f.reason : f.base.text) << " -> " << toString(f.base.verdict);
    if (f.base.verdict != Verdict::CannotBeChecked)
      o << "; extended: " << f.extended.text << " -> " << toString(f.extended.verdict);
    o << "\n";
  }
  if (v.causes.empty()) o << "Cause: none named (the findings do not single one out; best: "
                          << (v.ranked.empty() ? std::string("-") : v.ranked[0].name + ", delta BIC " + num(v.ranked[0].deltaBic, 4)) << ")\n";
  for (const auto& c : v.causes) {
    o << "Cause: " << c.fit.name << " " << formatValues(c.fit) << ", delta BIC " << num(c.fit.deltaBic, 4) << "\n";
    for (const auto& a : c.alike) o << "  cannot be told apart from " << a.name << " (delta BIC " << num(a.deltaBic, 4) << ")\n";
  }
  o << "Gain: deviance " << num(v.devianceBefore, 4) << " -> " << num(v.devianceAfter, 4) << ", BIC " << num(v.bicBefore, 4)
    << " -> " << num(v.bicAfter, 4) << "; now agree: findings " << listIndices(findChanged(v, false)) << "\n";
  return o.str();
}

json makeVerdictJson(const StudyVerdicts& v) {
  json findings = json::array();
  for (const auto& f : v.findings) {
    json j = {{"index", f.index},
              {"kind", diagnosis::getFindingKindName(f.finding.kind)},
              {"mode", analysis::toString(f.finding.mode)},
              {"speeds_mps", {f.finding.speedMin, f.finding.speedMax}},
              {"statement", f.statement},
              {"source", f.finding.source},
              {"tolerance", f.finding.tolerance},
              {"unit", diagnosis::getFindingUnit(f.finding.kind)},
              {"verdict", toString(f.base.verdict)},
              {"reason", f.reason},
              {"motostab", makeFigureJson(f.base)},
              {"extended", makeFigureJson(f.extended)}};
    findings.push_back(j);
  }
  json causes = json::array(), ranked = json::array();
  for (const auto& c : v.causes) {
    json j = makeCauseJson(c.fit);
    j["indistinguishable"] = json::array();
    for (const auto& a : c.alike) j["indistinguishable"].push_back(makeCauseJson(a));
    causes.push_back(j);
  }
  for (const auto& c : v.ranked) ranked.push_back(makeCauseJson(c));
  return {{"findings_file", v.findingsFile},
          {"findings", findings},
          {"diagnosis",
           {{"candidates", v.candidates}, {"unavailable", v.unavailable}, {"causes", causes}, {"candidates_ranked", ranked},
            {"checked_findings", v.numChecked}, {"deviance_before", finiteOrNull(v.devianceBefore)},
            {"deviance_after", finiteOrNull(v.devianceAfter)}, {"bic_before", finiteOrNull(v.bicBefore)},
            {"bic_after", finiteOrNull(v.bicAfter)}, {"now_agree", findChanged(v, false)},
            {"now_disagree", findChanged(v, true)}, {"seconds", v.seconds}}},
          {"extended_scenario", "extended.yaml"},
          {"extended_overrides", v.extendedOverrides}};
}

void writeVerdictOutputs(const std::filesystem::path& dir, const std::string& scenarioFile, const StudyVerdicts& v) {
  YAML::Emitter yaml;
  yaml << diagnosis::makeScenarioTree(scenarioFile, v.extendedOverrides);
  writeFileAtomically(dir / "extended.yaml", "# motostab study: " + scenarioFile +
                                                 " with the causes diagnosis names for its disagreements with the seed "
                                                 "paper's findings (verdicts.json)\n" + yaml.c_str() + "\n");
  writeFileAtomically(dir / "verdicts.json", formatJson(makeVerdictJson(v), "verdicts.json"));
}

}  // namespace motostab::output
