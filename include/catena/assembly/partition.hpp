#pragma once
// Element partition (METIS k-way on the element dual graph) and node ownership.
// Every rank holds the whole Model; the partition is computed on rank 0 and broadcast so
// that all ranks agree bit for bit.
#include <mpi.h>

#include <vector>

#include "catena/model/model.hpp"

namespace catena::assembly {

struct Partition {
  int n_parts = 1;
  std::vector<int> element_owner;  // per Model::elements entry
  std::vector<int> node_owner;     // lowest rank owning an element at the node; 0 if none
};

// Collective.
Partition partition_model(MPI_Comm comm, const model::Model& model);

// Not collective. METIS k-way partition of elements into n_parts (exposed for tests).
std::vector<int> partition_elements(const model::Model& model, int n_parts);

}  // namespace catena::assembly
