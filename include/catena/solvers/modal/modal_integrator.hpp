#pragma once
// The modal model (modal_model.hpp) as a TimeIntegrator, so that the step-control driver,
// output, checkpoints and signals treat it as any other method. Its own state is the modal
// coordinates and the pantographs' DOFs (ModalStepper); the system's vectors q, v, a are
// rebuilt from them (q = q0 + Σ φ_i η_i, the pantographs' DOFs as they are) only when asked
// for, and the contact forces come from the step itself (contact_forces()).
//
// Order: the modes and the pantographs are stepped exactly for the loads they are given;
// the site forces enter as loads linear over the step, so the coupled step is second order
// in h (the error of that interpolation), with no numerical damping and no period error of
// any mode. A state given by set_state() is projected on the modes (η = Φ̃ᵀ M (q − q0)):
// exact for a state of the model up to the shapes' single-precision rounding (Φ̃ᵀ M Φ̃ is
// I only to the rounding of its entries, 2⁻²⁴ each: a restart, or step doubling's return to
// a step's start, moves η by about that much of itself — estimated, not measured), the part
// outside the modes lost otherwise.
#include <mpi.h>

#include "catena/solvers/modal/modal_model.hpp"
#include "catena/solvers/modal/modal_stepper.hpp"
#include "catena/solvers/time/time_integrator.hpp"

namespace catena::solvers {

class ModalIntegrator final : public TimeIntegrator {
 public:
  // Collective.
  explicit ModalIntegrator(ModalModel model);

  std::string name() const override;
  int order() const override { return 2; }
  bool has_embedded_estimate() const override { return false; }
  void set_state(double t, Vec q, Vec v, Vec a) override;
  StepOutcome attempt(double h, const ErrorTolerance* tol) override;
  void accept() override;
  void interpolate(double t, Vec q, Vec v) override;
  double time() const override { return current_.t; }
  double previous_time() const override { return previous_.t; }
  Vec q() const override;
  Vec v() const override;
  Vec a() const override;
  Vec pending_q() const override;
  Vec pending_v() const override;
  const IntegratorCounters& counters() const override { return counters_; }
  // Linear between the step's ends (the loads' own interpolation).
  bool contact_forces_at(double t, std::vector<double>& out) const override;
  // A row's value from its mode shapes alone (q0 + φ_row·η, or the pantograph DOF): the
  // static correction is left out, as in q().
  bool current_entries(const std::vector<PetscInt>& rows, std::vector<double>& out) const override;

  // Not collective. ModalStepper::prepare for steps of h (the run's dt).
  void prepare(double h) { stepper_.prepare(h); }

  const ModalModel& model() const { return model_; }
  const ModalState& state() const { return current_; }
  // Not collective. How often a field (q, v, a or a pair) has been rebuilt from the modes so
  // far: each a pass over the shapes, a field sample's cost; the steps themselves need none.
  long field_rebuilds() const { return field_rebuilds_; }

 private:
  // Not collective (each rank its rows). q0 + Σ φ_i x_i with the pantographs' DOFs set to
  // q0 + y (displacements), or Σ φ_i x_i and y itself (rates) when `rates`.
  void rebuild(const Eigen::VectorXd& x, const Eigen::VectorXd& y, bool rates, Vec out) const;
  // Not collective. q from (η, u) and v from (η̇, u̇) together: one pass over the shapes.
  void rebuild_state(const Eigen::VectorXd& eta, const Eigen::VectorXd& eta_dot,
                     const Eigen::VectorXd& u, const Eigen::VectorXd& u_dot, Vec q, Vec v) const;
  void add_pantographs(const Eigen::VectorXd& y, double* values) const;
  // Collective. Φᵀ w over all ranks' rows (w: a vector laid out as q).
  Eigen::VectorXd project(Vec w) const;
  // Collective. The pantographs' entries of a global vector, on every rank.
  Eigen::VectorXd pantograph_values(Vec v) const;

  ModalModel model_;
  ModalStepper stepper_;
  ModalState current_, previous_, pending_;
  IntegratorCounters counters_;
  VecHandle q_, v_, a_, pending_q_, pending_v_, work_;
  // Which of the vectors above hold the state they stand for.
  mutable bool q_fresh_ = false, v_fresh_ = false, a_fresh_ = false, pending_fresh_ = false;
  mutable long field_rebuilds_ = 0;
  mutable Eigen::VectorXd field_, field_rate_;  // a rebuild's Φ̃ η and Φ̃ η̇ (rows: owned DOFs)
  std::vector<PetscInt> owned_pantograph_;      // per pantograph DOF: its local index or −1
};

}  // namespace catena::solvers
