#include "catena/couplings/element_coupling.hpp"

#include <algorithm>

#include "catena/elements/linearized.hpp"

namespace catena::couplings {

namespace {

// Which matrix part a request is, if it is exactly one part with coefficient 1 (an
// element has no multipliers, so c_λ and c_g do not matter): the element then writes
// that part straight into the request's buffer, with no copy.
enum class Part { none, K, C, M };
Part single_part(const JacobianCoefficients& c) {
  const bool k = c.c_K != 0.0, d = c.c_C != 0.0, m = c.c_M != 0.0;
  if (k && !d && !m && c.c_K == 1.0) return Part::K;
  if (d && !k && !m && c.c_C == 1.0) return Part::C;
  if (m && !k && !d && c.c_M == 1.0) return Part::M;
  return Part::none;
}

}  // namespace

ElementCoupling::ElementCoupling(std::unique_ptr<elements::Element> element, std::vector<int> nodes,
                                 ElementOrigin origin, int source)
    : element_(std::move(element)), nodes_(std::move(nodes)), origin_(origin), source_(source) {
  const int dpn = element_->dofs_per_node();
  dofs_.reserve(nodes_.size() * static_cast<size_t>(dpn));
  for (int n : nodes_)
    for (int k = 0; k < dpn; ++k) dofs_.push_back(DofKey::node(n, k));
}

void ElementCoupling::replace_element(std::unique_ptr<elements::Element> element) {
  CATENA_ASSERT(element->n_nodes() == element_->n_nodes() &&
                    element->dofs_per_node() == element_->dofs_per_node(),
                "replace_element: the same nodes and DOFs");
  element_ = std::move(element);
}

void ElementCoupling::evaluate(const CouplingState& s, double* f, std::span<const MatrixRequest> m,
                               Scratch& scratch) const {
  const size_t n = dofs_.size();
  const size_t nn = n * n;
  bool stiffness = false, damping = false, mass = false;
  double *K = nullptr, *C = nullptr, *M = nullptr;
  for (const MatrixRequest& r : m) {
    stiffness |= r.c.c_K != 0.0;
    damping |= r.c.c_C != 0.0;
    mass |= r.c.c_M != 0.0;
    switch (single_part(r.c)) {
      case Part::K:
        K = K ? K : r.out;
        break;
      case Part::C:
        C = C ? C : r.out;
        break;
      case Part::M:
        M = M ? M : r.out;
        break;
      case Part::none:
        break;
    }
  }
  if (stiffness && !K) K = (scratch.b.resize(nn), scratch.b.data());
  if (damping && !C) C = (scratch.c.resize(nn), scratch.c.data());
  if (mass && !M) M = (scratch.d.resize(nn), scratch.d.data());
  if (f || stiffness || damping) {
    if (!f) scratch.a.resize(n);
    const elements::LocalState local{s.q, s.v, s.path};
    element_->evaluate(local, {f != nullptr, stiffness, damping}, {f ? f : scratch.a.data(), K, C});
  }
  if (mass) element_->mass(M);
  // The other requests combine the parts (in the order K, C, M, as 0 + c_K K + ...).
  for (const MatrixRequest& r : m) {
    if (r.out == K || r.out == C || r.out == M) continue;  // written in place above
    if (const Part part = single_part(r.c); part != Part::none) {
      const double* src = part == Part::K ? K : part == Part::C ? C : M;
      std::copy(src, src + nn, r.out);
      continue;
    }
    std::fill(r.out, r.out + nn, 0.0);
    if (r.c.c_K != 0.0)
      for (size_t i = 0; i < nn; ++i) r.out[i] += r.c.c_K * K[i];
    if (r.c.c_C != 0.0)
      for (size_t i = 0; i < nn; ++i) r.out[i] += r.c.c_C * C[i];
    if (r.c.c_M != 0.0)
      for (size_t i = 0; i < nn; ++i) r.out[i] += r.c.c_M * M[i];
  }
}

void ElementCoupling::linearize_about(std::span<const double> q0) {
  element_ = std::make_unique<elements::Linearized>(std::move(element_), q0);
}

}  // namespace catena::couplings
