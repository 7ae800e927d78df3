// StateView: what output, checkpoints and tests ask of a state (the class:
// include/catena/assembly/state_view.hpp).
#include <Eigen/SVD>
#include <algorithm>
#include <memory>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/assembly/state_view.hpp"
#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/couplings/bilateral_contact.hpp"
#include "catena/couplings/element_coupling.hpp"
#include "catena/couplings/pantograph_contact.hpp"
#include "catena/couplings/slider_constraint.hpp"
#include "catena/model/supported_nodes.hpp"
#include "local_array.hpp"
#include "visit_forces.hpp"

namespace catena::assembly {

using couplings::ElementCoupling;
using couplings::ElementOrigin;
using detail::LocalArrayRead;

namespace {
// Width of a node's row in the reference coordinates and in checkpoint rows.
constexpr size_t kBlock = model::kMaxBlockUnknowns;
}  // namespace

StateView::StateView(const SecondOrderSystem& system) : system_(system) {
  for (size_t i = 0; i < system.couplings_.size(); ++i)
    if (dynamic_cast<const couplings::PantographContact*>(system.couplings_[i].get()))
      contact_couplings_.push_back(i);
    else if (dynamic_cast<const couplings::BilateralContact*>(system.couplings_[i].get()))
      bilateral_couplings_.push_back(i);
}

void StateView::section_results(const EvalPoint& p, std::vector<int>& element_indices,
                                std::vector<elements::SectionResult>& results) const {
  const SecondOrderSystem& sys = system_;
  sys.scatter_to_local(p.q, sys.q_work_.get());
  const LocalArrayRead q(sys.q_work_.get());
  element_indices.clear();
  results.clear();
  for (size_t i = 0; i < sys.couplings_.size(); ++i) {
    const auto* e = dynamic_cast<const ElementCoupling*>(sys.couplings_[i].get());
    if (!e || e->origin() != ElementOrigin::element) continue;
    const couplings::CouplingState g = sys.gather(sys.active(i, p.t, q.data(), sys.work_), q.data(),
                                                  nullptr, p.path, p.t, sys.work_);
    const elements::LocalState s{g.q, {}, p.path};
    element_indices.push_back(e->source());
    results.push_back(e->element().section_result(s));
  }
}

void StateView::owned_node_values(Vec q_global, std::vector<double>& positions,
                                  std::vector<double>& slopes) const {
  gather_owned_nodes(q_global, positions, slopes, true);
}

void StateView::owned_node_changes(Vec dq, std::vector<double>& positions,
                                   std::vector<double>& slopes) const {
  gather_owned_nodes(dq, positions, slopes, false);
}

void StateView::gather_owned_nodes(Vec q_global, std::vector<double>& positions,
                                   std::vector<double>& slopes, bool fixed_at_reference) const {
  const SecondOrderSystem& sys = system_;
  sys.scatter_to_local(q_global, sys.q_work_.get());
  const LocalArrayRead q(sys.q_work_.get());
  positions.clear();
  slopes.clear();
  for (int n : sys.dofs_.owned_nodes()) {
    auto value = [&](int k) {
      const PetscInt l = sys.dofs_.local_dof(n, k);
      if (l >= 0) return sys.dofs_.coefficient(n, k) * q.data()[l];
      return fixed_at_reference ? sys.reference_value(n, k) : 0.0;
    };
    const model::UnknownKindInfo& kind = model::kind_info(sys.dofs_.node_kind(n));
    for (int d = 0; d < 3; ++d)
      positions.push_back(kind.position >= 0 ? value(kind.position + d) : 0.0);
    for (int d = 0; d < 3; ++d)
      slopes.push_back(kind.gradients >= 0 ? value(kind.gradients + d) : 0.0);
  }
}

StateView::ComponentRows StateView::position_rows(const std::vector<int>& nodes,
                                                  int component) const {
  const SecondOrderSystem& sys = system_;
  const int rank = mpi_rank(sys.comm_);
  ComponentRows out;
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    const int n = nodes[j];
    if (sys.dofs_.node_owner(n) != rank) continue;
    const model::UnknownKindInfo& kind = model::kind_info(sys.dofs_.node_kind(n));
    CATENA_ASSERT(kind.position >= 0, "position_rows: a node without a position");
    const int k = kind.position + component;
    out.slot.push_back(static_cast<int>(j));
    out.row.push_back(sys.dofs_.local_dof(n, k));  // owned: its row in the owned part
    CATENA_ASSERT(out.row.back() < sys.dofs_.n_owned(), "position_rows: an owned node's DOF");
    out.coefficient.push_back(out.row.back() >= 0 ? sys.dofs_.coefficient(n, k) : 0.0);
    out.fixed.push_back(sys.reference_value(n, k));
  }
  return out;
}

