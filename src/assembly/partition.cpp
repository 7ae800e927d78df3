#include "catena/assembly/partition.hpp"

#include <metis.h>

#include <algorithm>
#include <string>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"

namespace catena::assembly {
namespace {

// Dual graph in CSR form: elements are vertices, joined when they share a node.
void dual_graph(const model::Model& model, std::vector<idx_t>& xadj, std::vector<idx_t>& adjncy) {
  const size_t n_el = model.elements.size(), n_nodes = model.nodes.size();
  std::vector<std::vector<int>> node_elements(n_nodes);
  for (size_t e = 0; e < n_el; ++e)
    for (int n : model.elements[e].nodes) node_elements[n].push_back(static_cast<int>(e));
  xadj.assign(n_el + 1, 0);
  adjncy.clear();
  std::vector<int> neighbours;
  for (size_t e = 0; e < n_el; ++e) {
    neighbours.clear();
    for (int n : model.elements[e].nodes)
      for (int other : node_elements[n])
        if (other != static_cast<int>(e)) neighbours.push_back(other);
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    for (int o : neighbours) adjncy.push_back(o);
    xadj[e + 1] = static_cast<idx_t>(adjncy.size());
  }
}

// True if every vertex of the CSR graph is reachable from vertex 0 (breadth first).
bool is_connected(const std::vector<idx_t>& xadj, const std::vector<idx_t>& adjncy) {
  const size_t n = xadj.size() - 1;
  if (n == 0) return true;
  std::vector<char> seen(n, 0);
  std::vector<idx_t> queue{0};
  seen[0] = 1;
  for (size_t head = 0; head < queue.size(); ++head)
    for (idx_t k = xadj[queue[head]]; k < xadj[queue[head] + 1]; ++k)
      if (!seen[adjncy[k]]) {
        seen[adjncy[k]] = 1;
        queue.push_back(adjncy[k]);
      }
  return queue.size() == n;
}

}  // namespace

std::vector<int> partition_elements(const model::Model& model, int n_parts) {
  const size_t n_el = model.elements.size();
  std::vector<int> owner(n_el, 0);
  if (n_parts <= 1 || n_el == 0) return owner;
  if (static_cast<size_t>(n_parts) > n_el) {
    // More ranks than elements: one element each, the remaining ranks own nothing.
    for (size_t e = 0; e < n_el; ++e) owner[e] = static_cast<int>(e);
    return owner;
  }
  std::vector<idx_t> xadj, adjncy;
  dual_graph(model, xadj, adjncy);
  idx_t nvtxs = static_cast<idx_t>(n_el), ncon = 1, nparts = n_parts, objval = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;  // reproducible partitions
  // Contiguous parts where the element graph allows them: METIS refuses CONTIG on a
  // disconnected graph (a pantograph touches the wire only through its moving contact,
  // which is no element) and prints an error to stdout, so ask only when connected.
  options[METIS_OPTION_CONTIG] = is_connected(xadj, adjncy) ? 1 : 0;
  std::vector<idx_t> part(n_el, 0);
  const int status =
      METIS_PartGraphKway(&nvtxs, &ncon, xadj.data(), adjncy.data(), nullptr, nullptr, nullptr,
                          &nparts, nullptr, nullptr, options, &objval, part.data());
  if (status != METIS_OK)
    throw Error("METIS_PartGraphKway failed with status " + std::to_string(status) + " for " +
                std::to_string(n_el) + " elements into " + std::to_string(n_parts) + " parts");
  for (size_t e = 0; e < n_el; ++e) owner[e] = static_cast<int>(part[e]);
  return owner;
}

Partition partition_model(MPI_Comm comm, const model::Model& model) {
  Partition p;
  p.n_parts = mpi_size(comm);
  const int n_el = static_cast<int>(model.elements.size());
  p.element_owner.assign(n_el, 0);
  int failed = 0;
  std::string message;
  if (mpi_rank(comm) == 0) {
    try {
      p.element_owner = partition_elements(model, p.n_parts);
    } catch (const Error& e) {
      failed = 1;
      message = e.what();
    }
  }
  MPI_Bcast(&failed, 1, MPI_INT, 0, comm);
  if (failed) {
    broadcast_string(comm, message);
    throw Error(message);
  }
  if (n_el > 0) MPI_Bcast(p.element_owner.data(), n_el, MPI_INT, 0, comm);

  p.node_owner.assign(model.nodes.size(), p.n_parts);
  for (int e = 0; e < n_el; ++e)
    for (int n : model.elements[e].nodes)
      p.node_owner[n] = std::min(p.node_owner[n], p.element_owner[e]);
  for (int& o : p.node_owner)
    if (o == p.n_parts) o = 0;
  return p;
}

}  // namespace catena::assembly
