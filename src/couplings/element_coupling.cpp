#include "catena/couplings/element_coupling.hpp"

namespace catena::couplings {

ElementCoupling::ElementCoupling(std::unique_ptr<elements::Element> element,
                                 std::vector<int> nodes, ElementOrigin origin, int source)
    : element_(std::move(element)), nodes_(std::move(nodes)), origin_(origin), source_(source) {
  const int dpn = element_->dofs_per_node();
  for (int n : nodes_)
    for (int k = 0; k < dpn; ++k) dofs_.push_back(DofKey::node(n, k));
}

void ElementCoupling::evaluate(const CouplingState& s, double* f,
                               std::span<const MatrixRequest> m, Scratch& scratch) const {
  const size_t n = dofs_.size();
  bool stiffness = false, damping = false, mass = false;
  for (const MatrixRequest& r : m) {
    stiffness |= r.c.c_K != 0.0;
    damping |= r.c.c_C != 0.0;
    mass |= r.c.c_M != 0.0;
  }
  if (!f && !stiffness && !damping && !mass) {
    for (const MatrixRequest& r : m) std::fill(r.out, r.out + n * n, 0.0);
    return;
  }
  double* K = nullptr;
  double* C = nullptr;
  if (stiffness || damping) {
    scratch.b.resize(n * n);
    scratch.c.resize(n * n);
    K = scratch.b.data();
    C = scratch.c.data();
  }
  if (f || stiffness || damping) {
    if (!f) scratch.a.resize(n);
    const elements::LocalState local{s.q, s.v, s.path};
    element_->evaluate(local, {f != nullptr, stiffness, damping},
                       {f ? f : scratch.a.data(), K, C});
  }
  double* M = nullptr;
  if (mass) {
    scratch.d.resize(n * n);
    M = scratch.d.data();
    element_->mass(M);
  }
  for (const MatrixRequest& r : m)
    for (size_t i = 0; i < n * n; ++i) {
      double value = 0.0;
      if (r.c.c_K != 0.0) value += r.c.c_K * K[i];
      if (r.c.c_C != 0.0) value += r.c.c_C * C[i];
      if (r.c.c_M != 0.0) value += r.c.c_M * M[i];
      r.out[i] = value;
    }
}

}  // namespace catena::couplings
