#include "catena/couplings/node_constraint.hpp"

#include <algorithm>
#include <cmath>

namespace catena::couplings {

namespace {
// u(t) of a prescribed motion.
Vec3 prescribed_displacement(const model::Constraint& c, double t) {
  return c.velocity * t + c.amplitude * std::sin(2.0 * M_PI * c.frequency * t);
}
}  // namespace

NodeConstraint::NodeConstraint(const model::Model& model, int index)
    : ConstraintCoupling(index),
      constraint_(model.constraints[static_cast<size_t>(index)]),
      reference_a_(model.nodes[static_cast<size_t>(constraint_.node_a)].position) {
  for (int k = 0; k < 3; ++k) dofs_.push_back(DofKey::multiplier(index, k));
  for (int k = 0; k < 3; ++k) dofs_.push_back(DofKey::node(constraint_.node_a, k));
  if (constraint_.type == model::ConstraintType::coincident)
    for (int k = 0; k < 3; ++k) dofs_.push_back(DofKey::node(constraint_.node_b, k));
}

void NodeConstraint::pattern(std::vector<std::pair<int, int>>& entries) const {
  entries.clear();
  for (int k = 0; k < 3; ++k) {
    entries.emplace_back(k, k);
    for (int node = 1; 3 * node < static_cast<int>(dofs_.size()); ++node) {
      entries.emplace_back(3 * node + k, k);
      entries.emplace_back(k, 3 * node + k);
    }
  }
}

void NodeConstraint::acceleration_target(const CouplingState& s, std::span<double> out) const {
  const double w = 2.0 * M_PI * constraint_.frequency;
  const Vec3 u_tt = constraint_.type == model::ConstraintType::prescribed
                        ? Vec3(-w * w * std::sin(w * s.t) * constraint_.amplitude)
                        : Vec3::Zero();
  for (int k = 0; k < 3; ++k) out[static_cast<size_t>(k)] = u_tt[k];
}

void NodeConstraint::velocity_target(const CouplingState& s, std::span<double> out) const {
  const double w = 2.0 * M_PI * constraint_.frequency;
  const Vec3 u_t = constraint_.type == model::ConstraintType::prescribed
                       ? Vec3(constraint_.velocity + w * std::cos(w * s.t) * constraint_.amplitude)
                       : Vec3::Zero();
  for (int k = 0; k < 3; ++k) out[static_cast<size_t>(k)] = u_t[k];
}

void NodeConstraint::evaluate(const CouplingState& s, double* f, std::span<const MatrixRequest> m,
                              Scratch&) const {
  const size_t n = dofs_.size();
  const bool coincident = constraint_.type == model::ConstraintType::coincident;
  if (f) {
    Vec3 target = Vec3::Zero();
    if (coincident)
      for (int k = 0; k < 3; ++k) target[k] = s.q[6 + k];
    else
      target = reference_a_ + (constraint_.type == model::ConstraintType::prescribed
                                   ? prescribed_displacement(constraint_, s.t)
                                   : Vec3::Zero());
    for (int k = 0; k < 3; ++k) {
      const double lambda = s.q[k];
      f[3 + k] = lambda;
      if (coincident) f[6 + k] = -lambda;
      f[k] = s.q[3 + k] - target[k];
    }
  }
  for (const MatrixRequest& r : m) {
    std::fill(r.out, r.out + n * n, 0.0);
    for (int k = 0; k < 3; ++k)
      for (size_t node = 1; 3 * node < n; ++node) {
        const double sign = node == 1 ? 1.0 : -1.0;
        r.out[(3 * node + k) * n + k] = sign * r.c.c_lambda;
        r.out[k * n + 3 * node + k] = sign * r.c.c_g;
      }
  }
}

}  // namespace catena::couplings
