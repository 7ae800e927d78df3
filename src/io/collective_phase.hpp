#pragma once
// Agreement on failure between the phases of a collective operation.
//
// Parallel HDF5 and MPI-IO calls are collective: if one rank throws and skips the next
// collective call while the others enter it, the job hangs. So the writer is cut into
// phases; each phase runs on every rank, any exception is caught, and at the phase
// boundary the ranks agree (one MPI_Allreduce) whether any of them failed. If so, every
// rank throws the same catena::Error and they all unwind together through the same
// destructors (which include H5Fclose, itself collective).
//
// A phase must not throw on some ranks *before* a collective call that the other ranks
// then enter: keep purely local checks (validation) in their own phase. Collective HDF5
// calls inside a phase agree on their own outcome (collective_hdf5_call.hpp): the
// catena::OutputError they throw is thrown by every rank at the same call, so the phase
// passes it on as it is, without a second agreement.
#include <mpi.h>

#include <filesystem>

#include <exception>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include "catena/io/atomic_file.hpp"
#include "catena/io/output_error.hpp"

namespace catena::io {

// Collective. If `local_error` is non-empty on any rank, throws catena::Error on every
// rank, carrying the message of the lowest failing rank (and that rank's number when the
// communicator has more than one rank).
void throw_if_any_rank_failed(MPI_Comm comm, const std::string& local_error);

// Not collective: the message of the exception currently being handled.
std::string current_exception_message();

// Collective. Runs `phase` on every rank and returns its result; throws on every rank
// (see throw_if_any_rank_failed) if it threw on any.
template <class Phase>
std::invoke_result_t<Phase> run_collective_phase(MPI_Comm comm, Phase&& phase) {
  using Result = std::invoke_result_t<Phase>;
  std::string local_error;
  if constexpr (std::is_void_v<Result>) {
    try {
      std::forward<Phase>(phase)();
    } catch (const OutputError&) {
      throw;  // already agreed: every rank throws it here
    } catch (...) {
      local_error = current_exception_message();
    }
    throw_if_any_rank_failed(comm, local_error);
  } else {
    std::optional<Result> result;
    try {
      result.emplace(std::forward<Phase>(phase)());
    } catch (const OutputError&) {
      throw;  // already agreed: every rank throws it here
    } catch (...) {
      local_error = current_exception_message();
    }
    throw_if_any_rank_failed(comm, local_error);
    return std::move(*result);
  }
}

// Collective. run_collective_phase for a phase that writes output: its agreed failure is
// a catena::OutputError on every rank.
template <class Phase>
std::invoke_result_t<Phase> run_output_phase(MPI_Comm comm, Phase&& phase) {
  try {
    return run_collective_phase(comm, std::forward<Phase>(phase));
  } catch (const OutputError&) {
    throw;
  } catch (const std::exception& agreed) {
    throw OutputError(agreed.what());
  }
}

// Collective. fsyncs `path` once per node: the page cache is per node, and each rank's
// MPI-IO writes sit in its own node's cache, so one fsync per node makes the file durable.
void fsync_once_per_node(MPI_Comm comm, const std::filesystem::path& path);

// A temporary sibling the ranks write together (atomic_file.hpp): named by rank 0's
// process id, so unique per run and the same on every rank; owned by rank 0, which removes
// it unless it is published. Declare it before the file written into it, so that on
// failure the file is closed before its removal.
struct CollectiveTemporary {
  // Collective. The temporary sibling of `target`.
  CollectiveTemporary(MPI_Comm comm, const std::filesystem::path& target);

  std::filesystem::path path;
  std::optional<TemporaryFile> owner;  // rank 0 only
};

// Collective. Makes the file the ranks wrote into `temporary` durable (fsync_once_per_node),
// then rank 0 renames it over `path` and syncs the directory: readers see the old complete
// file or the new one.
void publish_written_file(MPI_Comm comm, CollectiveTemporary& temporary,
                          const std::filesystem::path& path);

}  // namespace catena::io
