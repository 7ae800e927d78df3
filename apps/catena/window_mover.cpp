#include "window_mover.hpp"

#include <cstdio>
#include <string>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/model/unknown_kinds.hpp"

namespace catena::app {
namespace {

const model::CatenaryWindow& window_of(const model::Model& m) {
  if (!m.catenary || !m.catenary->window) throw Error("a window mover needs a catenary.window");
  return *m.catenary->window;
}

}  // namespace

WindowMover::WindowMover(assembly::SecondOrderSystem& system, Vec q_line) : system_(system) {
  const model::Model& m = system.model();
  window_of(m);
  const std::vector<int> images = model::window_state_sources(m, model::WindowImage::ahead);
  const assembly::DofMap& dofs = system.dof_map();
  q_line_ = system.create_vector();
  CATENA_PETSC(VecCopy(q_line, q_line_.get()));
  q_ = system.create_vector();
  v_ = system.create_vector();
  a_ = system.create_vector();
  std::vector<PetscInt> from, to;
  std::string mismatch;  // this rank's, agreed on before any collective call
  for (const int n : dofs.owned_nodes()) {
    const int image = images[static_cast<std::size_t>(n)];
    if (image == model::kWindowEnters) continue;
    if (dofs.node_kind(image) != dofs.node_kind(n)) {
      mismatch = "nodes " + std::to_string(m.nodes[static_cast<std::size_t>(n)].id) + " and " +
                 std::to_string(m.nodes[static_cast<std::size_t>(image)].id) +
                 ", one period apart, have different unknowns";
      continue;
    }
    const model::UnknownKindInfo& kind = model::kind_info(dofs.node_kind(n));
    const model::Node& at = m.nodes[static_cast<std::size_t>(image)];
    for (int k = 0; k < dofs.node_dofs(n); ++k) {
      const PetscInt row = dofs.global_dof(n, k), image_row = dofs.global_dof(image, k);
      if (row < 0) continue;
      const bool x = k == kind.position && image != n;
      if (image_row >= 0) {
        from.push_back(image_row);
        to.push_back(row);
        if (x) x_rows_.push_back(row - dofs.first_owned());
        continue;
      }
      // The image holds the component (a registration's y, a fixed messenger support's z)
      // where this node, a window's end, is free: the held (reference) value, at rest.
      const bool slope = kind.gradients >= 0 && k >= kind.gradients;
      const int d = k - (slope ? kind.gradients : kind.position);
      const double held = slope ? at.tangent[d] : at.position[d];
      fixed_rows_.push_back(row - dofs.first_owned());
      fixed_values_.push_back(x ? held - window_of(m).shift_x() : held);
    }
  }
  if (any_rank(system.comm(), !mismatch.empty()))
    throw Error("catenary.window: " +
                (mismatch.empty() ? std::string("a node and its image differ (another rank's)")
                                  : mismatch));
  // The constraints' multipliers (a bilateral contact's, a pantograph mechanism's joints)
  // stay theirs.
  for (int c = 0; c < dofs.n_constraints(); ++c)
    for (int k = 0; k < dofs.n_multipliers(c); ++k)
      if (dofs.multiplier_local(c, k) >= 0) {
        from.push_back(dofs.multiplier_dof(c, k));
        to.push_back(dofs.multiplier_dof(c, k));
      }
  IsHandle is_from, is_to;
  CATENA_PETSC(ISCreateGeneral(system.comm(), static_cast<PetscInt>(from.size()), from.data(),
                               PETSC_COPY_VALUES, is_from.out()));
  CATENA_PETSC(ISCreateGeneral(system.comm(), static_cast<PetscInt>(to.size()), to.data(),
                               PETSC_COPY_VALUES, is_to.out()));
  CATENA_PETSC(VecScatterCreate(q_.get(), is_from.get(), q_.get(), is_to.get(), &scatter_));
}

WindowMover::~WindowMover() {
  if (scatter_) VecScatterDestroy(&scatter_);
}

void WindowMover::move(Vec from, Vec to, bool positions) const {
  CATENA_PETSC(VecScatterBegin(scatter_, from, to, INSERT_VALUES, SCATTER_FORWARD));
  CATENA_PETSC(VecScatterEnd(scatter_, from, to, INSERT_VALUES, SCATTER_FORWARD));
  if (!positions) return;
  const double dx = window_of(system_.model()).shift_x();
  PetscScalar* q = nullptr;
  CATENA_PETSC(VecGetArray(to, &q));
  for (const PetscInt row : x_rows_) q[row] -= dx;
  for (std::size_t i = 0; i < fixed_rows_.size(); ++i) q[fixed_rows_[i]] = fixed_values_[i];
  CATENA_PETSC(VecRestoreArray(to, &q));
}

void WindowMover::restore(long moves) {
  const model::CatenaryWindow& w = window_of(system_.model());
  system_.move_contacts_back(static_cast<double>(moves - moves_) * w.shift_arc());
  moves_ = moves;
}

double WindowMover::x_offset() const {
  return static_cast<double>(moves_) * window_of(system_.model()).shift_x();
}

double WindowMover::arc_offset() const {
  const model::CatenaryWindow& w = window_of(system_.model());
  return w.origin_arc() + static_cast<double>(moves_) * w.shift_arc();
}

void WindowMover::before_step(solvers::TimeIntegrator& integrator) {
  const model::Model& m = system_.model();
  const model::CatenaryWindow& w = window_of(m);
  const model::MovingContact& first = m.contacts.front();
  const double t = integrator.time();
  // Where the first pantograph is in the window (the same on every rank: t is).
  const double s = first.start + first.speed * t - static_cast<double>(moves_) * w.shift_arc();
  if (s < (w.behind + w.period) * w.span_arc) return;
  CATENA_PETSC(VecCopy(q_line_.get(), q_.get()));  // the spans entering ahead: at rest
  CATENA_PETSC(VecZeroEntries(v_.get()));
  CATENA_PETSC(VecZeroEntries(a_.get()));
  move(integrator.q(), q_.get(), true);
  move(integrator.v(), v_.get(), false);
  move(integrator.a(), a_.get(), false);
  system_.move_contacts_back(w.shift_arc());
  ++moves_;
  integrator.set_state(t, q_.get(), v_.get(), a_.get());
  integrator.forget_jacobian();  // the contacts' couplings are on other elements now
  if (!announced_ && mpi_rank(system_.comm()) == 0) {
    std::printf(
        "window: moved %d span%s along the line at t = %g s (each time the first pantograph "
        "passes span %d of the window; the spans entering ahead start from the static state)\n",
        w.period, w.period == 1 ? "" : "s", t, w.behind + w.period + 1);
    std::fflush(stdout);
  }
  announced_ = true;
}

}  // namespace catena::app
