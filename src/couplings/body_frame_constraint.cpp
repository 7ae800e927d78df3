#include "catena/couplings/body_frame_constraint.hpp"

#include <algorithm>

#include "catena/core/error.hpp"

namespace catena::couplings {
namespace {
// Position in dofs() of component d of axis e (0-based): after the three multipliers.
int slot(int axis, int d) { return 3 + 3 * axis + d; }
}  // namespace

BodyFrameConstraint::BodyFrameConstraint(const model::Model& model, int index)
    : ConstraintCoupling(index) {
  const model::Constraint& c = model.constraints[static_cast<size_t>(index)];
  CATENA_ASSERT(c.type == model::ConstraintType::frame_lengths ||
                    c.type == model::ConstraintType::frame_angles,
                "BodyFrameConstraint takes a frame constraint");
  lengths_ = c.type == model::ConstraintType::frame_lengths;
  axes_ = lengths_ ? std::array<std::pair<int, int>, 3>{{{0, 0}, {1, 1}, {2, 2}}}
                   : std::array<std::pair<int, int>, 3>{{{1, 2}, {2, 0}, {0, 1}}};
  for (int k = 0; k < 3; ++k) dofs_.push_back(DofKey::multiplier(index, k));
  for (int k = 3; k < 12; ++k) dofs_.push_back(DofKey::node(c.node_a, k));
}

void BodyFrameConstraint::pattern(std::vector<std::pair<int, int>>& entries) const {
  entries.clear();
  for (int k = 0; k < 3; ++k) {
    entries.emplace_back(k, k);  // the multiplier diagonal: kept for pivoting solvers
    const auto [i, j] = axes_[static_cast<size_t>(k)];
    for (int d = 0; d < 3; ++d) {
      for (const int axis : {i, j}) {
        entries.emplace_back(k, slot(axis, d));
        entries.emplace_back(slot(axis, d), k);
      }
      entries.emplace_back(slot(i, d), slot(j, d));
      entries.emplace_back(slot(j, d), slot(i, d));
    }
  }
  std::sort(entries.begin(), entries.end());
  entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
}

void BodyFrameConstraint::evaluate(const CouplingState& s, double* f,
                                   std::span<const MatrixRequest> m, Scratch&) const {
  constexpr int n = 12;
  auto axis = [&](int a) { return Vec3(s.q[slot(a, 0)], s.q[slot(a, 1)], s.q[slot(a, 2)]); };
  if (f) {
    std::fill(f, f + n, 0.0);
    for (int k = 0; k < 3; ++k) {
      const auto [i, j] = axes_[static_cast<size_t>(k)];
      const Vec3 ei = axis(i), ej = axis(j);
      const double lambda = s.q[k];
      f[k] = lengths_ ? 0.5 * (ei.squaredNorm() - 1.0) : ei.dot(ej);
      // Gᵀλ: ∂g_k/∂e_i = e_j (with the ½, e_k for a length), ∂g_k/∂e_j = e_i.
      for (int d = 0; d < 3; ++d) {
        if (lengths_) {
          f[slot(i, d)] += lambda * ei[d];
        } else {
          f[slot(i, d)] += lambda * ej[d];
          f[slot(j, d)] += lambda * ei[d];
        }
      }
    }
  }
  for (const MatrixRequest& r : m) {
    std::fill(r.out, r.out + n * n, 0.0);
    for (int k = 0; k < 3; ++k) {
      const auto [i, j] = axes_[static_cast<size_t>(k)];
      const Vec3 ei = axis(i), ej = axis(j);
      const double lambda = s.q[k];
      for (int d = 0; d < 3; ++d) {
        if (lengths_) {
          r.out[slot(i, d) * n + k] += r.c.c_lambda * ei[d];
          r.out[k * n + slot(i, d)] += r.c.c_g * ei[d];
          r.out[slot(i, d) * n + slot(i, d)] += r.c.c_K * lambda;
        } else {
          r.out[slot(i, d) * n + k] += r.c.c_lambda * ej[d];
          r.out[slot(j, d) * n + k] += r.c.c_lambda * ei[d];
          r.out[k * n + slot(i, d)] += r.c.c_g * ej[d];
          r.out[k * n + slot(j, d)] += r.c.c_g * ei[d];
          r.out[slot(i, d) * n + slot(j, d)] += r.c.c_K * lambda;
          r.out[slot(j, d) * n + slot(i, d)] += r.c.c_K * lambda;
        }
      }
    }
  }
}

void BodyFrameConstraint::acceleration_target(const CouplingState& s,
                                              std::span<double> target) const {
  std::fill(target.begin(), target.end(), 0.0);
  if (s.v.empty()) return;  // at rest: vᵀ H v = 0
  auto rate = [&](int a) { return Vec3(s.v[slot(a, 0)], s.v[slot(a, 1)], s.v[slot(a, 2)]); };
  for (int k = 0; k < 3; ++k) {
    const auto [i, j] = axes_[static_cast<size_t>(k)];
    // d²g/dt² = G a + vᵀ H v: lengths ė_k·ė_k (with the ½: H = I), angles 2 ė_i·ė_j.
    target[static_cast<size_t>(k)] =
        lengths_ ? -rate(i).squaredNorm() : -2.0 * rate(i).dot(rate(j));
  }
}

}  // namespace catena::couplings
