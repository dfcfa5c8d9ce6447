#include "output/uncertainty_output.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "output/writer_tools.h"

namespace motostab::output {

using uncertainty::ModeQuantiles;
using uncertainty::SamplingMethod;
using uncertainty::TaskKind;
using uncertainty::TaskResult;
using uncertainty::UncertaintySetup;
using uncertainty::UncertaintySummary;
using uncertainty::UncertaintyTask;
using uncertainty::getTask;

using uncertainty::kUncertainModes;
namespace {

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

std::string getMethodName(SamplingMethod m) { return m == SamplingMethod::Sobol ? "sobol" : "mc"; }

std::string getSensitivityName(SamplingMethod m) {
  return m == SamplingMethod::Sobol ? "first-order Sobol indices (Jansen estimator, Saltelli et al. 2010, Table 2 f)"
                                    : "standardised regression coefficients with R^2 (Saltelli et al. 2008, sec. 1.2.5)";
}

std::string getKindName(const UncertaintySetup& s, const UncertaintyTask& t) {
  switch (t.kind) {
    case TaskKind::Sample: return "sample";
    case TaskKind::SobolA: return "A";
    case TaskKind::SobolB: return "B";
    case TaskKind::SobolAB: return "AB:" + s.params[t.param].path;
    case TaskKind::Nominal: return "nominal";
    case TaskKind::Plus: return "plus:" + s.params[t.param].path;
    case TaskKind::Minus: return "minus:" + s.params[t.param].path;
  }
  return "";
}

// A CSV text cell: quoted, inner quotes doubled, line breaks as spaces.
std::string quoteCell(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' || c == '\r' ? ' ' : c);
  return out + "\"";
}

bool hasFiniteValue(const std::vector<double>& v) {
  return std::any_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

// Parameter indices ranked by |sensitivity| (NaNs last).
std::vector<size_t> rankParameters(const std::vector<double>& sensitivity) {
  std::vector<size_t> order(sensitivity.size());
  std::iota(order.begin(), order.end(), 0);
  auto key = [&](size_t j) { return std::isnan(sensitivity[j]) ? -1.0 : std::abs(sensitivity[j]); };
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return key(a) > key(b); });
  return order;
}

nlohmann::json makeModesJson(const UncertaintySummary& sum) {
  nlohmann::json modes = nlohmann::json::object();
  for (const auto& q : sum.modes) {
    nlohmann::json m;
    for (int p = 0; p < 3; ++p) {
      static const char* names[] = {"p05", "p50", "p95"};
      nlohmann::json re = nlohmann::json::array(), fr = nlohmann::json::array();
      for (size_t k = 0; k < sum.speeds.size(); ++k) re.push_back(number(q.real[k][p])), fr.push_back(number(q.frequency[k][p]));
      m[std::string("real_") + names[p] + "_per_s"] = re;
      m[std::string("frequency_") + names[p] + "_hz"] = fr;
    }
    m["count"] = q.count;
    modes[q.mode] = m;
  }
  return modes;
}

}  // namespace

nlohmann::json makeUncertaintyJson(const std::string& name, const UncertaintySetup& s, const UncertaintySummary& sum) {
  nlohmann::json j;
  j["scenario"] = name;
  j["method"] = getMethodName(s.options.method);
  j["seed"] = s.options.seed;
  j["sensitivity_method"] = s.options.method == SamplingMethod::Sobol ? "sobol_first_order" : "src";
  j["samples"] = {{"requested", s.options.samples}, {"drawn", sum.samples}, {"succeeded", sum.succeeded},
                  {"failed", sum.failed}, {"redraws", sum.redraws}, {"sweeps", sum.tasks}};
  j["speeds_mps"] = {{"start", s.options.start}, {"stop", s.options.stop}, {"step", s.options.step},
                     {"values", sum.speeds}};
  nlohmann::json params = nlohmann::json::array();
  for (size_t p = 0; p < s.params.size(); ++p) {
    static const char* dist[] = {"normal", "uniform", "lognormal"};
    params.push_back({{"path", s.params[p].path}, {"nominal", s.nominal[p]}, {"sigma", s.params[p].sigma},
                      {"distribution", dist[static_cast<int>(s.params[p].distribution)]}});
  }
  j["parameters"] = params;
  nlohmann::json crit = nlohmann::json::object();
  for (const auto& c : sum.criticalSpeeds) {
    nlohmann::json sens = nlohmann::json::array();
    for (size_t p : rankParameters(c.sensitivity))
      sens.push_back({{"parameter", s.params[p].path}, {"index", number(c.sensitivity[p])},
                      {"derivative", number(c.derivatives[p])}});
    crit[c.mode] = {{"mean_mps", number(c.mean)}, {"std_mps", number(c.std)}, {"p05_mps", number(c.p05)},
                    {"p50_mps", number(c.p50)}, {"p95_mps", number(c.p95)}, {"fraction", number(c.fraction)},
                    {"count", c.count}, {"first_order_std_mps", number(c.firstOrderStd)},
                    {"nominal_mps", number(c.nominal)}, {"sensitivity", sens}, {"r2", number(c.r2)}};
  }
  j["critical_speeds"] = crit;
  j["modes"] = makeModesJson(sum);
  return j;
}

