// SecondOrderSystem, part: Lagrange-multiplier constraints, multiplier slots, node-indexed
// state and DOF names (the class: include/catena/assembly/second_order_system.hpp).
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/core/error.hpp"
#include "local_array.hpp"

namespace catena::assembly {

namespace {
// u(t) of a prescribed motion and its second derivative.
Vec3 prescribed_displacement(const model::Constraint& c, double t) {
  return c.velocity * t + c.amplitude * std::sin(2.0 * M_PI * c.frequency * t);
}
Vec3 prescribed_acceleration(const model::Constraint& c, double t) {
  const double w = 2.0 * M_PI * c.frequency;
  return -w * w * std::sin(w * t) * c.amplitude;
}
}  // namespace

void SecondOrderSystem::add_constraint_forces(double t, const double* q, double* f) const {
  const model::Model& m = *model_;
  for (const LocalConstraint& lc : constraints_) {
    const model::Constraint& con = m.constraints[static_cast<size_t>(lc.index)];
    auto position = [&](int node, const PetscInt* local, int k) {
      return local[k] >= 0 ? q[local[k]] : node_reference_[12 * static_cast<size_t>(node) + k];
    };
    Vec3 target = Vec3::Zero();  // g = r_A − target
    if (con.type == model::ConstraintType::coincident)
      for (int k = 0; k < 3; ++k) target[k] = position(con.node_b, lc.b_local, k);
    else
      target = m.nodes[static_cast<size_t>(con.node_a)].position +
               (con.type == model::ConstraintType::prescribed ? prescribed_displacement(con, t)
                                                              : Vec3::Zero());
    for (int k = 0; k < 3; ++k) {
      const double lambda = q[lc.lam_local[k]];
      if (lc.a_local[k] >= 0) f[lc.a_local[k]] += lambda;
      if (lc.b_local[k] >= 0) f[lc.b_local[k]] -= lambda;
      f[lc.lam_local[k]] += position(con.node_a, lc.a_local, k) - target[k];
    }
  }
}

void SecondOrderSystem::add_constraint_entries(double c_lambda, double c_g, Mat J) const {
  for (const LocalConstraint& lc : constraints_)
    for (int k = 0; k < 3; ++k) {
      const PetscInt lam = lc.lam_global[k];
      CATENA_PETSC(MatSetValue(J, lam, lam, 0.0, ADD_VALUES));
      for (auto [col, sign] : {std::pair{lc.a_global[k], 1.0}, {lc.b_global[k], -1.0}}) {
        if (col < 0) continue;
        CATENA_PETSC(MatSetValue(J, col, lam, sign * c_lambda, ADD_VALUES));
        CATENA_PETSC(MatSetValue(J, lam, col, sign * c_g, ADD_VALUES));
      }
    }
}

std::string SecondOrderSystem::describe_dof(PetscInt global) const {
  static const char* names[12] = {"x",    "y",    "z",    "rx_x", "rx_y", "rx_z",
                                  "ry_x", "ry_y", "ry_z", "rz_x", "rz_y", "rz_z"};
  if (global < 0 || global >= dofs_.n_global()) return "unknown DOF";
  const int node = dofs_.node_of_global(global);
  const int comp = dofs_.component_of_global(global);
  const std::string id = std::to_string(model_->nodes[static_cast<size_t>(node)].id);
  if (const int c = dofs_.constraint_of_global(global); c >= 0)
    return "constraint " + std::to_string(c + 1) + " (multiplier " + names[comp] + ", node " +
           id + ")";
  return "node " + id + " (" + (comp >= 0 ? names[comp] : "?") + ")";
}

void SecondOrderSystem::owned_node_rows(Vec x, std::vector<double>& rows,
                                        std::vector<double>& multipliers) const {
  rows.clear();
  multipliers.clear();
  const PetscScalar* a = nullptr;
  CATENA_PETSC(VecGetArrayRead(x, &a));
  for (int n : dofs_.owned_nodes())
    for (int k = 0; k < 12; ++k) {
      const PetscInt g = k < dofs_.node_dofs(n) ? dofs_.global_dof(n, k) : -1;
      rows.push_back(g >= 0 ? a[g - dofs_.first_owned()] : 0.0);
    }
  for (const LocalConstraint& lc : constraints_)
    for (int k = 0; k < 3; ++k) multipliers.push_back(a[lc.lam_local[k]]);
  CATENA_PETSC(VecRestoreArrayRead(x, &a));
}

void SecondOrderSystem::set_from_node_rows(Vec x, const std::vector<double>& rows,
                                           const std::vector<double>& multipliers) const {
  CATENA_ASSERT(rows.size() == 12 * model_->nodes.size() &&
                    multipliers.size() == 3 * model_->constraints.size(),
                "12 values per node, 3 per constraint");
  PetscScalar* a = nullptr;
  CATENA_PETSC(VecGetArray(x, &a));
  for (int n : dofs_.owned_nodes())
    for (int k = 0; k < dofs_.node_dofs(n); ++k) {
      const PetscInt g = dofs_.global_dof(n, k);
      if (g >= 0) a[g - dofs_.first_owned()] = rows[12 * static_cast<size_t>(n) + k];
    }
  for (const LocalConstraint& lc : constraints_)
    for (int k = 0; k < 3; ++k)
      a[lc.lam_local[k]] = multipliers[3 * static_cast<size_t>(lc.index) + k];
  CATENA_PETSC(VecRestoreArray(x, &a));
}

void SecondOrderSystem::owned_constraint_forces(Vec q, std::vector<int>& constraints,
                                                std::vector<double>& forces) const {
  constraints.clear();
  forces.clear();
  const PetscScalar* a = nullptr;
  CATENA_PETSC(VecGetArrayRead(q, &a));
  for (const LocalConstraint& lc : constraints_) {
    constraints.push_back(lc.index);
    for (int k = 0; k < 3; ++k) forces.push_back(-a[lc.lam_local[k]]);
  }
  CATENA_PETSC(VecRestoreArrayRead(q, &a));
}

void SecondOrderSystem::algebraic_mask(Vec mask) const {
  CATENA_PETSC(VecSet(mask, 0.0));
  for (const LocalConstraint& lc : constraints_)
    for (int k = 0; k < 3; ++k) CATENA_PETSC(VecSetValue(mask, lc.lam_global[k], 1.0, INSERT_VALUES));
  CATENA_PETSC(VecAssemblyBegin(mask));
  CATENA_PETSC(VecAssemblyEnd(mask));
}

void SecondOrderSystem::constraint_acceleration(double t, Vec out) const {
  CATENA_PETSC(VecSet(out, 0.0));
  for (const LocalConstraint& lc : constraints_) {
    const model::Constraint& con = model_->constraints[static_cast<size_t>(lc.index)];
    if (con.type != model::ConstraintType::prescribed) continue;
    const Vec3 acc = prescribed_acceleration(con, t);
    for (int k = 0; k < 3; ++k)
      CATENA_PETSC(VecSetValue(out, lc.lam_global[k], acc[k], INSERT_VALUES));
  }
  CATENA_PETSC(VecAssemblyBegin(out));
  CATENA_PETSC(VecAssemblyEnd(out));
}

}  // namespace catena::assembly
