#include "output/diagnosis_output.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "diagnosis/robustness.h"
#include "output/writer_tools.h"

namespace motostab::output {

using diagnosis::Cause;
using diagnosis::ComponentResidual;
using diagnosis::DiagnosisResult;
using diagnosis::FitSummary;
using diagnosis::MeasuredData;
using diagnosis::ParameterEstimate;
using diagnosis::makeScenarioTree;

namespace {

using nlohmann::json;

double finiteOr0(double v) { return std::isfinite(v) ? v : 0.0; }

json makeParameters(const std::vector<ParameterEstimate>& ps) {
  json j = json::object();
  for (const auto& p : ps) {
    json e{{"value", p.value}, {"stderr", p.stderr_}, {"key", p.path}, {"at_bound", p.atBound}};
    if (p.priorSigma > 0)
      e["prior_sigma"] = p.priorSigma, e["change_in_sigmas"] = p.sigmas, e["prior_measured"] = p.priorMeasured;
    if (p.hasProfile) e["profile_interval_95"] = {p.profileLow, p.profileHigh};
    if (!p.note.empty()) e["note"] = p.note;
    j[p.name] = e;
  }
  return j;
}

json makeFit(const FitSummary& f) {
  // A fit that failed (diagnosis/model_fit.h, fitOrFail) has no scores: null, its reason in failed_criteria.
  const bool fitFailed = !f.failed.empty() && f.failed.front().rfind("fit failed", 0) == 0;
  auto score = [&](double v) { return fitFailed ? json(nullptr) : json(v); };
  json j{{"name", f.name}, {"parameters", makeParameters(f.parameters)}, {"rms", score(f.rms)}, {"chi2", score(f.chi2)},
         {"bic", score(f.bic)}, {"delta_bic", score(f.deltaBic)}, {"at_bound", f.atBound}, {"p_value", score(f.pValue)},
         {"num_parameters", f.numParameters}, {"failed_criteria", f.failed}};
  j["cv_rms"] = f.hasCv ? json(f.cvRms) : json(nullptr);
  if (f.hasCv)  // cv_folds: the folds the CV RMS covers (a failed fold has no held-out score)
    j["folds_better"] = f.foldsBetter, j["failed_folds"] = f.foldFailures,
    j["cv_folds"] = f.foldFailed.size() - f.foldFailures.size();
  json corr = json::array();
  for (int r = 0; r < f.correlation.rows(); ++r) {
    json row = json::array();
    for (int c = 0; c < f.correlation.cols(); ++c) row.push_back(finiteOr0(f.correlation(r, c)));
    corr.push_back(row);
  }
  j["correlation"] = corr;
  return j;
}

json makeByMode(const std::vector<ComponentResidual>& rs) {
  json j = json::object();
  for (const auto& r : rs) {
    const auto dot = r.name.rfind('.');
    const std::string mode = r.name.substr(0, dot), part = r.name.substr(dot + 1);
    if (mode.rfind("run", 0) == 0) {
      j[r.name] = {{"mean_residual", r.meanReal}, {"rms_normalised", r.rmsReal}, {"vaf_percent", r.vafAfter}};
    } else if (part == "real+imag") {  // one noise level for both parts (FitProblem::poolSmallComponents)
      j[mode]["mean_residual"] = r.meanReal;
      j[mode]["rms_normalised"] = r.rmsReal;
      j[mode]["rows"] = r.count;
    } else if (part == "real") {
      j[mode]["mean_real_residual"] = r.meanReal;
      j[mode]["slope_real_per_mps"] = r.slopeRealPerMps;
      j[mode]["slope_real_stderr"] = r.slopeStderr;
      j[mode]["slope_real_p"] = r.slopeP;
      j[mode]["rms_real_normalised"] = r.rmsReal;
      j[mode]["rows"] = r.count;
      if (!j[mode].contains("mean_imag_residual")) j[mode]["mean_imag_residual"] = 0.0;
    } else {
      j[mode]["mean_imag_residual"] = r.meanReal;
      j[mode]["rms_imag_normalised"] = r.rmsReal;
    }
  }
  return j;
}

json makeModelSummary(const FitSummary& f, const DiagnosisResult& r, const std::vector<ComponentResidual>& rs) {
  return {{"rms", f.rms}, {"cv_rms", f.cvRms}, {"chi2", f.chi2}, {"bic", f.bic}, {"n_obs", r.numObservations},
          {"by_mode", makeByMode(rs)}};
}

}  // namespace

json makeDiagnosisJson(const DiagnosisResult& r) {
  json j;
  j["baseline"] = makeModelSummary(r.baseline, r, r.residualsBefore);
  j["extended"] = makeModelSummary(r.extended, r, r.residualsAfter);
  j["candidates"] = json::array();
  for (const auto& c : r.candidates) j["candidates"].push_back(makeFit(c));
  j["causes"] = json::array();
  for (const auto& c : r.causes) {
    json e = makeFit(c.fit);
    e["indistinguishable"] = json::array();
    for (const auto& o : c.indistinguishable)
      e["indistinguishable"].push_back({{"name", o.name}, {"parameters", makeParameters(o.parameters)}, {"delta_bic", o.bic - c.fit.bic}});
    j["causes"].push_back(e);
  }
  j["robustness"] = json::array();
  for (const auto& run : r.robustness) {
    json causes = json::array();
    for (const auto& f : run.fits) causes.push_back({{"name", f.name}, {"parameters", makeParameters(f.parameters)}});
    json e{{"left_out", run.leftOut}, {"causes", causes}, {"verdict", getVerdictName(run.verdict)}, {"fragile", run.isFragile()}};
    if (!run.error.empty()) e["error"] = run.error;
    j["robustness"].push_back(e);
  }
  if (!r.robustness.empty()) j["fragile"] = r.isFragile();
  j["pairs"] = json::array();
  for (const auto& p : r.pairs) j["pairs"].push_back(makeFit(p));
  j["contradicts_measurement"] = json::array();
  for (const auto& c : r.contradicting) j["contradicts_measurement"].push_back(makeFit(c));
  const double factor = r.extended.cvRms > 0 ? r.baseline.cvRms / r.extended.cvRms : 0.0;
  j["gain"] = {{"rms_before", r.baseline.rms}, {"rms_after", r.extended.rms}, {"cv_rms_before", r.baseline.cvRms},
               {"cv_rms_after", r.extended.cvRms}, {"factor", factor}};
  j["extended_scenario"] = "extended.yaml";
  j["folds"] = r.numFolds;
  j["noise"] = json::object();
  for (const auto& n : r.noise)
    j["noise"][n.component] = {{"sigma", n.sigma}, {"estimated", n.estimated}, {"ar", n.ar}, {"marginal_sigma", n.marginalSigma}};
  j["unavailable_candidates"] = r.unavailable;
  j["extended_overrides"] = r.extendedOverrides;
  return j;
}

}  // namespace motostab::output

