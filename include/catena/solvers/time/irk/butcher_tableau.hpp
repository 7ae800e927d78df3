#pragma once
// Butcher tableaus of the implicit Runge–Kutta methods behind Catena's IRK integrators.
// Convention (Hairer & Wanner, Solving ODEs II, Sect. IV.5; Butcher, Numerical Methods for
// ODEs, 3rd ed., Ch. 3): for y' = f(t, y) one step of size h is
//   k_i = f(t0 + c_i h, y0 + h Σ_j a_ij k_j),  i = 1..s,     y1 = y0 + h Σ_i b_i k_i.
// For the second-order K-form (HOTINT; J. Gerstmayr, "An implicit Runge–Kutta solver
// adapted to flexible multibody system simulation", 7. Workshop über Deskriptorsysteme,
// Paderborn 2005) with stage accelerations K_j:
//   v_i = v0 + h Σ_j a_ij K_j,   u_i = u0 + h c_i v0 + h² Σ_j (A²)_ij K_j,
// which uses Σ_j a_ij = c_i (true for every tableau here); see a_squared().
//
// Families (s = stages; R(z) = 1 + z bᵀ(I − zA)⁻¹𝟙 the stability function):
//   gauss         s = 1..5  order 2s    stage order s    A-stable, |R(∞)| = 1
//   radau_iia     s = 1..5  order 2s−1  stage order s    L-stable, stiffly accurate
//   lobatto_iiia  s = 2..5  order 2s−2  stage order s    A-stable, |R(∞)| = 1, stiffly acc.
//   lobatto_iiic  s = 2..5  order 2s−2  stage order s−1  L-stable, stiffly accurate
//   sdirk         s = 3     order 3     stage order 1    L-stable, stiffly accurate
//                 (Alexander, SIAM J. Numer. Anal. 14 (1977) 1006–1021; HW IV.6)
// The coefficients are computed in long double on every call (microseconds), not typed in:
// the nodes are roots of Legendre-type polynomials, A and b the collocation integrals or the
// simplifying assumptions (docs/tableaus.md). The closed forms checked in the tests (s ≤ 3)
// come out correctly rounded (≤ 0.5 ulp).
//
// Error estimation: Radau IIA with odd s carries the embedded formula of Hairer & Wanner's
// RADAU5/RADAU codes (HW II, Sect. IV.8). It is not a plain b̂, as it also weighs f(t0, y0):
//   ŷ1 − y1 = h (γ0 f(t0, y0) + Σ_i (b̂_i − b_i) k_i)      (K-form: k_i = stage derivatives)
//           = γ0 h f(t0, y0) + Σ_i e_i z_i                 (Z-form: z_i = stage increments)
//   err = (I − h γ0 J)⁻¹ (ŷ1 − y1),   J ≈ ∂f/∂y,   ‖err‖ = O(h^{s+1}) → step-size control,
// with γ0 the real eigenvalue of A (so (I − hγ0J) is the real block of the transformed
// Newton matrix) and e = A⁻ᵀ(b̂ − b). The filter (I − hγ0J)⁻¹ keeps the estimate bounded
// for stiff components. Even s has no real eigenvalue of A (HW's RADAU code offers only odd
// s for this reason); there, and for every other family, no estimate is given and the
// integrator uses step doubling. docs/tableaus.md gives the K-form of the estimate for
// M a + f(q, v) = 0: one solve with the system Jacobian at c_M = 1, c_C = hγ0, c_K = (hγ0)².
//
// Not collective: no MPI, no PETSc; every rank can build the same tableau.
#include <Eigen/Dense>
#include <optional>
#include <string>
#include <string_view>

#include "catena/model/integrator_catalogue.hpp"

namespace catena::solvers {

enum class TableauFamily { gauss, radau_iia, lobatto_iiia, lobatto_iiic, sdirk };

struct ButcherTableau {
  std::string name;  // "<family>_<s>", e.g. "radau_iia_3" (the names parse_tableau_family reads)
  TableauFamily family = TableauFamily::gauss;
  int stages = 0;
  int order = 0;        // classical order p: all rooted-tree conditions of order ≤ p, not p + 1
  int stage_order = 0;  // largest q with C(q): Σ_j a_ij c_j^{k−1} = c_i^k / k, k = 1..q
  bool stiffly_accurate = false;  // last row of A equals bᵀ (so y1 is the last stage value)
  bool a_stable = false;          // |R(z)| ≤ 1 for Re z ≤ 0
  bool l_stable = false;          // A-stable and R(∞) = 0
  Eigen::MatrixXd A;              // s × s
  Eigen::VectorXd b, c;           // s; c_i = Σ_j a_ij

  // Embedded estimate (Radau IIA, odd s only; see the header comment). b_embedded = b̂
  // (weights on the stages), gamma0 = γ0 (weight on f(t0, y0)), e_embedded = A⁻ᵀ(b̂ − b).
  // The embedded method (nodes 0, c_1..c_s; weights γ0, b̂) has order embedded_order = s.
  std::optional<Eigen::VectorXd> b_embedded;
  std::optional<Eigen::VectorXd> e_embedded;
  double gamma0 = 0.0;
  int embedded_order = 0;  // 0 when there is no embedded estimate
};

// Not collective. Throws catena::InputError naming the family and the accepted stage
// counts (model/integrator_catalogue.hpp: gauss, radau_iia: 1..5; lobatto_iiia,
// lobatto_iiic: 2..5; sdirk: 3).
ButcherTableau make_tableau(TableauFamily family, int stages);

// "gauss", "radau" (= "radau_iia"), "radau_iia", "lobatto_iiia", "lobatto_iiic", "sdirk".
// Throws catena::InputError listing the accepted names.
TableauFamily parse_tableau_family(const std::string& name);

// The canonical name of a family ("radau_iia", ...), accepted by parse_tableau_family.
std::string_view tableau_family_name(TableauFamily family);

// The family's entry in the integrator catalogue (stage counts, estimate, what it refuses).
const model::IntegratorType& integrator_type(TableauFamily family);

// A², the K-form position weights: u_i = u0 + h c_i v0 + h² Σ_j (A²)_ij K_j. The sums are
// accumulated in long double and rounded once. Not collective.
Eigen::MatrixXd a_squared(const ButcherTableau& tableau);

}  // namespace catena::solvers
