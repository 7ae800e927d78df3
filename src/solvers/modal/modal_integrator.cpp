#include "catena/solvers/modal/modal_integrator.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"

namespace catena::solvers {

ModalIntegrator::ModalIntegrator(ModalModel model)
    : model_(std::move(model)), stepper_(model_.dynamics) {
  for (VecHandle* v : {&q_, &v_, &a_, &pending_q_, &pending_v_, &work_})
    CATENA_PETSC(VecDuplicate(model_.q0.get(), v->out()));
  PetscInt first = 0, end = 0;
  CATENA_PETSC(VecGetOwnershipRange(model_.q0.get(), &first, &end));
  for (const PetscInt g : model_.pantograph_dofs)
    owned_pantograph_.push_back(g >= first && g < end ? g - first : -1);
  current_ = previous_ = pending_ = stepper_.rest(0.0);
}

std::string ModalIntegrator::name() const {
  std::ostringstream s;
  s << "modal(" << model_.dynamics.n_modes() << " modes <= " << model_.cutoff_hz << " Hz)";
  return s.str();
}

Eigen::VectorXd ModalIntegrator::project(Vec w) const {
  const double* a = nullptr;
  CATENA_PETSC(VecGetArrayRead(w, &a));
  Eigen::VectorXd x = model_.shapes.multiply_transposed(a);
  CATENA_PETSC(VecRestoreArrayRead(w, &a));
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(w));
  if (x.size() > 0)
    MPI_Allreduce(MPI_IN_PLACE, x.data(), static_cast<int>(x.size()), MPI_DOUBLE, MPI_SUM, comm);
  return x;
}

Eigen::VectorXd ModalIntegrator::pantograph_values(Vec v) const {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(owned_pantograph_.size()));
  const double* a = nullptr;
  CATENA_PETSC(VecGetArrayRead(v, &a));
  for (std::size_t k = 0; k < owned_pantograph_.size(); ++k)
    if (owned_pantograph_[k] >= 0) y(static_cast<Eigen::Index>(k)) = a[owned_pantograph_[k]];
  CATENA_PETSC(VecRestoreArrayRead(v, &a));
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(v));
  if (y.size() > 0)
    MPI_Allreduce(MPI_IN_PLACE, y.data(), static_cast<int>(y.size()), MPI_DOUBLE, MPI_SUM, comm);
  return y;
}

void ModalIntegrator::rebuild(const Eigen::VectorXd& x, const Eigen::VectorXd& y, bool rates,
                              Vec out) const {
  ++field_rebuilds_;
  const double* base = nullptr;
  double* a = nullptr;
  if (!rates) CATENA_PETSC(VecGetArrayRead(model_.q0.get(), &base));
  CATENA_PETSC(VecGetArray(out, &a));
  model_.shapes.multiply(x, field_);
  for (Eigen::Index r = 0; r < field_.size(); ++r) a[r] = (base ? base[r] : 0.0) + field_(r);
  add_pantographs(y, a);
  CATENA_PETSC(VecRestoreArray(out, &a));
  if (!rates) CATENA_PETSC(VecRestoreArrayRead(model_.q0.get(), &base));
}

void ModalIntegrator::rebuild_state(const Eigen::VectorXd& eta, const Eigen::VectorXd& eta_dot,
                                    const Eigen::VectorXd& u, const Eigen::VectorXd& u_dot, Vec q,
                                    Vec v) const {
  ++field_rebuilds_;
  const double* base = nullptr;
  double *a = nullptr, *b = nullptr;
  CATENA_PETSC(VecGetArrayRead(model_.q0.get(), &base));
  CATENA_PETSC(VecGetArray(q, &a));
  CATENA_PETSC(VecGetArray(v, &b));
  // Each row (one DOF's values in every mode) dotted with both coordinate vectors while it
  // is in cache: the shapes, the model's largest array, are read once for the pair (a field
  // sample's cost is that read).
  model_.shapes.multiply_pair(eta, eta_dot, field_, field_rate_);
  for (Eigen::Index r = 0; r < field_.size(); ++r) {
    a[r] = base[r] + field_(r);
    b[r] = field_rate_(r);
  }
  add_pantographs(u, a);
  add_pantographs(u_dot, b);
  CATENA_PETSC(VecRestoreArray(v, &b));
  CATENA_PETSC(VecRestoreArray(q, &a));
  CATENA_PETSC(VecRestoreArrayRead(model_.q0.get(), &base));
}

void ModalIntegrator::add_pantographs(const Eigen::VectorXd& y, double* values) const {
  for (std::size_t k = 0; k < owned_pantograph_.size(); ++k)
    if (owned_pantograph_[k] >= 0) values[owned_pantograph_[k]] += y(static_cast<Eigen::Index>(k));
}

bool ModalIntegrator::current_entries(const std::vector<PetscInt>& rows,
                                      std::vector<double>& out) const {
  const double* base = nullptr;
  CATENA_PETSC(VecGetArrayRead(model_.q0.get(), &base));
  out.resize(rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const PetscInt r = rows[k];
    if (r < 0) {  // a fixed DOF: no row (the caller has its value)
      out[k] = 0.0;
      continue;
    }
    out[k] = base[r] + model_.shapes.row_dot(r, current_.eta);
    for (std::size_t p = 0; p < owned_pantograph_.size(); ++p)
      if (owned_pantograph_[p] == r) out[k] += current_.u(static_cast<Eigen::Index>(p));
  }
  CATENA_PETSC(VecRestoreArrayRead(model_.q0.get(), &base));
  return true;
}