Reactions StateView::reactions(const EvalPoint& p) const {
  const SecondOrderSystem& sys = system_;
  const model::Model& m = *sys.model_;
  const std::vector<int> supported = model::supported_nodes(m);  // replicated, ascending
  // The sums live with the supported nodes' owners: kBlock rows per owned supported node, in
  // ascending node order on each rank, the ranks' blocks in rank order. Each rank adds what
  // its couplings put on a node (another rank's too: a ghost node's elements), and only
  // those parts cross ranks (PETSc's assembly), not every node's block.
  const int rank = mpi_rank(sys.comm_), size = mpi_size(sys.comm_);
  const auto owner = [&](int node) { return static_cast<size_t>(sys.partition_.node_owner[node]); };
  std::vector<PetscInt> first_row(static_cast<size_t>(size) + 1, 0);
  for (const int node : supported) first_row[owner(node) + 1] += static_cast<PetscInt>(kBlock);
  for (size_t r = 1; r < first_row.size(); ++r) first_row[r] += first_row[r - 1];
  // Per supported node (in `supported`'s order) its first row.
  std::vector<PetscInt> node_row(supported.size());
  {
    std::vector<PetscInt> next(first_row.begin(), first_row.end() - 1);
    for (size_t i = 0; i < supported.size(); ++i) {
      node_row[i] = next[owner(supported[i])];
      next[owner(supported[i])] += static_cast<PetscInt>(kBlock);
    }
  }
  // The node's first row, or −1 for a node that is no support (a neighbour of one, held
  // only in a 2D line's plane: its reaction is not reported).
  const auto row_of = [&](int node) -> PetscInt {
    const auto at = std::lower_bound(supported.begin(), supported.end(), node);
    return at != supported.end() && *at == node
               ? node_row[static_cast<size_t>(at - supported.begin())]
               : -1;
  };
  const PetscInt first_owned_row = first_row[static_cast<size_t>(rank)];
  VecHandle sums;
  CATENA_PETSC(VecCreateMPI(sys.comm_, first_row[static_cast<size_t>(rank) + 1] - first_owned_row,
                            PETSC_DETERMINE, sums.out()));

  // The element couplings carry the support force: R = f_int − f_ext at a fixed DOF, and
  // an elastic support pulls its node back. So does a slider's constraint, the one
  // constraint that acts on fixed DOFs (the supported nodes of its path): the wheel load a
  // trolley next to a mast puts on it.
  std::vector<PetscInt> rows;
  std::vector<PetscScalar> values;
  sys.visit_forces(
      p,
      [&](size_t i, const SecondOrderSystem::ActiveDofs& dofs, std::span<const double> f_el) {
        const couplings::Coupling* c = sys.couplings_[i].get();
        const auto* e = dynamic_cast<const ElementCoupling*>(c);
        if (!e && !dynamic_cast<const couplings::SliderConstraint*>(c)) return;
        const std::vector<couplings::DofKey>& keys = c->dofs();
        for (size_t k = 0; k < f_el.size(); ++k) {
          // A slider acts on the path element under it: its k-th active DOF is not dofs()[k].
          const couplings::DofKey& key = keys[dofs.position(k)];
          if (key.kind == couplings::DofKey::Kind::multiplier) continue;
          const int node = key.index, comp = key.component;
          const PetscInt row = row_of(node);
          if (row < 0) continue;
          // A linked slope's force is a reaction too: its part along the tangent, the
          // stretch's equation, sums to zero over the node's couplings. An elastic support's,
          // a surface's or an absorbing end's force is a reaction where the DOF is free;
          // at a fixed DOF the support's reaction already balances it, and the two are one
          // (nothing added).
          const bool fixed = dofs.global[k] < 0 || sys.dofs_.linked(node, comp);
          double value = 0.0;
          if (e && couplings::acts_as_support(e->origin())) {
            if (!fixed) value = -f_el[k];
          } else if (fixed) {
            value = f_el[k];
          }
          if (value == 0.0) continue;
          rows.push_back(row + comp);
          values.push_back(value);
        }
      },
      &sys.at_supports_);  // only the couplings that enter a reaction
  if (!rows.empty())
    CATENA_PETSC(VecSetValues(sums.get(), static_cast<PetscInt>(rows.size()), rows.data(),
                              values.data(), ADD_VALUES));
  CATENA_PETSC(VecAssemblyBegin(sums.get()));
  CATENA_PETSC(VecAssemblyEnd(sums.get()));

  Reactions r;
  const LocalArrayRead q(sys.q_work_.get());
  const PetscScalar* total = nullptr;
  CATENA_PETSC(VecGetArrayRead(sums.get(), &total));
  for (size_t i = 0; i < supported.size(); ++i) {
    const int node = supported[i];
    if (sys.partition_.node_owner[node] != rank) continue;
    const double* R = total + (node_row[i] - first_owned_row);
    const model::UnknownKindInfo& kind = model::kind_info(sys.dofs_.node_kind(node));
    r.nodes.push_back(node);
    for (int d = 0; d < 3; ++d) r.force.push_back(R[kind.position + d]);
    // Generalised forces Q_g on gradient g act as the moment Σ g × Q_g.
    Vec3 moment = Vec3::Zero();
    for (int k = kind.gradients; k >= 0 && k < kind.size; k += 3) {
      Vec3 grad, Q;
      for (int d = 0; d < 3; ++d) {
        const PetscInt l = sys.dofs_.local_dof(node, k + d);
        grad[d] = l >= 0 ? sys.dofs_.coefficient(node, k + d) * q.data()[l]
                         : sys.reference_value(node, k + d);
        Q[d] = R[k + d];
      }
      moment += grad.cross(Q);
    }
    for (int d = 0; d < 3; ++d) r.moment.push_back(moment[d]);
  }
  CATENA_PETSC(VecRestoreArrayRead(sums.get(), &total));
  return r;
}

