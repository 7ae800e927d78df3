#include "catena/solvers/time/state_guard.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/model/path_stations.hpp"
#include "catena/model/unknown_kinds.hpp"

namespace catena::solvers {
namespace {

// Not collective. The diagonal of the box around the mesh nodes (at least 1 m, so that a
// model of one point has a size).
double size_of(const model::Model& m) {
  if (m.nodes.empty()) return 1.0;
  Vec3 lo = m.nodes.front().position, hi = lo;
  for (const model::Node& n : m.nodes) {
    lo = lo.cwiseMin(n.position);
    hi = hi.cwiseMax(n.position);
  }
  return std::max(1.0, (hi - lo).norm());
}

// Not collective. The farthest a prescribed motion carries its node from the mesh by t_end.
double prescribed_travel(const model::Model& m, double t_end) {
  double travel = 0.0;
  for (const model::Constraint& c : m.constraints)
    if (c.type == model::ConstraintType::prescribed)
      travel = std::max(travel, c.velocity.norm() * t_end + c.amplitude.norm());
  return travel;
}

}  // namespace

StateGuard::StateGuard(const assembly::SecondOrderSystem& system, double t_end, double dt)
    : system_(system), dt_(dt) {
  const model::Model& m = system.model();
  size_ = size_of(m);
  position_bound_ = kReachFactor * size_ + prescribed_travel(m, t_end);
  reference_ = system.create_vector();
  system.reference_state(reference_.get());
  const assembly::DofMap& dofs = system.dof_map();
  bound_.assign(static_cast<std::size_t>(dofs.n_owned()), 0.0);
  for (const int n : dofs.owned_nodes()) {
    const model::UnknownKindInfo& kind = model::kind_info(dofs.node_kind(n));
    for (int k = 0; k < dofs.node_dofs(n); ++k) {
      const PetscInt g = dofs.global_dof(n, k);
      if (g < 0) continue;
      const bool position = kind.position >= 0 && k >= kind.position && k < kind.position + 3;
      bound_[static_cast<std::size_t>(g - dofs.first_owned())] =
          position ? position_bound_ : kReachFactor;
    }
  }
  for (std::size_t k = 0; k < m.sliders.size(); ++k) {
    const model::Slider& slider = m.sliders[k];
    const PetscInt g = dofs.global_dof(slider.node, 3);
    if (g < 0 || g < dofs.first_owned() || g >= dofs.first_owned() + dofs.n_owned()) continue;
    const auto entry = static_cast<std::size_t>(g - dofs.first_owned());
    bound_[entry] = 0.0;
    const auto& path = m.paths[static_cast<std::size_t>(slider.path)].elements;
    sliders_.push_back({entry, static_cast<int>(k), model::path_stations(m, path).length()});
  }
}

bool StateGuard::watches_sliders() const { return !system_.model().sliders.empty(); }

void StateGuard::check_sliders(double t, Vec q) const {
  if (!watches_sliders()) return;
  const PetscScalar* x = nullptr;
  CATENA_PETSC(VecGetArrayRead(q, &x));
  std::vector<double> slides;
  for (const SliderEntry& e : sliders_) slides.push_back(x[e.entry]);
  CATENA_PETSC(VecRestoreArrayRead(q, &x));
  check_sliders(t, slides);
}

void StateGuard::check_sliders(double t, const std::vector<double>& slides) const {
  if (system_.model().sliders.empty()) return;  // the same on every rank: no reduction
  // The first slider (in scene order) off its path, and where it is.
  struct {
    double s;
    int slider;
  } off{0.0, static_cast<int>(system_.model().sliders.size())};
  for (std::size_t k = 0; k < sliders_.size(); ++k) {
    const SliderEntry& e = sliders_[k];
    const double s = slides[k];
    const double slack = 1e-9 * std::max(1.0, e.length);
    if ((s < -slack || s > e.length + slack) && e.slider < off.slider) off = {s, e.slider};
  }
  MPI_Allreduce(MPI_IN_PLACE, &off.slider, 1, MPI_INT, MPI_MIN, system_.comm());
  if (off.slider == static_cast<int>(system_.model().sliders.size())) return;
  // The owner of that slider sends its arc length.
  double s = 0.0;
  for (std::size_t k = 0; k < sliders_.size(); ++k)
    if (sliders_[k].slider == off.slider) s = slides[k];
  MPI_Allreduce(MPI_IN_PLACE, &s, 1, MPI_DOUBLE, MPI_SUM, system_.comm());
  const model::Slider& slider = system_.model().sliders[static_cast<std::size_t>(off.slider)];
  const model::ElementPath& path = system_.model().paths[static_cast<std::size_t>(slider.path)];
  std::ostringstream os;
  os.precision(6);
  os << "slider '" << slider.name << "' left its path '" << path.name << "' at t = " << t
     << " s (s = " << s << " m; the path runs from 0 to "
     << model::path_stations(system_.model(), path.elements).length()
     << " m): a slider runs between its path's ends; hold it before an end (an elastic "
        "support on its node: a buffer spring) or extend the path";
  throw NumericalError(os.str());
}

std::string StateGuard::unstable_step() const {
  std::ostringstream os;
  os << ": the step (dt = " << dt_
     << " s) is unstable for this scene; a smaller integrator.dt keeps it bounded "
        "(docs/accuracy.md, \"Where each method stops working\", lists the measured limits)";
  return os.str();
}

void StateGuard::check(const std::string& who, double t, Vec q, Vec v) const {
  const PetscScalar *x = nullptr, *u = nullptr, *r = nullptr;
  CATENA_PETSC(VecGetArrayRead(q, &x));
  CATENA_PETSC(VecGetArrayRead(v, &u));
  CATENA_PETSC(VecGetArrayRead(reference_.get(), &r));
  const PetscInt first = system_.dof_map().first_owned();
  // The first entry that is not finite (a global index; n_global if none), and the entry
  // furthest beyond its bound, as (change / bound, global index) for MPI_MAXLOC.
  long not_finite = static_cast<long>(system_.dof_map().n_global());
  struct {
    double ratio;
    int index;
  } worst{0.0, -1};
  for (std::size_t i = 0; i < bound_.size(); ++i) {
    const PetscInt g = first + static_cast<PetscInt>(i);
    if (!std::isfinite(x[i]) || !std::isfinite(u[i])) {
      not_finite = std::min(not_finite, static_cast<long>(g));
      continue;
    }
    if (bound_[i] <= 0.0) continue;
    const double ratio = std::abs(x[i] - r[i]) / bound_[i];
    if (ratio > worst.ratio) worst = {ratio, static_cast<int>(g)};
  }
  std::vector<double> slides;  // the owned sliders' arc lengths, as sliders_
  for (const SliderEntry& e : sliders_) slides.push_back(x[e.entry]);
  CATENA_PETSC(VecRestoreArrayRead(reference_.get(), &r));
  CATENA_PETSC(VecRestoreArrayRead(v, &u));
  CATENA_PETSC(VecRestoreArrayRead(q, &x));
  MPI_Allreduce(MPI_IN_PLACE, &not_finite, 1, MPI_LONG, MPI_MIN, system_.comm());
  MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE_INT, MPI_MAXLOC, system_.comm());
  std::ostringstream os;
  os.precision(4);
  if (not_finite < static_cast<long>(system_.dof_map().n_global())) {
    os << who << ": the state is not finite at t = " << t << " s (first at "
       << system_.describe_dof(static_cast<PetscInt>(not_finite)) << ")" << unstable_step();
    throw NumericalError(os.str());
  }
  if (worst.ratio <= 1.0) {
    check_sliders(t, slides);
    return;
  }
  const assembly::DofMap& dofs = system_.dof_map();
  const model::UnknownKindInfo& kind =
      model::kind_info(dofs.node_kind(dofs.node_of_global(worst.index)));
  const int component = dofs.component_of_global(worst.index);
  const bool position =
      kind.position >= 0 && component >= kind.position && component < kind.position + 3;
  os << who << ": the motion grew without bound (energy growth) at t = " << t
     << " s: " << system_.describe_dof(worst.index);
  if (position)
    os << " is " << worst.ratio * position_bound_ << " m from its mesh position, beyond "
       << position_bound_ << " m (" << kReachFactor << " times the model's size, " << size_ << " m"
       << (position_bound_ > kReachFactor * size_ ? ", and the prescribed motions' travel" : "")
       << ")";
  else
    os << " changed by " << worst.ratio * kReachFactor << ", beyond " << kReachFactor
       << " (a unit tangent stretched tenfold)";
  os << ", which no motion of the scene reaches" << unstable_step();
  throw NumericalError(os.str());
}

}  // namespace catena::solvers