namespace motostab::output {
namespace {

std::string fmt(double v, int digits = 4) { return formatNumber(v, digits); }

std::string makeParameterText(const std::vector<ParameterEstimate>& ps) {
  std::string s;
  for (const auto& p : ps) {
    s += (s.empty() ? "" : ", ") + p.name + " = " + fmt(p.value) + " +/- " + fmt(p.stderr_, 2);
    if (p.priorSigma > 0)
      s += " (" + fmt(p.sigmas, 3) + (p.priorMeasured ? " sigma from the measured " : " default sigma from the scenario's ") +
           fmt(p.priorMean, 6) + ")";
    if (!p.note.empty()) s += " (" + p.note + ")";
  }
  return s;
}

std::string makeDataSection(const DiagnosisResult& r) {
  std::ostringstream o;
  const MeasuredData& d = *r.data;
  o << "## The data\n\n`" << d.file << "` (" << d.name << "): " << d.eigenvalues.size() << " eigenvalue rows, "
    << d.responses.size() << " response runs; " << r.numObservations << " scalar observations, " << r.numFolds
    << " cross-validation folds.\n\nNoise (sigma per component; estimated ones are the extended model's, each "
    << "model being scored with its own estimate; a response signal's residuals as AR(p) noise, sigma its "
    << "innovations', prewhitened in every fit; the RMS values below are of the whitened residuals):\n\n"
    << "| component | sigma | source | AR coefficients | marginal sigma |\n|---|---|---|---|---|\n";
  for (const auto& n : r.noise) {
    std::string ar;
    for (double a : n.ar) ar += (ar.empty() ? "" : ", ") + fmt(a, 3);
    o << "| " << n.component << " | " << fmt(n.sigma) << " | " << (n.estimated ? "estimated" : "given") << " | "
      << (ar.empty() ? "white" : ar) << " | " << fmt(n.marginalSigma) << " |\n";
  }
  return o.str();
}

std::string makeResidualSection(const DiagnosisResult& r) {
  std::ostringstream o;
  o << "\n## What the model gets wrong\n\nBase scenario `" << r.scenarioFile << "`: RMS " << fmt(r.baseline.rms)
    << " (normalised), chi2 " << fmt(r.baseline.chi2) << ", BIC " << fmt(r.baseline.bic) << ".\n\n"
    << "| component | n | mean residual (measured - model) | RMS / sigma (whitened) | trend per m/s (p) | VAF % |\n|---|---|---|---|---|---|\n";
  for (const auto& c : r.residualsBefore) {
    o << "| " << c.name << " | " << c.count << " | " << fmt(c.meanReal) << " | " << fmt(c.rmsReal) << " | ";
    o << (c.slopeStderr > 0 ? fmt(c.slopeRealPerMps) + " (" + fmt(c.slopeP, 2) + ")" : "-") << " | ";
    o << (c.name.rfind("run", 0) == 0 ? fmt(c.vafAfter, 3) : "-") << " |\n";
  }
  return o.str();
}

// " (over k of K folds)" when some folds of `f`'s cross-validation failed; else "".
std::string makeFoldCount(const FitSummary& f) {
  if (f.foldFailures.empty()) return "";
  return " (over " + std::to_string(f.foldFailed.size() - f.foldFailures.size()) + " of " + std::to_string(f.foldFailed.size()) + " folds)";
}

std::string makeCandidateSection(const DiagnosisResult& r) {
  std::ostringstream o;
  o << "\n## Candidates (first step, best BIC first)\n\n| candidate | parameters | RMS | CV RMS | delta BIC | p | unmet criteria |\n|---|---|---|---|---|---|---|\n";
  for (const auto& c : r.candidates) {
    std::string failed;
    for (const auto& f : c.failed) failed += (failed.empty() ? "" : "; ") + f;
    for (const auto& f : c.foldFailures) failed += (failed.empty() ? "" : "; ") + ("CV " + f + ", not counted as better");
    o << "| " << c.name << " | " << makeParameterText(c.parameters) << " | " << fmt(c.rms) << " | "
      << (c.hasCv ? fmt(c.cvRms) + makeFoldCount(c) : "-") << " | " << fmt(c.deltaBic) << " | " << fmt(c.pValue, 2) << " | "
      << (failed.empty() ? "none" : failed) << " |\n";
  }
  if (!r.unavailable.empty()) {
    o << "\nNot available for this scenario or build:\n\n";
    for (const auto& u : r.unavailable) o << "- " << u << "\n";
  }
  return o.str();
}

std::string makeCauseSection(const DiagnosisResult& r) {
  std::ostringstream o;
  o << "\n## The cause\n\n";
  if (r.causes.empty()) {
    o << "No candidate meets every criterion (BIC drop >= 10, likelihood-ratio p < 0.01, cross-validated error lower "
         "in >= 80 % of folds, confidence interval excluding \"off\", correlation <= 0.95): no cause among the "
         "candidates. The residual structure left is that of the table above";
    double worst = 0;
    std::string which;
    for (const auto& c : r.residualsBefore)
      if (c.slopeStderr > 0 && c.slopeP < 0.01 && std::abs(c.slopeRealPerMps) > worst) worst = std::abs(c.slopeRealPerMps), which = c.name;
    if (!which.empty()) o << " (a significant trend with speed in " << which << ")";
    o << ".\n";
    return o.str();
  }
  for (size_t k = 0; k < r.causes.size(); ++k) {
    const Cause& c = r.causes[k];
    o << k + 1 << ". **" << c.fit.name << "**: " << makeParameterText(c.fit.parameters) << "; delta BIC "
      << fmt(c.fit.deltaBic) << ", p " << fmt(c.fit.pValue, 2) << ", CV better in " << c.fit.foldsBetter << " of "
      << r.numFolds << " folds.";
    for (const auto& p : c.fit.parameters)
      if (p.hasProfile) o << " 95 % profile-likelihood interval of " << p.name << ": [" << fmt(p.profileLow) << ", " << fmt(p.profileHigh) << "].";
    o << "\n";
    if (!c.indistinguishable.empty()) {
      o << "   The data cannot tell it apart from (within 2 BIC, or meeting every criterion with a change of the "
           "residuals correlated above 0.95):";
      for (const auto& i : c.indistinguishable) o << " " << i.name << " (" << makeParameterText(i.parameters) << ", delta BIC " << fmt(i.bic - c.fit.bic, 3) << ");";
      o << " measurements at other speeds, with larger amplitudes, or of another mode (wobble, capsize) would separate them.\n";
    }
  }
  return o.str();
}

std::string makePairSection(const DiagnosisResult& r) {
  if (r.pairs.empty()) return "";
  std::ostringstream o;
  o << "\n## Pairs\n\nNo single candidate met every criterion, so pairs of the best singles (by deviance gain) were "
       "fitted together, for effects that partly cancel. A pair must meet the criteria of a cause and need both "
       "members (each alone explains significantly less).\n\n| pair | parameters | delta BIC | p | unmet criteria |\n|---|---|---|---|---|\n";
  for (const auto& p : r.pairs) {
    std::string failed;
    for (const auto& f : p.failed) failed += (failed.empty() ? "" : "; ") + f;
    o << "| " << p.name << " | " << makeParameterText(p.parameters) << " | " << fmt(p.deltaBic) << " | " << fmt(p.pValue, 2)
      << " | " << (failed.empty() ? "none" : failed) << " |\n";
  }
  return o.str();
}

std::string makeContradictionSection(const DiagnosisResult& r) {
  if (r.contradicting.empty()) return "";
  std::ostringstream o;
  o << "\n## Fits, but contradicts the measurement\n\nThese candidates meet every criterion but move a measured "
       "parameter by more than 3 of its sigmas (the scenario's `uncertainty:` section), without the overwhelming "
       "evidence (a BIC at least 40 below the best alternative) that would overrule the measurement. Check the "
       "measurement before believing them:\n\n";
  for (const auto& c : r.contradicting)
    o << "- " << c.name << ": " << makeParameterText(c.parameters) << "; delta BIC " << fmt(c.deltaBic) << "\n";
  return o.str();
}

std::string makeRobustnessSection(const DiagnosisResult& r) {
  if (r.robustness.empty()) return "";
  std::ostringstream o;
  std::string named;
  for (const auto& c : r.causes) named += (named.empty() ? "" : ", ") + c.fit.name;
  o << "\n## Robustness\n\nThe stepwise search rerun on other preparations of the same data (each source left out, "
       "speed ranges taken at their mid speeds). On all the data: "
    << (named.empty() ? "no cause" : named) << ". "
    << (r.isFragile() ? "**Fragile**: some preparation names another first cause, or the same with an inconsistent value."
                      : "Not fragile: no preparation names another first cause or an inconsistent value.")
    << " (Verdicts: same; lost power = names nothing with less data; indistinguishable = names a look-alike the "
       "full data listed; other cause; value differs; failed.)\n\n| left out | causes named | verdict |\n|---|---|---|\n";
  for (const auto& run : r.robustness) {
    std::string causes;
    for (const auto& f : run.fits) causes += (causes.empty() ? "" : "; ") + f.name + " (" + makeParameterText(f.parameters) + ")";
    if (!run.error.empty()) causes = "search failed: " + run.error;
    o << "| " << run.leftOut << " | " << (causes.empty() ? "none" : causes) << " | " << getVerdictName(run.verdict) << " |\n";
  }
  return o.str();
}

std::string makeGainSection(const DiagnosisResult& r) {
  std::ostringstream o;
  o << "\n## The extension\n\n`extended.yaml` is the base scenario with these overrides:\n\n";
  if (r.extendedOverrides.empty()) o << "(none: it equals the base scenario)\n";
  for (const auto& s : r.extendedOverrides) o << "- `" << s << "`\n";
  const double factor = r.extended.cvRms > 0 ? r.baseline.cvRms / r.extended.cvRms : 0.0;
  o << "\n## The gain\n\nRMS (normalised) " << fmt(r.baseline.rms) << " -> " << fmt(r.extended.rms) << "; cross-validated "
    << fmt(r.baseline.cvRms) << " -> " << fmt(r.extended.cvRms) << makeFoldCount(r.extended) << " (factor " << fmt(factor, 3)
    << ").\n\n"
    << "| component | RMS / sigma (whitened) before | after | VAF % before | after |\n|---|---|---|---|---|\n";
  for (size_t k = 0; k < r.residualsAfter.size(); ++k) {
    const auto& a = r.residualsAfter[k];
    const bool run = a.name.rfind("run", 0) == 0;
    o << "| " << a.name << " | " << fmt(r.residualsBefore[k].rmsReal) << " | " << fmt(a.rmsReal) << " | "
      << (run ? fmt(a.vafBefore, 3) : "-") << " | " << (run ? fmt(a.vafAfter, 3) : "-") << " |\n";
  }
  return o.str();
}

std::string makeResidualCsv(const DiagnosisResult& r) {
  CsvWriter w({"component", "speed_mps", "time_s", "measured", "sigma", "predicted_before", "predicted_after",
               "residual_before", "residual_after", "whitened_before", "whitened_after"});
  for (size_t i = 0; i < r.observed.size(); ++i)
    w.beginRow().add(r.observationComponent[i]).addOrEmpty(r.observationSpeed[i]).addOrEmpty(r.observationTime[i]).add(r.observed[i])
        .add(r.sigma[i]).add(r.predictedBefore[i]).add(r.predictedAfter[i])
        .add((r.observed[i] - r.predictedBefore[i]) / r.sigma[i]).add((r.observed[i] - r.predictedAfter[i]) / r.sigma[i])
        .add(i < r.whitenedBefore.size() ? r.whitenedBefore[i] : 0.0).add(i < r.whitenedAfter.size() ? r.whitenedAfter[i] : 0.0);
  return w.getText();
}

// Per mode: speed, measured re/im with sigma, baseline and extended re/im (one line per row).
void writeEigenvaluePlots(const std::filesystem::path& dir, const DiagnosisResult& r) {
  const auto& rows = r.data->eigenvalues;
  std::vector<std::string> modes;
  for (const auto& e : rows) {
    const std::string m = e.mode ? analysis::toString(*e.mode) : "nearest";
    if (std::find(modes.begin(), modes.end(), m) == modes.end()) modes.push_back(m);
  }
  for (const auto& mode : modes) {
    std::vector<std::vector<double>> table(rows.size(), std::vector<double>(10, 0.0));
    for (size_t i = 0; i < r.observed.size(); ++i) {
      const int row = r.observationRow[i];
      if (row < 0) continue;
      const int p = r.observationPart[i];
      auto& t = table[row];
      t[0] = rows[row].speed;
      t[1 + p] = r.observed[i] / (p ? 2 * M_PI : 1);
      t[3 + p] = r.sigma[i] / (p ? 2 * M_PI : 1);
      t[5 + p] = r.predictedBefore[i] / (p ? 2 * M_PI : 1);
      t[7 + p] = r.predictedAfter[i] / (p ? 2 * M_PI : 1);
    }
    CsvWriter w({"speed_mps", "real", "frequency_hz", "real_sigma", "frequency_sigma", "real_before", "frequency_before",
                 "real_after", "frequency_after"});
    for (size_t i = 0; i < rows.size(); ++i)
      if ((rows[i].mode ? analysis::toString(*rows[i].mode) : "nearest") == mode) {
        w.beginRow();
        for (int c = 0; c < 9; ++c) w.add(table[i][c]);
      }
    writeFileAtomically(dir / ("eigen_" + mode + ".csv"), w.getText());
    const std::string f = "'eigen_" + mode + ".csv'";
    renderGnuplot(dir, "eigen_" + mode,
                  "set datafile separator ','\nset key autotitle columnhead outside right top\nset multiplot layout 2,1 title " +
                  gnuplotText(mode + " eigenvalues: measured (error bars: sigma), baseline model, extended model") + "\n"
                  "set xlabel 'forward speed v (m/s)'\nset ylabel 'real part (1/s)'\nset grid\n"
                  "plot " + f + " u 1:2:4 w yerrorbars t 'measured', '' u 1:6 w p pt 6 t 'baseline', '' u 1:8 w p pt 7 t 'extended'\n"
                  "set ylabel 'frequency (Hz)'\n"
                  "plot " + f + " u 1:3:5 w yerrorbars t 'measured', '' u 1:7 w p pt 6 t 'baseline', '' u 1:9 w p pt 7 t 'extended'\n"
                  "unset multiplot\n");
  }
}

// A response plot's vertical axis: the column and its unit (the model's rad or rad/s through the
// signal's scale, or the column's own unit when its gain is fitted).
std::string describeSignalAxis(const diagnosis::ResponseSignal& sig) {
  const bool angle = sig.quantity == diagnosis::Quantity::RollAngle || sig.quantity == diagnosis::Quantity::SteerAngle;
  const std::string unit = angle ? "rad" : "rad/s";
  if (sig.freeScale) return sig.column + " (the column's unit; the models through a fitted gain)";
  if (sig.scale == 1) return sig.column + " (" + unit + ")";
  std::ostringstream os;
  os << sig.column << " (column unit: column x " << sig.scale << " = " << unit << ")";
  return os.str();
}

void writeResponsePlots(const std::filesystem::path& dir, const DiagnosisResult& r) {
  for (size_t run = 0; run < r.data->responses.size(); ++run) {
    const auto& rr = r.data->responses[run];
    for (size_t j = 0; j < rr.signals.size(); ++j) {
      CsvWriter w({"time_s", "measured", "baseline", "extended"});
      for (size_t i = 0; i < r.observed.size(); ++i)
        if (r.observationRun[i] == static_cast<int>(run) && r.observationSignal[i] == static_cast<int>(j))
          w.beginRow().add(r.observationTime[i]).add(r.observed[i]).add(r.predictedBefore[i]).add(r.predictedAfter[i]);
      const std::string name = "run" + std::to_string(run + 1) + "_" + rr.signals[j].column;
      writeFileAtomically(dir / (name + ".csv"), w.getText());
      renderGnuplot(dir, name,
                    "set datafile separator ','\nset key autotitle columnhead\nset grid\nset xlabel 'time (s)'\n"
                    "set title " + gnuplotText("Run " + std::to_string(run + 1) + " at " + fmt(rr.speed, 3) + " m/s: " +
                                               rr.signals[j].column + " (" + getQuantityName(rr.signals[j].quantity) + ")") + "\n"
                    "set ylabel " + gnuplotText(describeSignalAxis(rr.signals[j])) + "\n"
                    "plot '" + name + ".csv' u 1:2 w l t 'measured', '' u 1:3 w l t 'baseline', '' u 1:4 w l t 'extended'\n");
    }
  }
}

}  // namespace

std::string makeDiagnosisReport(const DiagnosisResult& r) {
  return "# Diagnosis of " + r.scenarioFile + " against " + r.data->name + "\n\n" + makeDataSection(r) +
         makeResidualSection(r) + makeCandidateSection(r) + makePairSection(r) + makeCauseSection(r) + makeContradictionSection(r) +
         makeRobustnessSection(r) + makeGainSection(r);
}

void writeDiagnosisOutputs(const std::filesystem::path& dir, const DiagnosisResult& r) {
  YAML::Emitter yaml;
  yaml << makeScenarioTree(r.scenarioFile, r.extendedOverrides);
  writeFileAtomically(dir / "extended.yaml", std::string("# motostab diagnose: ") + r.scenarioFile + " with the named causes\n" + yaml.c_str() + "\n");
  writeFileAtomically(dir / "diagnosis.json", formatJson(makeDiagnosisJson(r), "diagnosis.json"));
  writeFileAtomically(dir / "report.md", makeDiagnosisReport(r));
  writeFileAtomically(dir / "residuals.csv", makeResidualCsv(r));
  writeEigenvaluePlots(dir, r);
  writeResponsePlots(dir, r);
}

}  // namespace motostab::output
