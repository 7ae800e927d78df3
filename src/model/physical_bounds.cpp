#include "physical_bounds.hpp"

#include <array>
#include <utility>

namespace catena::model::detail {
namespace {

// Each bound, with what it is generous for. Derived quantities stay far from overflow:
// the largest product the solvers form from two of them (a stiffness times a length,
// a mass times an acceleration) is about 1e22, its square 1e44.
constexpr std::array<std::pair<std::string_view, double>, 16> kBounds{{
    {"m", kMaxCoordinate},  // coordinates, lengths, amplitudes, tolerances (see header)
    {"m/s", 1e4},           // speeds: 36 000 km/h, far above any train
    {"km/h", 3.6e4},        // the same speed in km/h
    {"m/s^2", 1e4},         // gravity: 1000 g
    {"kg", 1e9},            // point masses, stage masses: a million tonnes
    {"kg/m", 1e6},          // mass per length: a contact wire is 1 kg/m, a bridge deck 1e4
    {"kg*m", 1e6},          // rotary inertia per length
    {"N", 1e12},            // forces, tensions, EA, GA: a wire's EA is 2e7 N
    {"N/m", 1e15},          // spring and contact stiffness, distributed loads
    {"N*m^2", 1e15},        // EI, GJ: a large bridge girder is 1e11 N m^2
    {"N*s/m", 1e15},        // dashpots
    {"N*s^2/m^2", 1e6},     // aerodynamic uplift coefficient (EN 50367: about 0.01)
    {"s", 1e9},             // durations, steps, damping times, intervals: 30 years
    {"1/s", 1e9},           // Rayleigh mass factor
    {"Hz", 1e9},            // frequencies
    {"", 1e6},              // dimensionless: direction components, prestrain
}};

}  // namespace

double physical_magnitude_bound(std::string_view unit) {
  for (const auto& [name, bound] : kBounds)
    if (name == unit) return bound;
  return std::numeric_limits<double>::infinity();
}

}  // namespace catena::model::detail
