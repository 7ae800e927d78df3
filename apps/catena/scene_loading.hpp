#pragma once
#include <mpi.h>

#include <string>
#include <vector>

#include "catena/model/memory_estimate.hpp"
#include "catena/model/model.hpp"
#include "cli.hpp"

namespace catena::app {

// Collective. Rank 0 reads and checks the file, every rank parses the same text, so all
// ranks hold the same Model or all throw the same InputError (also when the run would not
// fit `budget`).
model::Model load_scene(MPI_Comm comm, const std::string& path,
                        const std::vector<std::string>& overrides,
                        const model::MemoryBudget& budget = {});

// Collective over the whole job, once, before any part of it runs on a communicator of its
// own: how many of the job's ranks share this rank's host, for memory_budget.
void record_job_layout(MPI_Comm world);

// Collective. The memory a run on `comm` may use per host: the smallest host's physical
// memory, or --memory-limit; the ranks, and the most of them on one host (MPI shared-memory
// groups). Where other ranks of the job share a host (record_job_layout), this run's share.
model::MemoryBudget memory_budget(MPI_Comm comm, const CommandLine& cl);

}  // namespace catena::app
