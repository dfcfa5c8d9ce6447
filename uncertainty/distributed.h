#pragma once
// Distributed uncertainty studies over MPI (docs/distributed.md). The binary is built with MPI when
// CMake finds it (option MOTOSTAB_WITH_MPI); MPI is started only when a launcher (mpirun, srun)
// started the process, so the same binary also runs as one plain process.
//
// Split: rank r of K runs the tasks t with t mod K = r (interleaved, so slow and fast samples spread
// evenly), each on its own threads; rank 0 gathers every result (MPI_Gatherv of a fixed-width
// record of doubles per task, and of the reason and crossing strings) and writes the outputs.
#include <string>
#include <vector>

#include "uncertainty/uncertainty_study.h"

namespace motostab::uncertainty {

/// An MPI session for the lifetime of the object, or a single process.
class DistributedSession {
 public:
  DistributedSession();   ///< MPI_Init when launched by mpirun/srun and built with MPI
  ~DistributedSession();  ///< MPI_Finalize if it started MPI
  DistributedSession(const DistributedSession&) = delete;
  DistributedSession& operator=(const DistributedSession&) = delete;

  int getRank() const { return rank_; }
  int getSize() const { return size_; }
  bool isDistributed() const { return active_; }

 private:
  int rank_ = 0, size_ = 1;
  bool active_ = false;
};

/// True when the environment shows an MPI launcher (OMPI_COMM_WORLD_SIZE, PMIX_RANK, PMI_RANK, PMI_SIZE).
bool isLaunchedByMpi();

/// The tasks of `rank` among `size`: t in [0, count) with t mod size = rank.
std::vector<size_t> getRankTasks(size_t count, int rank, int size);

/// A task result as doubles (ok, redraws, parameters, first crossings, mode values) and text
/// (reason, crossings); exact round trip.
std::vector<double> packResult(const TaskResult& r, size_t parameters, size_t modeValues);
std::string packResultText(const TaskResult& r);
TaskResult unpackResult(const double* record, size_t parameters, size_t modeValues, const std::string& text);

/// Every task's result on rank 0, in task order (other ranks get an empty vector). `local` holds
/// this rank's results for getRankTasks(count, rank, size).
std::vector<TaskResult> gatherResults(const DistributedSession& session, const std::vector<TaskResult>& local,
                                      size_t count, size_t parameters, size_t modeValues);

/// The maximum over ranks of a flag (1 when some rank failed), so that all ranks agree.
int reduceMax(const DistributedSession& session, int value);

}  // namespace motostab::uncertainty
