#include "output/response_output.h"

#include <cstdio>
#include <stdexcept>

#include "io/number.h"
#include "output/writer_tools.h"

namespace motostab::output {

using response::IdentificationResult;
using response::ResponseRecord;
using response::calcModelResponse;

nlohmann::json makeModesJson(const IdentificationResult& result, const std::vector<std::string>& signalNames) {
  if (signalNames.size() != result.offset.size())
    throw std::logic_error("makeModesJson: " + std::to_string(signalNames.size()) + " names for " +
                                std::to_string(result.offset.size()) + " signals");
  nlohmann::json modes = nlohmann::json::array();
  for (const auto& m : result.modes) {
    modes.push_back({{"real", m.real},
                     {"imag", m.imag},
                     {"frequency_hz", m.frequencyHz},
                     {"damping_ratio", m.dampingRatio},
                     {"kind", m.imag > 0 ? "oscillatory" : "real"},
                     {"amplitude", m.amplitude},
                     {"phase_rad", m.phase}});
  }
  nlohmann::json candidates = nlohmann::json::array();
  for (const auto& c : result.candidates)
    candidates.push_back({{"order", c.order},
                          {"pencil_size", c.pencilSize},
                          {"offset", c.offset},
                          {"singular_value_ratio", c.singularValueRatio},
                          {"at_gap", c.atGap},
                          {"r_squared", c.rSquared},
                          {"bic", c.criterion}});
  return {{"method", "matrix pencil (Hua & Sarkar 1990); order: lowest BIC among pencil sizes at a "
                     "singular-value gap; variable-projection Levenberg-Marquardt polish on the original samples"},
          {"model", "y_k(t) = offset_k + sum_m amplitude_mk exp(real_m tau) cos(imag_m tau + phase_mk), "
                    "tau = t - reference_time_s; complex pairs listed once (imag > 0)"},
          {"signals", signalNames},
          {"modes", modes},
          {"offset", result.offset},
          {"order", result.order},
          {"fit",
           {{"r_squared", result.rSquared},
            {"rms_residual", result.rmsResidual},
            {"normalised_rms_residual", result.normalisedRmsResidual}}},
          {"window", {{"start_s", result.windowStart}, {"end_s", result.windowEnd}, {"samples", result.sampleCount}}},
          {"reference_time_s", result.referenceTime},
          {"pencil", {{"resampled", result.resampled}, {"step_s", result.pencilStep},
                      {"singular_values", result.singularValues}}},
          {"candidates", candidates}};
}

std::string formatModesTable(const IdentificationResult& result, const std::vector<std::string>& signalNames) {
  std::string out;
  char line[256];
  std::snprintf(line, sizeof line, "%-4s %12s %12s %12s %10s  %s\n", "mode", "real [1/s]", "imag [rad/s]",
                "freq [Hz]", "damping", "amplitude");
  out += line;
  for (size_t i = 0; i < result.modes.size(); ++i) {
    const auto& m = result.modes[i];
    std::string amps;
    for (size_t s = 0; s < m.amplitude.size(); ++s) {
      char a[64];
      std::snprintf(a, sizeof a, "%s%.4g", s ? ", " : "", m.amplitude[s]);
      amps += a;
    }
    std::snprintf(line, sizeof line, "%-4zu %12.5f %12.5f %12.5f %10.5f  %s\n", i + 1, m.real, m.imag, m.frequencyHz,
                  m.dampingRatio, amps.c_str());
    out += line;
  }
  std::snprintf(line, sizeof line, "order %d, R^2 = %.6f, window %.6g to %.6g s (%d samples)\n", result.order,
                result.rSquared, result.windowStart, result.windowEnd, result.sampleCount);
  out += line;
  for (size_t s = 0; s < signalNames.size() && s < result.rmsResidual.size(); ++s) {
    std::snprintf(line, sizeof line, "  %s: offset %.6g, rms residual %.4g (%.4g of its std dev)\n",
                  signalNames[s].c_str(), result.offset[s], result.rmsResidual[s], result.normalisedRmsResidual[s]);
    out += line;
  }
  return out;
}

void writeResponseReport(const std::filesystem::path& dir, const ResponseRecord& record,
                         const IdentificationResult& result, const nlohmann::json& extra) {
  nlohmann::json json = makeModesJson(result, record.signalColumns);
  json["source"] = {{"file", record.source}, {"time_column", record.timeColumn}};
  json.update(extra);
  writeFileAtomically(dir / "modes.json", formatJson(json, "modes.json"));

  std::vector<std::string> header{record.timeColumn};
  header.insert(header.end(), record.signalColumns.begin(), record.signalColumns.end());
  CsvWriter data(header);
  for (size_t i = 0; i < record.time.size(); ++i) {
    data.beginRow().add(record.time[i]);
    for (const auto& s : record.signals) data.add(s[i]);
  }
  writeFileAtomically(dir / "response_data.csv", data.getText());

  // The model on a grid 10x finer than the samples (at least 500 points) over the window.
  const int points = std::max(500, 10 * result.sampleCount);
  std::vector<double> dense(points);
  for (int i = 0; i < points; ++i)
    dense[i] = result.windowStart + (result.windowEnd - result.windowStart) * i / (points - 1);
  std::vector<std::string> fitHeader{record.timeColumn};
  std::vector<std::vector<double>> model;
  for (size_t s = 0; s < record.signalColumns.size(); ++s) {
    fitHeader.push_back("model_" + record.signalColumns[s]);
    model.push_back(calcModelResponse(result, static_cast<int>(s), dense));
  }
  CsvWriter fit(fitHeader);
  for (int i = 0; i < points; ++i) {
    fit.beginRow().add(dense[i]);
    for (const auto& m : model) fit.add(m[i]);
  }
  writeFileAtomically(dir / "response_fit.csv", fit.getText());

  char title[200] = "no mode";
  if (!result.modes.empty())
    std::snprintf(title, sizeof title, "dominant mode %.4g %+.4gi 1/s (%.4g Hz, damping ratio %.3g), R^2 = %.4f",
                  result.modes.front().real, result.modes.front().imag, result.modes.front().frequencyHz,
                  result.modes.front().dampingRatio, result.rSquared);
  std::string body = "  set datafile separator ','\n  set grid\n  set key top right\n";
  body += "  set multiplot layout " + std::to_string(record.signalColumns.size()) + ",1 title " +
          gnuplotQuote(title) + " noenhanced\n";
  for (size_t s = 0; s < record.signalColumns.size(); ++s) {
    body += "  set xlabel " + gnuplotQuote(record.timeColumn) + " noenhanced\n";
    body += "  set ylabel " + gnuplotQuote(record.signalColumns[s]) + " noenhanced\n";
    for (double t : {result.windowStart, result.windowEnd})
      body += "  set arrow from " + formatNumber(t) + ", graph 0 to " + formatNumber(t) +
              ", graph 1 nohead dt 2 lc rgb 'gray50'\n";
    body += "  plot 'response_data.csv' skip 1 using 1:" + std::to_string(s + 2) +
            " with lines lc rgb 'gray40' title 'record', 'response_fit.csv' skip 1 using 1:" +
            std::to_string(s + 2) + " with lines lw 2 lc rgb 'red' title 'fitted model'\n";
    body += "  unset arrow\n";
  }
  body += "  unset multiplot";
  renderGnuplot(dir, "response_fit", body);
}

}  // namespace motostab::output
