// SecondOrderSystem, part: the law of each absorbing end from the run's initial state (the
// class: include/catena/assembly/second_order_system.hpp).
#include <sstream>
#include <variant>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/core/error.hpp"
#include "catena/couplings/bilateral_contact.hpp"
#include "catena/couplings/element_coupling.hpp"
#include "catena/couplings/moving_load.hpp"
#include "catena/couplings/pantograph_contact.hpp"
#include "catena/couplings/slider_constraint.hpp"
#include "catena/elements/absorbing_end.hpp"
#include "catena/model/unknown_kinds.hpp"

namespace catena::assembly {
namespace {
// The least strain T/EA of a line an absorbing end accepts.
constexpr double kTautStrain = 1.0e-7;
}  // namespace

void SecondOrderSystem::calibrate_absorbing_ends(Vec q0) {
  const model::Model& m = *model_;
  const std::size_t n = m.absorbing_ends.size();
  if (n == 0) return;
  // f(q0) of the structure at an end node: the force the line beyond must supply. Without
  // the absorbing ends themselves, and without what moves along the line (a pantograph's
  // contact, a moving load, a slider): a pantograph standing on the end element at the
  // start is not part of the line's force, and would otherwise stay in it when it leaves.
  std::vector<std::size_t> others;
  for (std::size_t i = 0; i < couplings_.size(); ++i) {
    const couplings::Coupling* c = couplings_[i].get();
    const auto* e = dynamic_cast<const couplings::ElementCoupling*>(c);
    const bool moving = dynamic_cast<const couplings::PantographContact*>(c) ||
                        dynamic_cast<const couplings::MovingLoad*>(c) ||
                        dynamic_cast<const couplings::BilateralContact*>(c) ||
                        dynamic_cast<const couplings::SliderConstraint*>(c);
    if (!moving && (!e || e->origin() != couplings::ElementOrigin::absorbing_end))
      others.push_back(i);
  }
  VecHandle f = create_vector();
  sum_forces(EvalPoint{q0, nullptr, {}, 0.0}, others, f.get(), nullptr);
  // Per end: f at its position (3), then at its slope (3).
  std::vector<double> local(6 * n, 0.0), end_force(6 * n, 0.0);
  {
    const PetscScalar* values = nullptr;
    CATENA_PETSC(VecGetArrayRead(f.get(), &values));
    for (std::size_t i = 0; i < n; ++i) {
      const int node = m.absorbing_ends[i].node;
      const model::UnknownKindInfo& kind = model::kind_info(dofs_.node_kind(node));
      for (int d = 0; d < 6; ++d) {
        const int component = d < 3 ? kind.position + d : kind.gradients + d - 3;
        const PetscInt g = dofs_.global_dof(node, component);
        if (g >= dofs_.first_owned() && g < dofs_.first_owned() + dofs_.n_owned())
          local[6 * i + static_cast<std::size_t>(d)] = values[g - dofs_.first_owned()];
      }
    }
    CATENA_PETSC(VecRestoreArrayRead(f.get(), &values));
  }
  MPI_Allreduce(local.data(), end_force.data(), static_cast<int>(local.size()), MPI_DOUBLE, MPI_SUM,
                comm_);

  std::vector<elements::AbsorbingEndLaw> laws;
  for (std::size_t i = 0; i < n; ++i) {
    const model::AbsorbingEnd& a = m.absorbing_ends[i];
    const Vec3 F(end_force[6 * i], end_force[6 * i + 1], end_force[6 * i + 2]);
    // Outwards: from the element's other node to this one (reference positions).
    const model::ElementDesc& element = m.elements[static_cast<std::size_t>(a.element)];
    const int other = element.nodes[0] == a.node ? element.nodes[1] : element.nodes[0];
    const Vec3 outwards = (m.nodes[static_cast<std::size_t>(a.node)].position -
                           m.nodes[static_cast<std::size_t>(other)].position)
                              .normalized();
    // Taut: pulled outwards with at least kTautStrain·EA (1.8 N on a contact wire). Below,
    // the direction of F is round-off and the transverse impedance √(T m') nearly nothing.
    const auto& cable = std::get<model::CableProps>(*element.props);
    if (!(F.dot(outwards) > kTautStrain * cable.EA)) {
      std::ostringstream os;
      os << "absorbing end at node " << m.nodes[static_cast<std::size_t>(a.node)].id
         << ": its line is not taut there at the run's start (the force the line beyond "
            "would have to supply is ["
         << F[0] << ", " << F[1] << ", " << F[2] << "] N; it must pull outwards along the line "
         << "with at least " << kTautStrain * cable.EA
         << " N, 1e-7 of EA); an absorbing end needs a taut line";
      throw NumericalError(os.str());
    }
    laws.push_back(elements::cable_end_law(F, cable.EA, cable.mass_per_length));
    laws.back().slope_force =
        Vec3(end_force[6 * i + 3], end_force[6 * i + 4], end_force[6 * i + 5]);
  }
  for (auto& c : couplings_) {
    auto* e = dynamic_cast<couplings::ElementCoupling*>(c.get());
    if (e && e->origin() == couplings::ElementOrigin::absorbing_end)
      e->replace_element(
          std::make_unique<elements::AbsorbingEnd>(laws[static_cast<std::size_t>(e->source())]));
  }
}

}  // namespace catena::assembly
