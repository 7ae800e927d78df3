#include "catena/couplings/bilateral_contact.hpp"

#include <algorithm>

#include "catena/core/error.hpp"

namespace catena::couplings {
namespace {

constexpr int kPath = ContactPath::kActive;

// `dofs` with the multiplier and the head's position appended (the path's DOFs follow).
std::vector<DofKey>& with_head(std::vector<DofKey>& dofs, int constraint, int head) {
  dofs.push_back(DofKey::multiplier(constraint, 0));
  for (int k = 0; k < 3; ++k) dofs.push_back(DofKey::node(head, k));
  return dofs;
}

// The contact's index into model.contacts (its constraint is of type contact).
int contact_of(const model::Model& model, int constraint) {
  const model::Constraint& c = model.constraints[static_cast<size_t>(constraint)];
  CATENA_ASSERT(c.type == model::ConstraintType::contact && c.contact >= 0,
                "BilateralContact takes a contact constraint");
  return c.contact;
}

}  // namespace

BilateralContact::BilateralContact(const model::Model& model, int index)
    : ConstraintCoupling(index),
      contact_(contact_of(model, index)),
      path_(model, model.contacts[static_cast<size_t>(contact_)],
            with_head(dofs_, index,
                      model.contacts[static_cast<size_t>(contact_of(model, index))].head_node)) {}

void BilateralContact::pattern(std::vector<std::pair<int, int>>& entries) const {
  entries.clear();
  const int n = static_cast<int>(dofs_.size());
  for (int j = 1; j < n; ++j) {
    entries.emplace_back(0, j);
    entries.emplace_back(j, 0);
  }
}

void BilateralContact::active_dofs(double t, std::vector<int>& positions) const {
  positions.clear();
  for (int k = 0; k < 4; ++k) positions.push_back(k);
  path_.element_dofs(t, positions);
}

void BilateralContact::evaluate(const CouplingState& s, double* f, std::span<const MatrixRequest> m,
                                Scratch&) const {
  double N[kPath], D[kPath];
  path_.directions(s.t, N, D);
  const double lambda = s.q[0];
  if (f) {
    f[0] = 0.0;
    for (int j = 0; j < kPath; ++j) {
      f[0] += N[j] * s.q[static_cast<size_t>(1 + j)];
      f[1 + j] = lambda * N[j];
    }
  }
  for (const MatrixRequest& r : m) {
    std::fill(r.out, r.out + kActive * kActive, 0.0);
    for (int j = 0; j < kPath; ++j) {
      r.out[(1 + j) * kActive] = r.c.c_lambda * N[j];
      r.out[1 + j] = r.c.c_g * N[j];
    }
  }
}

void BilateralContact::acceleration_target(const CouplingState& s, std::span<double> out) const {
  double N[kPath], D[kPath], E[kPath];
  path_.directions(s.t, N, D, E);
  double gamma = 0.0;
  for (int j = 0; j < kPath; ++j) {
    const auto i = static_cast<size_t>(1 + j);
    gamma -= E[j] * s.q[i] + (s.v.empty() ? 0.0 : 2.0 * D[j] * s.v[i]);
  }
  std::fill(out.begin(), out.end(), 0.0);
  out[0] = gamma;
}

void BilateralContact::velocity_target(const CouplingState& s, std::span<double> out) const {
  double N[kPath], D[kPath];
  path_.directions(s.t, N, D);
  double beta = 0.0;
  for (int j = 0; j < kPath; ++j) beta -= D[j] * s.q[static_cast<size_t>(1 + j)];
  std::fill(out.begin(), out.end(), 0.0);
  out[0] = beta;
}

}  // namespace catena::couplings
