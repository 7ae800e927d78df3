#pragma once
// Models and helpers shared by the time-integration tests.
#include <petscvec.h>

#include <memory>
#include <string>
#include <vector>

#include "catena/assembly/second_order_system.hpp"
#include "catena/model/model.hpp"
#include "catena/solvers/time/irk/butcher_tableau.hpp"
#include "catena/solvers/time/time_integrator.hpp"

namespace catena::test {

// Every tableau Catena offers (family, stage count), for parametrised tests.
struct TableauChoice {
  solvers::TableauFamily family;
  int stages;
};
std::vector<TableauChoice> every_tableau();
std::string tableau_label(const TableauChoice& choice);  // "radau_iia_3"

// A point mass on an isotropic elastic support, no gravity: x'' = −ω² x per axis.
model::Model oscillator(double mass, double omega);

// Collective. The value of global DOF g (−1: 0.0) on every rank.
double global_value(MPI_Comm comm, Vec x, PetscInt g);
// Collective. Sets global DOF g of x (the owner writes).
void set_global_value(Vec x, PetscInt g, double value);
// Not collective. A copy of x's owned entries.
std::vector<double> owned_values(Vec x);

// Collective. n fixed steps of size dt; throws NumericalError if Newton fails.
void advance_fixed(solvers::TimeIntegrator& integrator, double dt, int n);

// Collective. An integrator for closed-form checks of constrained mechanisms: `type` "hht"
// (with `alpha`) or an IRK family name ("radau_iia", 3 stages), Newton to 1e-12 / 1e-13
// and at most 30 iterations.
std::unique_ptr<solvers::TimeIntegrator> tight_integrator(assembly::SecondOrderSystem& system,
                                                          const std::string& type, double alpha);

// A pinned–pinned pre-tensioned wire of n cable elements along x (no gravity), with its
// first mode z = A sin(πx/L) (and slopes) set into q.
struct TautString {
  double L = 60.0, T = 20000.0, EA = 1.8e7, EI = 195.0, mu = 1.35;
  int n = 60;
  // f₁ of the tensioned Euler–Bernoulli beam, pinned ends:
  // f_n = n/(2L)·sqrt(T/μ)·sqrt(1 + n²π²EI/(T L²)), μ per tensioned length.
  double first_frequency() const;
  model::Model model() const;
  void pluck(const assembly::SecondOrderSystem& system, Vec q, double amplitude) const;
};

}  // namespace catena::test
