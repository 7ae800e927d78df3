#include "dynamics_fixtures.hpp"

#include <cmath>
#include <numbers>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/time/hht_integrator.hpp"
#include "catena/solvers/time/irk/irk_integrator.hpp"
#include "catena/solvers/time/rattle_integrator.hpp"
#include "model_builders.hpp"

namespace catena::test {

std::vector<TableauChoice> every_tableau() {
  using solvers::TableauFamily;
  std::vector<TableauChoice> all;
  for (int s = 1; s <= 5; ++s) all.push_back({TableauFamily::gauss, s});
  for (int s = 1; s <= 5; ++s) all.push_back({TableauFamily::radau_iia, s});
  for (int s = 2; s <= 5; ++s) all.push_back({TableauFamily::lobatto_iiia, s});
  for (int s = 2; s <= 5; ++s) all.push_back({TableauFamily::lobatto_iiic, s});
  all.push_back({TableauFamily::sdirk, 3});
  return all;
}

std::string tableau_label(const TableauChoice& choice) {
  return std::string(solvers::tableau_family_name(choice.family)) + "_" +
         std::to_string(choice.stages);
}

model::Model oscillator(double mass, double omega) {
  model::Model m;
  m.gravity = Vec3::Zero();
  m.nodes.push_back({1, Vec3(0, 0, 0), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()});
  m.point_masses.push_back({0, mass});
  const double k = mass * omega * omega;
  m.elastic_supports.push_back({0, Vec3(k, k, k), Vec3::Zero()});
  return m;
}

double global_value(MPI_Comm comm, Vec x, PetscInt g) {
  PetscInt lo = 0, hi = 0;
  VecGetOwnershipRange(x, &lo, &hi);
  double local = 0.0, value = 0.0;
  if (g >= lo && g < hi) VecGetValues(x, 1, &g, &local);
  MPI_Allreduce(&local, &value, 1, MPI_DOUBLE, MPI_SUM, comm);
  return value;
}

void set_global_value(Vec x, PetscInt g, double value) {
  PetscInt lo = 0, hi = 0;
  VecGetOwnershipRange(x, &lo, &hi);
  if (g >= lo && g < hi) VecSetValue(x, g, value, INSERT_VALUES);
  VecAssemblyBegin(x);
  VecAssemblyEnd(x);
}

void advance_fixed(solvers::TimeIntegrator& integrator, double dt, int n) {
  for (int i = 0; i < n; ++i) {
    const solvers::StepOutcome step = integrator.attempt(dt, nullptr);
    if (!step.converged) throw NumericalError(integrator.name() + ": " + step.failure);
    integrator.accept();
  }
}

double TautString::first_frequency() const {
  const double mu_tensioned = mu / (1.0 + T / EA);
  return 1.0 / (2 * L) * std::sqrt(T / mu_tensioned) *
         std::sqrt(1 + std::numbers::pi * std::numbers::pi * EI / (T * L * L));
}

model::Model TautString::model() const {
  model::Model m;
  m.gravity = Vec3::Zero();
  const auto nodes = add_line(m, {0, 0, 0}, {L, 0, 0}, n,
                              model::CableProps{EA, EI, mu, 0.0, T / EA, {}, false, false});
  set_reference_frames(m);
  pin(m, nodes.front());
  pin(m, nodes.back());
  return m;
}

void TautString::pluck(const assembly::SecondOrderSystem& system, Vec q, double amplitude) const {
  const auto& dofs = system.dof_map();
  PetscInt lo = 0, hi = 0;
  VecGetOwnershipRange(q, &lo, &hi);
  const double k = std::numbers::pi / L;
  for (int i = 0; i <= n; ++i) {
    const double x = L * i / n;
    const PetscInt gz = dofs.global_dof(i, 2), gs = dofs.global_dof(i, 5);
    if (gz >= lo && gz < hi) VecSetValue(q, gz, amplitude * std::sin(k * x), INSERT_VALUES);
    if (gs >= lo && gs < hi) VecSetValue(q, gs, amplitude * k * std::cos(k * x), INSERT_VALUES);
  }
  VecAssemblyBegin(q);
  VecAssemblyEnd(q);
}

std::vector<double> owned_values(Vec x) {
  PetscInt n = 0;
  CATENA_PETSC(VecGetLocalSize(x, &n));
  const PetscScalar* a = nullptr;
  CATENA_PETSC(VecGetArrayRead(x, &a));
  std::vector<double> out(a, a + n);
  CATENA_PETSC(VecRestoreArrayRead(x, &a));
  return out;
}

std::unique_ptr<solvers::TimeIntegrator> tight_integrator(assembly::SecondOrderSystem& system,
                                                          const std::string& type, double alpha) {
  if (type == "hht") {
    solvers::HhtOptions o;
    o.alpha = alpha;
    o.atol = 1e-12;
    o.rtol = 1e-13;
    o.max_newton_iterations = 30;
    return std::make_unique<solvers::HhtIntegrator>(system, o);
  }
  if (type == "rattle") {
    solvers::RattleOptions o;
    o.atol = 1e-12;
    o.rtol = 1e-13;
    o.max_newton_iterations = 30;
    return std::make_unique<solvers::RattleIntegrator>(system, o);
  }
  solvers::IrkOptions o;
  o.family = solvers::parse_tableau_family(type);
  o.stages = 3;
  o.atol = 1e-12;
  o.rtol = 1e-13;
  o.max_newton_iterations = 30;
  return std::make_unique<solvers::IrkIntegrator>(system, o);
}

}  // namespace catena::test