std::vector<ContactState> StateView::contact_states(const EvalPoint& p) const {
  const SecondOrderSystem& sys = system_;
  const size_t n = sys.model_->contacts.size();
  if (n == 0) return {};
  std::vector<double> local(4 * n, 0.0), global(4 * n, 0.0);
  sys.scatter_to_local(p.q, sys.q_work_.get());
  if (p.v) sys.scatter_to_local(p.v, sys.v_work_.get());
  {
    const LocalArrayRead q(sys.q_work_.get());
    std::unique_ptr<LocalArrayRead> v;
    if (p.v) v = std::make_unique<LocalArrayRead>(sys.v_work_.get());
    for (const size_t i : contact_couplings_) {
      const auto* c = static_cast<const couplings::PantographContact*>(sys.couplings_[i].get());
      const size_t k = static_cast<size_t>(c->index());
      const bool on = c->on_path(p.t);
      double delta = 0.0, F = 0.0;
      if (on) {
        F = c->force(sys.gather(sys.active(i, p.t, q.data(), sys.work_), q.data(),
                                v ? v->data() : nullptr, p.path, p.t, sys.work_),
                     &delta);
      }
      local[4 * k] = F;
      local[4 * k + 1] = c->position(p.t);
      local[4 * k + 2] = delta;
      local[4 * k + 3] = on ? 1.0 : 0.0;
    }
    // A bilateral contact's force is its multiplier (the first of its DOFs); the head is on
    // the wire (penetration 0, to the Newton tolerance).
    for (const size_t i : bilateral_couplings_) {
      const auto* c = static_cast<const couplings::BilateralContact*>(sys.couplings_[i].get());
      const auto k = static_cast<size_t>(c->contact());
      const couplings::CouplingState state =
          sys.gather(sys.active(i, p.t, q.data(), sys.work_), q.data(), v ? v->data() : nullptr,
                     p.path, p.t, sys.work_);
      local[4 * k] = state.q[0];
      local[4 * k + 1] = c->position(p.t);
      local[4 * k + 3] = 1.0;
    }
  }
  MPI_Allreduce(local.data(), global.data(), static_cast<int>(global.size()), MPI_DOUBLE, MPI_SUM,
                sys.comm_);
  std::vector<ContactState> out(n);
  for (size_t i = 0; i < n; ++i)
    out[i] = {global[4 * i], global[4 * i + 1], global[4 * i + 2], global[4 * i + 3] > 0.5};
  return out;
}