void ModalIntegrator::set_state(double t, Vec q, Vec v, Vec) {
  // η = Φᵀ M (q − q0), η̇ = Φᵀ M v (unit modal masses); the pantographs' DOFs as they are.
  ModalState s;
  s.t = t;
  CATENA_PETSC(VecWAXPY(work_.get(), -1.0, model_.q0.get(), q));
  s.u = pantograph_values(work_.get());
  CATENA_PETSC(MatMult(model_.M.get(), work_.get(), a_.get()));
  s.eta = project(a_.get());
  if (v) {
    s.u_dot = pantograph_values(v);
    CATENA_PETSC(MatMult(model_.M.get(), v, a_.get()));
    s.eta_dot = project(a_.get());
  } else {
    s.u_dot = Eigen::VectorXd::Zero(s.u.size());
    s.eta_dot = Eigen::VectorXd::Zero(s.eta.size());
  }
  stepper_.settle_forces(s);
  current_ = previous_ = pending_ = s;
  q_fresh_ = v_fresh_ = a_fresh_ = pending_fresh_ = false;
}

StepOutcome ModalIntegrator::attempt(double h, const ErrorTolerance*) {
  const ModalStepResult r = stepper_.step(current_, h, pending_);
  pending_fresh_ = false;
  StepOutcome out;
  out.converged = r.converged;
  out.newton_iterations = r.iterations;
  out.failure = r.failure;
  counters_.newton_iterations += r.iterations;
  if (!r.converged) {
    ++counters_.newton_failures;
    ++counters_.steps_rejected;
  }
  return out;
}

void ModalIntegrator::accept() {
  previous_ = current_;
  current_ = pending_;
  ++counters_.steps_accepted;
  q_fresh_ = v_fresh_ = a_fresh_ = false;
}

bool ModalIntegrator::contact_forces_at(double t, std::vector<double>& out) const {
  const double h = current_.t - previous_.t;
  const double s = h > 0.0 ? std::clamp((t - previous_.t) / h, 0.0, 1.0) : 1.0;
  out.resize(current_.contact_force.size());
  for (std::size_t c = 0; c < out.size(); ++c)
    out[c] = (1.0 - s) * previous_.contact_force[c] + s * current_.contact_force[c];
  return true;
}

// q and v are rebuilt together: one pass over the shapes costs little more than one, and
// whoever asks for one (output, a checkpoint) asks for the other.
Vec ModalIntegrator::q() const {
  if (!q_fresh_ || !v_fresh_)
    rebuild_state(current_.eta, current_.eta_dot, current_.u, current_.u_dot, q_.get(), v_.get());
  q_fresh_ = v_fresh_ = true;
  return q_.get();
}

Vec ModalIntegrator::v() const {
  q();
  return v_.get();
}

Vec ModalIntegrator::a() const {
  if (!a_fresh_) {
    Eigen::VectorXd eta_ddot, u_ddot;
    stepper_.accelerations(current_, eta_ddot, u_ddot);
    rebuild(eta_ddot, u_ddot, true, a_.get());
  }
  a_fresh_ = true;
  return a_.get();
}

Vec ModalIntegrator::pending_q() const {
  if (!pending_fresh_)
    rebuild_state(pending_.eta, pending_.eta_dot, pending_.u, pending_.u_dot, pending_q_.get(),
                  pending_v_.get());
  pending_fresh_ = true;
  return pending_q_.get();
}

Vec ModalIntegrator::pending_v() const {
  pending_q();
  return pending_v_.get();
}

void ModalIntegrator::interpolate(double t, Vec q, Vec v) {
  // Cubic Hermite over the last step: positions from (x, ẋ), rates from (ẋ, ẍ) at both ends.
  const double h = current_.t - previous_.t;
  const double s = h > 0.0 ? (t - previous_.t) / h : 1.0;
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
  Eigen::VectorXd eta, u, eta_dot, u_dot;
  if (q) {
    eta = h00 * previous_.eta + h10 * h * previous_.eta_dot + h01 * current_.eta +
          h11 * h * current_.eta_dot;
    u = h00 * previous_.u + h10 * h * previous_.u_dot + h01 * current_.u + h11 * h * current_.u_dot;
  }
  if (v) {
    Eigen::VectorXd e0, e1, u0, u1;
    stepper_.accelerations(previous_, e0, u0);
    stepper_.accelerations(current_, e1, u1);
    eta_dot = h00 * previous_.eta_dot + h10 * h * e0 + h01 * current_.eta_dot + h11 * h * e1;
    u_dot = h00 * previous_.u_dot + h10 * h * u0 + h01 * current_.u_dot + h11 * h * u1;
  }
  if (q && v)
    rebuild_state(eta, eta_dot, u, u_dot, q, v);
  else if (q)
    rebuild(eta, u, false, q);
  else if (v)
    rebuild(eta_dot, u_dot, true, v);
}

}  // namespace catena::solvers
