#pragma once
// Central finite differences for testing analytic Jacobians (tests only, never production).
#include <functional>
#include <vector>

namespace catena::test {

// Returns the n×m row-major matrix ∂f/∂x by central differences with step h·max(1,|x_j|).
std::vector<double> central_difference_jacobian(
    const std::function<void(const std::vector<double>& x, std::vector<double>& f)>& fn,
    const std::vector<double>& x, int n_out, double h = 1e-6);

// max |A − B| / max(|B|_max, floor): a scale-aware relative difference of two matrices.
double relative_max_difference(const std::vector<double>& a, const std::vector<double>& b,
                               double floor = 1e-12);

}  // namespace catena::test