void StateView::owned_node_rows(Vec x, std::vector<double>& rows,
                                std::vector<double>& multipliers) const {
  const SecondOrderSystem& sys = system_;
  rows.clear();
  multipliers.clear();
  const PetscScalar* a = nullptr;
  CATENA_PETSC(VecGetArrayRead(x, &a));
  // Nodal values (a linked slot's coefficient × its unknown); 0 where fixed.
  for (int n : sys.dofs_.owned_nodes())
    for (int k = 0; k < static_cast<int>(kBlock); ++k) {
      const PetscInt g = k < sys.dofs_.node_dofs(n) ? sys.dofs_.global_dof(n, k) : -1;
      rows.push_back(g >= 0 ? sys.dofs_.coefficient(n, k) * a[g - sys.dofs_.first_owned()] : 0.0);
    }
  // Rows of multiplier_width() values, padded with 0 beyond a constraint's equations.
  const int width = model::multiplier_width(*sys.model_);
  for (int c = 0; c < sys.dofs_.n_constraints(); ++c)
    if (sys.dofs_.multiplier_local(c, 0) >= 0)
      for (int k = 0; k < width; ++k)
        multipliers.push_back(k < sys.dofs_.n_multipliers(c) ? a[sys.dofs_.multiplier_local(c, k)]
                                                             : 0.0);
  CATENA_PETSC(VecRestoreArrayRead(x, &a));
}

void StateView::set_from_node_rows(Vec x, const std::vector<double>& rows,
                                   const std::vector<double>& multipliers) const {
  const SecondOrderSystem& sys = system_;
  const auto width = static_cast<size_t>(model::multiplier_width(*sys.model_));
  CATENA_ASSERT(rows.size() == kBlock * sys.model_->nodes.size() &&
                    multipliers.size() == width * sys.model_->constraints.size(),
                "a row per node, a multiplier row per constraint");
  PetscScalar* a = nullptr;
  CATENA_PETSC(VecGetArray(x, &a));
  // Each unknown is Σ c_k·row_k over its slots: the row itself, or a linked slope's
  // projection on the tangent.
  for (int n : sys.dofs_.owned_nodes()) {
    for (int k = 0; k < sys.dofs_.node_dofs(n); ++k)
      if (const PetscInt g = sys.dofs_.global_dof(n, k); g >= 0) a[g - sys.dofs_.first_owned()] = 0;
    for (int k = 0; k < sys.dofs_.node_dofs(n); ++k)
      if (const PetscInt g = sys.dofs_.global_dof(n, k); g >= 0)
        a[g - sys.dofs_.first_owned()] +=
            sys.dofs_.coefficient(n, k) * rows[kBlock * static_cast<size_t>(n) + k];
  }
  for (int c = 0; c < sys.dofs_.n_constraints(); ++c)
    for (int k = 0; k < sys.dofs_.n_multipliers(c); ++k)
      if (const PetscInt l = sys.dofs_.multiplier_local(c, k); l >= 0)
        a[l] = multipliers[width * static_cast<size_t>(c) + static_cast<size_t>(k)];
  CATENA_PETSC(VecRestoreArray(x, &a));
}

