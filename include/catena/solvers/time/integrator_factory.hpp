#pragma once
// From the scene's integrator settings (model::IntegratorOptions) to a TimeIntegrator and
// its step control.
#include <memory>

#include "catena/assembly/second_order_system.hpp"
#include "catena/model/model.hpp"
#include "catena/solvers/time/time_integrator.hpp"
#include "catena/solvers/time/transient_solver.hpp"

namespace catena::solvers {

// Collective. Throws InputError for settings the chosen method cannot honour.
std::unique_ptr<TimeIntegrator> make_integrator(assembly::SecondOrderSystem& system,
                                                const model::IntegratorOptions& options);

// Not collective.
StepControl make_step_control(const model::IntegratorOptions& options);

}  // namespace catena::solvers
