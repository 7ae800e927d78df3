#pragma once
// The coefficients of the linear multistep formulas of MultistepIntegrator
// (multistep_integrator.hpp) on a variable step grid, from the polynomial that interpolates
// the data: with steps of any length the formulas are those of the interpolating
// polynomial through the actual times (the variable-coefficient form; Hairer, Nørsett &
// Wanner I, III.5), not the constant-step tables rescaled.
//
//   backward differentiation (BDF-k): y'(t₀) ≈ Σ_{j=0..k} w_j y(t_j), the derivative at t₀
//     of the degree-k polynomial through (t_j, y_j), t₀ the new time and t₁ > t₂ > ... the
//     past ones;
//   Park's formula (K. C. Park, J. Appl. Mech. 42 (1975) 464–470): the mean of BDF-2 and
//     BDF-3, w = ½(w^(2) + w^(3)); at constant steps (10 y₀ − 15 y₁ + 6 y₂ − y₃)/(6h),
//     second order and A-stable;
//   Adams–Bashforth and Adams–Moulton: y₀ = y₁ + ∫_{t₁}^{t₀} p, p the polynomial through
//     the derivative's past values (Bashforth, explicit) or through the new one and the
//     past ones (Moulton) (Hairer, Nørsett & Wanner I, III.1 and III.5);
//   the predictor: y(t₀) from y₁, y'₁ and y₂ ... y_p, the degree-p polynomial through those
//     values with the slope y'₁ at t₁ (Hermite), for the Newton start and the error estimate.
//
// Not collective: no MPI, no PETSc.
#include <span>
#include <vector>

namespace catena::solvers {

// One piece of data of an interpolating polynomial: its value (derivative 0) or its first
// or second derivative at `time`.
struct InterpolationDatum {
  double time = 0.0;
  int derivative = 0;
};

// The weights c_i with Σ c_i d_i = p^(derivative)(target), where p is the polynomial of
// degree data.size() − 1 that matches the data d_i. Throws std::invalid_argument if the
// data do not determine p (a time repeated with the same derivative).
std::vector<double> interpolation_weights(std::span<const InterpolationDatum> data, double target,
                                          int derivative);

// The weights c_i with Σ c_i d_i = ∫_from^to p(t) dt for the polynomial p through the data
// (values only): the Adams formulas. Throws std::invalid_argument as above.
std::vector<double> integration_weights(std::span<const double> times, double from, double to);

// BDF-k's weights w_0 ... w_k for times[0] (new) > times[1] > ... > times[k]; k ≥ 1.
std::vector<double> bdf_weights(std::span<const double> times, int k);

// Park's weights w_0 ... w_3 over times[0..3].
std::vector<double> park_weights(std::span<const double> times);

// The predictor of degree p ≥ 1: y(times[0]) ≈ s·y'(times[1]) + Σ_{j=1..p} c_j y(times[j]).
// Returns {s, c_1, ..., c_p}.
std::vector<double> hermite_predictor_weights(std::span<const double> times, int p);

}  // namespace catena::solvers