void StateView::owned_constraint_forces(Vec q, std::vector<int>& constraints,
                                        std::vector<double>& forces) const {
  const SecondOrderSystem& sys = system_;
  constraints.clear();
  forces.clear();
  const PetscScalar* a = nullptr;
  CATENA_PETSC(VecGetArrayRead(q, &a));
  const int width = model::multiplier_width(*sys.model_);
  for (int c = 0; c < sys.dofs_.n_constraints(); ++c) {
    if (sys.dofs_.multiplier_local(c, 0) < 0) continue;
    constraints.push_back(c);
    for (int k = 0; k < width; ++k)
      forces.push_back(k < sys.dofs_.n_multipliers(c) ? -a[sys.dofs_.multiplier_local(c, k)] : 0.0);
  }
  CATENA_PETSC(VecRestoreArrayRead(q, &a));
}

BodyPoses StateView::body_poses(Vec q, Vec v) const {
  const SecondOrderSystem& sys = system_;
  const std::vector<model::RigidBody>& bodies = sys.model_->rigid_bodies;
  BodyPoses out;
  out.orientation.assign(4 * bodies.size(), 0.0);
  out.angular_velocity.assign(3 * bodies.size(), 0.0);
  if (bodies.empty()) return out;
  const PetscScalar *qa = nullptr, *va = nullptr;
  CATENA_PETSC(VecGetArrayRead(q, &qa));
  CATENA_PETSC(VecGetArrayRead(v, &va));
  const PetscInt first = sys.dofs_.first_owned();
  for (size_t b = 0; b < bodies.size(); ++b) {
    const int node = bodies[b].node;
    if (sys.dofs_.node_owner(node) != mpi_rank(sys.comm_)) continue;
    Mat3 R;
    Vec3 omega = Vec3::Zero();
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 e, rate;
      for (int d = 0; d < 3; ++d) {
        // A body's axes are never fixed (the scene reader refuses such supports).
        const PetscInt g = sys.dofs_.global_dof(node, 3 + 3 * axis + d);
        e[d] = qa[g - first];
        rate[d] = va[g - first];
      }
      R.col(axis) = e;
      omega += 0.5 * e.cross(rate);
    }
    // The nearest rotation to R (its orthonormal polar factor), then its quaternion.
    const Eigen::JacobiSVD<Mat3> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Quaterniond rotation(Mat3(svd.matrixU() * svd.matrixV().transpose()));
    rotation.normalize();
    if (rotation.w() < 0.0) rotation.coeffs() *= -1.0;  // one of ±p: w ≥ 0
    const double wxyz[4] = {rotation.w(), rotation.x(), rotation.y(), rotation.z()};
    std::copy(wxyz, wxyz + 4, out.orientation.begin() + static_cast<std::ptrdiff_t>(4 * b));
    for (int d = 0; d < 3; ++d) out.angular_velocity[3 * b + static_cast<size_t>(d)] = omega[d];
  }
  CATENA_PETSC(VecRestoreArrayRead(q, &qa));
  CATENA_PETSC(VecRestoreArrayRead(v, &va));
  // Each body's values are nonzero on its owner only: a sum gathers them.
  MPI_Allreduce(MPI_IN_PLACE, out.orientation.data(), static_cast<int>(out.orientation.size()),
                MPI_DOUBLE, MPI_SUM, sys.comm_);
  MPI_Allreduce(MPI_IN_PLACE, out.angular_velocity.data(),
                static_cast<int>(out.angular_velocity.size()), MPI_DOUBLE, MPI_SUM, sys.comm_);
  return out;
}