std::string makeSamplesCsv(const UncertaintySetup& s, const std::vector<TaskResult>& results) {
  std::vector<std::string> header{"task", "kind", "row", "status", "redraws"};
  for (const auto& p : s.params) header.push_back(p.path);
  for (analysis::ModeLabel m : kUncertainModes) header.push_back(std::string(analysis::toString(m)) + "_speed_mps");
  header.push_back("crossings");
  header.push_back("reason");
  CsvWriter csv(header);
  for (size_t t = 1 + 2 * s.params.size(); t < results.size(); ++t) {
    const TaskResult& r = results[t];
    const UncertaintyTask task = getTask(s, t);
    csv.beginRow().add(std::to_string(t)).add(getKindName(s, task)).add(std::to_string(task.row));
    csv.add(r.ok ? "ok" : "failed").add(std::to_string(r.redraws));
    for (size_t p = 0; p < s.params.size(); ++p) csv.addOrEmpty(p < r.parameters.size() ? r.parameters[p] : NAN);
    for (double v : r.firstCrossing) csv.addOrEmpty(v);
    csv.add(quoteCell(r.crossings)).add(quoteCell(r.reason));
  }
  return csv.getText();
}

std::string makeUncertaintyReport(const std::string& name, const UncertaintySetup& s, const UncertaintySummary& sum) {
  std::ostringstream r;
  auto f = [](double v, int digits = 4) { return std::isfinite(v) ? formatNumber(v, digits) : std::string("-"); };
  r << "# Uncertainty of stability: " << name << "\n\n"
    << "Method `" << getMethodName(s.options.method) << "`, seed " << s.options.seed << ", " << sum.samples
    << " samples drawn (" << sum.succeeded << " succeeded), " << sum.tasks << " sweeps in all, " << sum.failed
    << " failed, " << sum.redraws << " unphysical draws replaced. Speeds " << s.options.start << "-" << s.options.stop
    << " m/s, step " << s.options.step << " m/s.\n\n## Parameters\n\n| parameter | nominal | sigma | distribution |\n|---|---|---|---|\n";
  for (size_t p = 0; p < s.params.size(); ++p) {
    static const char* dist[] = {"normal", "uniform", "lognormal"};
    r << "| `" << s.params[p].path << "` | " << f(s.nominal[p], 6) << " | " << f(s.params[p].sigma, 4) << " | "
      << dist[static_cast<int>(s.params[p].distribution)] << " |\n";
  }
  r << "\n## Critical speeds (first crossing in the range, m/s)\n\n"
    << "| mode | nominal | fraction | mean | std | first-order std | p05 | p50 | p95 |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& c : sum.criticalSpeeds)
    r << "| " << c.mode << " | " << f(c.nominal) << " | " << f(c.fraction, 3) << " | " << f(c.mean) << " | " << f(c.std, 3)
      << " | " << f(c.firstOrderStd, 3) << " | " << f(c.p05) << " | " << f(c.p50) << " | " << f(c.p95) << " |\n";
  r << "\nFirst-order std: sqrt(J Sigma J^T), J by central differences at +/- " << s.options.derivativeStep
    << " sigma about the nominal scenario.\n\n## Sensitivity: " << getSensitivityName(s.options.method) << "\n";
  for (const auto& c : sum.criticalSpeeds) {
    if (c.count == 0) continue;
    r << "\n### " << c.mode;
    if (s.options.method == SamplingMethod::MonteCarlo) r << " (R^2 = " << f(c.r2, 4) << ")";
    r << "\n\n";
    if (!hasFiniteValue(c.sensitivity))
      r << (s.options.method == SamplingMethod::MonteCarlo
                ? "No index: the regression on " + std::to_string(s.params.size()) + " parameters needs at least " +
                      std::to_string(s.params.size() + 2) + " samples with this crossing (" + std::to_string(c.count) + " here).\n\n"
                : std::string("No index: fewer than two complete rows, or no spread of the speed.\n\n"));
    r << "| rank | parameter | index | dv/dx (m/s per unit) |\n|---|---|---|---|\n";
    int rank = 0;
    for (size_t p : rankParameters(c.sensitivity))
      r << "| " << ++rank << " | `" << s.params[p].path << "` | " << f(c.sensitivity[p], 3) << " | " << f(c.derivatives[p], 4)
        << " |\n";
  }
  r << "\nFiles: `summary.json`, `samples.csv`, `mode_quantiles.csv`, `sensitivity.csv`, fan charts "
       "`fan_real_part`, `fan_frequency`, histograms `histogram_<mode>`, bars `sensitivity_<mode>` (.gp/.png/.svg).\n";
  return r.str();
}

