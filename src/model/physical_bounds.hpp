#pragma once
// Generous physical bounds on the magnitude of every real number a scene gives, by unit.
// Finite is not enough: a value near DBL_MAX (a point mass of 1e308 kg) passes "finite
// and positive" and then overflows a quantity derived from it (its weight, a force norm,
// a Newton tolerance), failing deep inside the solver with no word about the scene. Each
// bound lies orders of magnitude above anything a railway or cable structure needs and
// far enough below DBL_MAX (1.8e308) that the products and sums of squares the solvers
// form stay finite. docs/scene.md ("Physical bounds") lists them.
#include <limits>
#include <string_view>

namespace catena::model::detail {

// Coordinates and lengths, m: Earth's diameter is 1.3e7 m. Also what keeps positions
// meaningful: a double near 1e7 m resolves 2e-9 m, below the integrators' default
// position tolerance (atol 1e-6 m) and the Newton update test's 1e-12 relative floor
// of |q| (docs/integrators.md), so that a converged state is converged in every node.
inline constexpr double kMaxCoordinate = 1e7;

// Not collective. The largest accepted |value| for a quantity in `unit` (the SI unit
// strings the readers use: "kg", "N", "N/m", "m", ...); infinity for a unit without a
// bound.
double physical_magnitude_bound(std::string_view unit);

}  // namespace catena::model::detail