std::vector<double> StateView::joint_links(Vec q) const {
  const SecondOrderSystem& sys = system_;
  const model::Model& m = *sys.model_;
  std::vector<double> out(12 * m.joints.size(), 0.0);
  if (m.joints.empty()) return out;
  const int rank = mpi_rank(sys.comm_);
  const PetscScalar* qa = nullptr;
  CATENA_PETSC(VecGetArrayRead(q, &qa));
  const PetscInt first = sys.dofs_.first_owned();
  // Component k of an owned node's block at q (a fixed one at its reference value).
  auto value = [&](int n, int k) {
    const PetscInt g = sys.dofs_.global_dof(n, k);
    return g >= 0 ? sys.dofs_.coefficient(n, k) * qa[g - first] : sys.reference_value(n, k);
  };
  auto position = [&](int n) {
    const int p = model::kind_info(sys.dofs_.node_kind(n)).position;
    return Vec3(value(n, p), value(n, p + 1), value(n, p + 2));
  };
  // A body's node and a point fixed in the body (given by its reference position): r + Σ c_k
  // e_k with c_k its coordinates in the body's reference axes (natural coordinates: the
  // node's r, e1, e2, e3).
  auto body_point = [&](int n, const Vec3& reference_point) {
    const model::Node& node = m.nodes[static_cast<size_t>(n)];
    const Vec3 d = reference_point - node.position;
    const double c[3] = {node.tangent.dot(d), node.section_y.dot(d), node.section_z.dot(d)};
    Vec3 p = position(n);
    for (int axis = 0; axis < 3; ++axis)
      for (int k = 0; k < 3; ++k) p[k] += c[axis] * value(n, 3 + 3 * axis + k);
    return p;
  };
  auto put = [&](size_t j, int slot, const Vec3& p) {
    for (int k = 0; k < 3; ++k) out[12 * j + static_cast<size_t>(3 * slot + k)] = p[k];
  };
  for (size_t j = 0; j < m.joints.size(); ++j) {
    const model::Joint& joint = m.joints[j];
    const int a = m.rigid_bodies[static_cast<size_t>(joint.body_a)].node;
    if (sys.dofs_.node_owner(a) == rank) {
      put(j, 0, position(a));
      put(j, 1, body_point(a, joint.point));
    }
    if (joint.body_b >= 0) {
      const int b = m.rigid_bodies[static_cast<size_t>(joint.body_b)].node;
      if (sys.dofs_.node_owner(b) == rank) {
        put(j, 2, body_point(b, joint.point));
        put(j, 3, position(b));
      }
    } else if (joint.node_b >= 0) {
      if (sys.dofs_.node_owner(joint.node_b) == rank) {
        put(j, 2, position(joint.node_b));
        put(j, 3, position(joint.node_b));
      }
    } else if (rank == 0) {
      put(j, 2, joint.point);
      put(j, 3, joint.point);
    }
  }
  CATENA_PETSC(VecRestoreArrayRead(q, &qa));
  // Each point is nonzero on one rank only: a sum gathers them.
  MPI_Allreduce(MPI_IN_PLACE, out.data(), static_cast<int>(out.size()), MPI_DOUBLE, MPI_SUM,
                sys.comm_);
  return out;
}

SliderTravel StateView::slider_travel(Vec q, Vec v) const {
  const SecondOrderSystem& sys = system_;
  const std::vector<model::Slider>& sliders = sys.model_->sliders;
  SliderTravel out;
  out.position.assign(sliders.size(), 0.0);
  out.speed.assign(sliders.size(), 0.0);
  if (sliders.empty()) return out;
  const PetscScalar *qa = nullptr, *va = nullptr;
  CATENA_PETSC(VecGetArrayRead(q, &qa));
  CATENA_PETSC(VecGetArrayRead(v, &va));
  const PetscInt first = sys.dofs_.first_owned();
  for (size_t k = 0; k < sliders.size(); ++k) {
    const int node = sliders[k].node;
    if (sys.dofs_.node_owner(node) != mpi_rank(sys.comm_)) continue;
    // s may be fixed (a support holding the slider): then it keeps its start, at rest.
    const PetscInt g = sys.dofs_.global_dof(node, 3);
    out.position[k] = g >= 0 ? qa[g - first] : sliders[k].start;
    out.speed[k] = g >= 0 ? va[g - first] : 0.0;
  }
  CATENA_PETSC(VecRestoreArrayRead(q, &qa));
  CATENA_PETSC(VecRestoreArrayRead(v, &va));
  // Each slider's values are nonzero on its owner only: a sum gathers them.
  MPI_Allreduce(MPI_IN_PLACE, out.position.data(), static_cast<int>(out.position.size()),
                MPI_DOUBLE, MPI_SUM, sys.comm_);
  MPI_Allreduce(MPI_IN_PLACE, out.speed.data(), static_cast<int>(out.speed.size()), MPI_DOUBLE,
                MPI_SUM, sys.comm_);
  return out;
}

}  // namespace catena::assembly
