#include "collective_hdf5_call.hpp"

#include <string>

#include "catena/core/mpi_comm.hpp"
#include "catena/io/output_error.hpp"
#include "hdf5_error.hpp"
#include "space_probe.hpp"
#include "write_fault_injection.hpp"

namespace catena::io {

void agree_on_hdf5_call(MPI_Comm comm, const Hdf5CallSite& site, bool failed, int call_errno) {
  std::string local_failure;
  bool cause_known = false;
  if (failed) {
    local_failure = hdf5_failure_message(site.call, site.file, site.object, call_errno);
    cause_known = names_a_write_cause(call_errno);
  } else if (write_fault_injected(site.call, site.file, site.object)) {
    local_failure = std::string(site.call) + " failed for '" + std::string(site.file) + "'" +
                    (site.object.empty() ? "" : " at " + std::string(site.object)) +
                    ": No space left on device (injected by CATENA_FAULT_INJECT_WRITE)";
    cause_known = true;
  }

  // Ranks in order of preference: those that know the cause, then the other failed ones.
  const int n_ranks = mpi_size(comm);
  const int rank = mpi_rank(comm);
  const int my_candidate =
      local_failure.empty() ? 2 * n_ranks : (cause_known ? rank : n_ranks + rank);
  int best_candidate = 2 * n_ranks;
  MPI_Allreduce(&my_candidate, &best_candidate, 1, MPI_INT, MPI_MIN, comm);
  if (best_candidate == 2 * n_ranks) return;

  const int reporting_rank = best_candidate % n_ranks;
  broadcast_string(comm, local_failure, reporting_rank);
  if (n_ranks > 1) local_failure += " (on rank " + std::to_string(reporting_rank) + ")";
  // No rank's errno told the cause (errno may be overwritten before HDF5 returns, and the
  // MPI-IO driver reports a short write only as "file write failed"): a test write beside
  // the file tells a full disk or an exceeded quota.
  if (best_candidate >= n_ranks) {
    const std::string why = failed_test_write_beside(comm, std::string(site.file));
    if (!why.empty()) local_failure += "; a test write beside it failed: " + why;
  }
  throw OutputError(local_failure);
}

}  // namespace catena::io