namespace {

// mode_quantiles.csv: per fan mode (in blocks) and speed the count and 5/50/95 % real part and frequency.
std::string makeModeQuantilesCsv(const UncertaintySummary& sum) {
  CsvWriter csv({"speed_mps", "mode", "count", "real_p05", "real_p50", "real_p95", "frequency_p05_hz",
                 "frequency_p50_hz", "frequency_p95_hz"});
  for (const auto& q : sum.modes)
    for (size_t k = 0; k < sum.speeds.size(); ++k) {
      csv.beginRow().add(sum.speeds[k]).add(q.mode).add(std::to_string(q.count[k]));
      for (double v : q.real[k]) csv.addOrEmpty(v);
      for (double v : q.frequency[k]) csv.addOrEmpty(v);
    }
  return csv.getText();
}

// sensitivity.csv: per critical speed the ranked parameters. `rows` gets each mode's first and
// last data row (0-based, header excluded) for the bar charts.
std::string makeSensitivityCsv(const UncertaintySetup& s, const UncertaintySummary& sum,
                               std::vector<std::pair<size_t, size_t>>& rows) {
  CsvWriter csv({"mode", "rank", "parameter", "index", "derivative"});
  size_t line = 0;
  rows.clear();
  for (const auto& c : sum.criticalSpeeds) {
    rows.push_back({line, line + s.params.size() - 1});
    int rank = 0;
    for (size_t p : rankParameters(c.sensitivity)) {
      csv.beginRow().add(c.mode).add(std::to_string(++rank)).add(s.params[p].path);
      csv.addOrEmpty(c.sensitivity[p]);
      csv.addOrEmpty(c.derivatives[p]);
      ++line;
    }
  }
  return csv.getText();
}

const std::string kCommon = "  set datafile separator ','\n  set grid\n  set key outside right\n";

// Whether a fan mode has a finite 5-95 % band value somewhere (frequency: `frequency`, else real part).
// gnuplot stops with an error on a plot whose every point is undefined.
bool hasFiniteBand(const ModeQuantiles& q, bool frequency) {
  for (const auto& k : frequency ? q.frequency : q.real)
    if (std::isfinite(k[0]) || std::isfinite(k[2])) return true;
  return false;
}

// Fan chart of column triple (p05, p50, p95) = (c, c+1, c+2) of mode_quantiles.csv against speed, one
// row of panels per mode with a finite band (c = 7: frequency): left the band and the median, each
// panel scaled to its mode, right the band's width p95 - p05, which stays readable when the band is thin
// beside the median's change with speed. Empty when no mode has a band.
std::string makeFanBody(const UncertaintySummary& sum, int c, const std::string& title, const std::string& quantity,
                        const std::string& unit) {
  std::vector<size_t> shown;
  for (size_t m = 0; m < sum.modes.size(); ++m)
    if (hasFiniteBand(sum.modes[m], c == 7)) shown.push_back(m);
  if (shown.empty()) return "";
  const std::string lo = std::to_string(c), mid = std::to_string(c + 1), hi = std::to_string(c + 2);
  // No key inside the panels (it would cover the curves): the title says what the line and the band are.
  std::string b = "  set datafile separator ','\n  set grid\n  unset key\n  set xzeroaxis lt -1\n"
                  "  set style fill transparent solid 0.35 noborder\n  set multiplot layout " +
                  std::to_string(shown.size()) + ",2 title " + gnuplotText(title) +
                  " margins 0.1, 0.98, 0.1, 0.9 spacing 0.14, 0.08\n";
  for (size_t i = 0; i < shown.size(); ++i) {
    const std::string mode = sum.modes[shown[i]].mode, lt = std::to_string(shown[i] + 1);
    const std::string sel = "(strcol(2) eq '" + mode + "' ? $";
    const std::string xlabel = i + 1 == shown.size() ? "'forward speed v (m/s)'" : "''";
    b += "  set xlabel " + xlabel + "\n  set ylabel " + gnuplotText(mode + " " + quantity + " (" + unit + ")") + "\n" +
         "  plot 'mode_quantiles.csv' skip 1 using 1:" + sel + lo + " : NaN):" + sel + hi + " : NaN) with filledcurves lt " + lt +
         " title '5-95 %', \\\n       'mode_quantiles.csv' skip 1 using 1:" + sel + mid + " : NaN) with lines lt " + lt +
         " lw 2 title 'median'\n" + "  set ylabel " + gnuplotText("p95 - p05 (" + unit + ")") + "\n" +
         "  plot 'mode_quantiles.csv' skip 1 using 1:" + sel + hi + " - $" + lo + " : NaN) with lines lt " + lt +
         " lw 2 title 'p95 - p05'\n";
  }
  return b + "  unset multiplot\n";
}

// Histogram of one samples.csv column (1-based), binned by gnuplot into 30 bins over its range.
std::string makeHistogramBody(const std::string& mode, int column) {
  const std::string c = std::to_string(column);
  return kCommon + "  set title " + gnuplotText("First " + mode + " critical speed over the samples") +
         "\n  set xlabel 'critical speed (m/s)'\n  set ylabel 'samples'\n  set style fill solid 0.5\n"
         "  stats 'samples.csv' skip 1 using " + c + " nooutput\n"
         "  w = (STATS_max - STATS_min) / 30.0\n  if (w <= 0) { w = 1e-6 }\n"
         "  plot 'samples.csv' skip 1 using (STATS_min + w * (floor((column(" + c + ") - STATS_min) / w) + 0.5)):(1.0) "
         "smooth frequency with boxes title " + gnuplotText(mode) + "\n";
}

std::string makeSensitivityBody(const std::string& mode, std::pair<size_t, size_t> rows, bool sobol) {
  return kCommon + "  set title " + gnuplotText("Sensitivity of the " + mode + " critical speed") +
         "\n  set ylabel " + gnuplotQuote(sobol ? "first-order Sobol index (-)" : "standardised regression coefficient (-)") +
         "\n  set xlabel 'parameter'" +
         "\n  set style fill solid 0.6\n  set boxwidth 0.7\n  set xtics rotate by -45 noenhanced\n  unset key\n"
         "  plot 'sensitivity.csv' skip 1 every ::" + std::to_string(rows.first) + "::" + std::to_string(rows.second) +
         " using 0:4:xtic(3) with boxes\n";
}

}  // namespace

