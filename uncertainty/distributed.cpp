#include "uncertainty/distributed.h"

#include "io/result_error.h"

#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>

#ifdef MOTOSTAB_WITH_MPI
#include <mpi.h>
#endif

namespace motostab::uncertainty {

bool isLaunchedByMpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(v)) return true;
  return false;
}

DistributedSession::DistributedSession() {
#ifdef MOTOSTAB_WITH_MPI
  if (!isLaunchedByMpi()) return;
  int ready = 0;
  MPI_Initialized(&ready);
  if (!ready) MPI_Init(nullptr, nullptr);
  active_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
#endif
}

DistributedSession::~DistributedSession() {
#ifdef MOTOSTAB_WITH_MPI
  if (active_) MPI_Finalize();
#endif
}

std::vector<size_t> getRankTasks(size_t count, int rank, int size) {
  std::vector<size_t> out;
  for (size_t t = static_cast<size_t>(rank); t < count; t += static_cast<size_t>(size)) out.push_back(t);
  return out;
}

std::vector<double> packResult(const TaskResult& r, size_t parameters, size_t modeValues) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> d{r.ok ? 1.0 : 0.0, static_cast<double>(r.redraws)};
  for (size_t j = 0; j < parameters; ++j) d.push_back(j < r.parameters.size() ? r.parameters[j] : nan);
  d.insert(d.end(), r.firstCrossing.begin(), r.firstCrossing.end());
  for (size_t j = 0; j < modeValues; ++j) d.push_back(j < r.modeValues.size() ? r.modeValues[j] : nan);
  return d;
}

std::string packResultText(const TaskResult& r) { return r.reason + '\x1e' + r.crossings + '\x1f'; }

TaskResult unpackResult(const double* d, size_t parameters, size_t modeValues, const std::string& text) {
  TaskResult r;
  r.ok = d[0] != 0;
  r.redraws = static_cast<int>(d[1]);
  r.parameters.assign(d + 2, d + 2 + parameters);
  for (size_t m = 0; m < r.firstCrossing.size(); ++m) r.firstCrossing[m] = d[2 + parameters + m];
  const double* mv = d + 2 + parameters + r.firstCrossing.size();
  if (r.ok) r.modeValues.assign(mv, mv + modeValues);
  const size_t sep = text.find('\x1e');
  r.reason = text.substr(0, sep);
  r.crossings = sep == std::string::npos ? "" : text.substr(sep + 1);
  return r;
}

namespace {

// Splits the concatenated texts of packResultText.
std::vector<std::string> splitTexts(const std::string& all) {
  std::vector<std::string> out;
  size_t start = 0;
  for (size_t end; (end = all.find('\x1f', start)) != std::string::npos; start = end + 1)
    out.push_back(all.substr(start, end - start));
  return out;
}

}  // namespace

std::vector<TaskResult> gatherResults(const DistributedSession& session, const std::vector<TaskResult>& local,
                                      size_t count, size_t parameters, size_t modeValues) {
  const size_t width = 2 + parameters + kUncertainModes.size() + modeValues;
  std::vector<double> data;
  std::string text;
  for (const auto& r : local) {
    const auto d = packResult(r, parameters, modeValues);
    data.insert(data.end(), d.begin(), d.end());
    text += packResultText(r);
  }
  std::vector<std::vector<double>> rankData(static_cast<size_t>(session.getSize()));
  std::vector<std::string> rankText(rankData.size());
  if (!session.isDistributed()) {
    rankData[0] = std::move(data), rankText[0] = std::move(text);
  } else {
#ifdef MOTOSTAB_WITH_MPI
    const int size = session.getSize(), root = 0;
    auto gather = [&](const void* buf, int n, MPI_Datatype type, size_t bytes, auto& out) {
      std::vector<int> counts(size), offsets(size);
      MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, root, MPI_COMM_WORLD);
      long total = 0;
      for (int r = 0; r < size; ++r) offsets[r] = static_cast<int>(total), total += counts[r];
      if (total > std::numeric_limits<int>::max()) throw io::ResultError("the results of the ranks exceed one MPI_Gatherv (2^31 values): run fewer samples per job");
      std::vector<char> all(session.getRank() == root ? static_cast<size_t>(total) * bytes : 0);
      MPI_Gatherv(buf, n, type, all.data(), counts.data(), offsets.data(), type, root, MPI_COMM_WORLD);
      if (session.getRank() != root) return;
      for (int r = 0; r < size; ++r) {
        auto& o = out[r];
        o.resize(static_cast<size_t>(counts[r]));
        if (counts[r] > 0) std::memcpy(o.data(), all.data() + static_cast<size_t>(offsets[r]) * bytes, counts[r] * bytes);
      }
    };
    gather(data.data(), static_cast<int>(data.size()), MPI_DOUBLE, sizeof(double), rankData);
    gather(text.data(), static_cast<int>(text.size()), MPI_CHAR, 1, rankText);
#endif
  }
  std::vector<TaskResult> out;
  if (session.getRank() != 0) return out;
  out.resize(count);
  for (int r = 0; r < session.getSize(); ++r) {
    const auto tasks = getRankTasks(count, r, session.getSize());
    const auto texts = splitTexts(rankText[r]);
    if (rankData[r].size() != tasks.size() * width || texts.size() != tasks.size())
      throw io::ResultError("rank " + std::to_string(r) + " returned an incomplete set of results");
    for (size_t i = 0; i < tasks.size(); ++i)
      out[tasks[i]] = unpackResult(rankData[r].data() + i * width, parameters, modeValues, texts[i]);
  }
  return out;
}

int reduceMax(const DistributedSession& session, int value) {
#ifdef MOTOSTAB_WITH_MPI
  if (session.isDistributed()) {
    int out = 0;
    MPI_Allreduce(&value, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return out;
  }
#endif
  return value;
}

}  // namespace motostab::uncertainty