void writeUncertaintyOutputs(const std::filesystem::path& dir, const std::string& name, const UncertaintySetup& s,
                             const UncertaintySummary& sum, const std::vector<TaskResult>& results) {
  std::vector<std::pair<size_t, size_t>> rows;
  writeFileAtomically(dir / "summary.json", formatJson(makeUncertaintyJson(name, s, sum), "summary.json"));
  writeFileAtomically(dir / "samples.csv", makeSamplesCsv(s, results));
  writeFileAtomically(dir / "mode_quantiles.csv", makeModeQuantilesCsv(sum));
  writeFileAtomically(dir / "sensitivity.csv", makeSensitivityCsv(s, sum, rows));
  writeFileAtomically(dir / "report.md", makeUncertaintyReport(name, s, sum));
  // A chart is drawn only when it has a finite value to show (few samples can leave none).
  const std::string fanReal = makeFanBody(sum, 4, "Real part against speed: median (line), 5-95 % band (shaded); right, the band's width: " + name, "real part", "1/s");
  const std::string fanFrequency = makeFanBody(sum, 7, "Frequency against speed: median (line), 5-95 % band (shaded); right, the band's width: " + name, "frequency", "Hz");
  if (!fanReal.empty()) renderGnuplot(dir, "fan_real_part", fanReal);
  if (!fanFrequency.empty()) renderGnuplot(dir, "fan_frequency", fanFrequency);
  const bool sobol = s.options.method == SamplingMethod::Sobol;
  for (size_t m = 0; m < sum.criticalSpeeds.size(); ++m) {
    const auto& c = sum.criticalSpeeds[m];
    if (c.count < 2) continue;
    renderGnuplot(dir, "histogram_" + c.mode, makeHistogramBody(c.mode, static_cast<int>(6 + s.params.size() + m)));
    if (hasFiniteValue(c.sensitivity)) renderGnuplot(dir, "sensitivity_" + c.mode, makeSensitivityBody(c.mode, rows[m], sobol));
  }
}

}  // namespace motostab::output
