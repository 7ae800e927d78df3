#include "catena/solvers/time/irk/butcher_tableau.hpp"

#include <array>
#include <sstream>

#include "catena/core/error.hpp"
#include "catena/model/integrator_catalogue.hpp"
#include "tableau_collocation.hpp"

namespace catena::solvers {
namespace {

using detail::MatrixL;
using detail::Real;
using detail::VectorL;

struct FamilyInfo {
  TableauFamily family;
  std::string_view name;  // the integrator type's (model/integrator_catalogue.hpp)
};

// The families and their names; their facts (stage counts, estimate) are the catalogue's.
constexpr std::array<FamilyInfo, 5> families{{
    {TableauFamily::gauss, "gauss"},
    {TableauFamily::radau_iia, "radau_iia"},
    {TableauFamily::lobatto_iiia, "lobatto_iiia"},
    {TableauFamily::lobatto_iiic, "lobatto_iiic"},
    {TableauFamily::sdirk, "sdirk"},
}};

const FamilyInfo& info(TableauFamily family) {
  for (const auto& f : families) {
    if (f.family == family) return f;
  }
  CATENA_ASSERT(false, "TableauFamily without an entry in families");
  return families[0];
}

struct Coefficients {
  MatrixL a;
  VectorL b, c;
};

// Order, stage order and stability are properties of the families (HW II, Sects. IV.3 and
// IV.5; Butcher, Ch. 3); the unit tests verify every one of them for every tableau.
void set_properties(ButcherTableau& t) {
  const int s = t.stages;
  switch (t.family) {
    case TableauFamily::gauss:
      t.order = 2 * s, t.stage_order = s;
      t.stiffly_accurate = false, t.a_stable = true, t.l_stable = false;
      break;
    case TableauFamily::radau_iia:
      t.order = 2 * s - 1, t.stage_order = s;
      t.stiffly_accurate = true, t.a_stable = true, t.l_stable = true;
      break;
    case TableauFamily::lobatto_iiia:
      t.order = 2 * s - 2, t.stage_order = s;
      t.stiffly_accurate = true, t.a_stable = true, t.l_stable = false;
      break;
    case TableauFamily::lobatto_iiic:
      t.order = 2 * s - 2, t.stage_order = s - 1;
      t.stiffly_accurate = true, t.a_stable = true, t.l_stable = true;
      break;
    case TableauFamily::sdirk:
      t.order = 3, t.stage_order = 1;
      t.stiffly_accurate = true, t.a_stable = true, t.l_stable = true;
      break;
  }
}

Eigen::MatrixXd to_double(const MatrixL& m) { return m.cast<double>(); }
Eigen::VectorXd to_double(const VectorL& v) { return v.cast<double>(); }

Coefficients collocation(const VectorL& c) {
  return {detail::collocation_matrix(c), detail::quadrature_weights(c), c};
}

Coefficients lobatto_iiic(int s) {
  const VectorL c = detail::lobatto_nodes(s);
  const VectorL b = detail::quadrature_weights(c);
  return {detail::lobatto_iiic_matrix(c, b), b, c};
}

// Alexander's (1977) L-stable SDIRK of order 3 (HW II, Sect. IV.6):
//   γ       | γ
//   (1+γ)/2 | (1−γ)/2  γ
//   1       | b1       b2  γ         b1 = −(6γ² − 16γ + 1)/4,  b2 = (6γ² − 20γ + 5)/4
//           | b1       b2  γ
// γ ≈ 0.4358665215 is the root in (0.3, 0.6) of x³ − 3x² + 3x/2 − 1/6, which makes
// R(∞) = 0 while keeping order 3; the other two roots (0.159, 2.41) lie outside the
// A-stable range 1/3 ≤ γ ≤ 1.0686 of order-3 three-stage SDIRKs.
Coefficients sdirk3() {
  const Real g = detail::bracketed_root(
      [](Real x) { return ((x - 3) * x + Real{3} / 2) * x - Real{1} / 6; }, Real{0.3L}, Real{0.6L});
  const Real b1 = -(6 * g * g - 16 * g + 1) / 4, b2 = (6 * g * g - 20 * g + 5) / 4;
  Coefficients k{MatrixL::Zero(3, 3), VectorL(3), VectorL(3)};
  k.a(0, 0) = g;
  k.a(1, 0) = (1 - g) / 2, k.a(1, 1) = g;
  k.a(2, 0) = b1, k.a(2, 1) = b2, k.a(2, 2) = g;
  k.b << b1, b2, g;
  k.c << g, (1 + g) / 2, 1;
  return k;
}

// The real root of det(I − zA) on (0, 100] — the reciprocal of A's real eigenvalue. The
// eigenvalues of a Radau IIA matrix have positive real part, and for odd s exactly one is
// real (its inverse is 1, 3.64, 6.29 for s = 1, 3, 5).
Real real_eigenvalue(const MatrixL& a) {
  const auto q = [&a](Real z) {
    const MatrixL m = MatrixL::Identity(a.rows(), a.cols()) - z * a;
    return m.partialPivLu().determinant();
  };
  Real lo = 0;
  for (Real hi = Real{0.25L}; hi <= 100; hi += Real{0.25L}) {
    if (q(hi) <= 0) return 1 / detail::bracketed_root(q, lo, hi);
    lo = hi;
  }
  CATENA_ASSERT(false, "Radau IIA matrix without a real eigenvalue 1/z, z in (0, 100]");
  return 0;
}

// RADAU5's embedded formula generalised to odd s (HW II, Sect. IV.8). The embedded
// method has the nodes 0, c_1..c_s and weights γ0, b̂ and satisfies B(s):
//   γ0 p(0) + Σ_j b̂_j p(c_j) = ∫_0^1 p  for deg p ≤ s − 1   ⇔   b̂_j = b_j − γ0 ℓ_j(0);
// with C(s) of the Radau stages it has order s. With k = A⁻¹z/h (z = stage increments),
// ŷ1 − y1 = γ0 h f0 + Σ (b̂ − b)_i h k_i = γ0 h f0 + Σ e_i z_i,  e = A⁻ᵀ(b̂ − b).
void add_radau_estimate(ButcherTableau& t, const Coefficients& k) {
  const Real gamma0 = real_eigenvalue(k.a);
  const VectorL b_hat = k.b - gamma0 * detail::lagrange_values(k.c, 0);
  const VectorL e = k.a.transpose().partialPivLu().solve(b_hat - k.b);
  t.gamma0 = static_cast<double>(gamma0);
  t.b_embedded = to_double(b_hat);
  t.e_embedded = to_double(e);
  t.embedded_order = t.stages;
}

void check_stages(TableauFamily family, int stages) {
  const model::IntegratorType& f = integrator_type(family);
  if (model::stages_accepted(f, stages)) return;
  std::ostringstream os;
  os << "Butcher tableau '" << f.name << "' with " << stages
     << " stages is not supported; accepted stage counts: " << f.min_stages;
  if (f.max_stages > f.min_stages) os << " to " << f.max_stages;
  throw InputError(InputLocation{}, os.str());
}

}  // namespace

ButcherTableau make_tableau(TableauFamily family, int stages) {
  check_stages(family, stages);
  ButcherTableau t;
  t.family = family;
  t.stages = stages;
  t.name = std::string(tableau_family_name(family)) + "_" + std::to_string(stages);
  set_properties(t);

  Coefficients k;
  switch (family) {
    case TableauFamily::gauss:
      k = collocation(detail::gauss_nodes(stages));
      break;
    case TableauFamily::radau_iia:
      k = collocation(detail::radau_right_nodes(stages));
      break;
    case TableauFamily::lobatto_iiia:
      k = collocation(detail::lobatto_nodes(stages));
      break;
    case TableauFamily::lobatto_iiic:
      k = lobatto_iiic(stages);
      break;
    case TableauFamily::sdirk:
      k = sdirk3();
      break;
  }
  // Stiffly accurate: make the last row of A and b bitwise equal (they agree to long-double
  // rounding), so that y1 is exactly the last stage value.
  if (t.stiffly_accurate) k.a.row(stages - 1) = k.b.transpose();
  t.A = to_double(k.a);
  t.b = to_double(k.b);
  t.c = to_double(k.c);
  if (model::has_embedded_estimate(integrator_type(family), stages, false)) {
    CATENA_ASSERT(family == TableauFamily::radau_iia,
                  "an embedded estimate in the catalogue for a family without its formula");
    add_radau_estimate(t, k);
  }
  return t;
}

TableauFamily parse_tableau_family(const std::string& name) {
  const model::IntegratorType* type = model::find_integrator_type(name);  // "radau" too
  for (const auto& f : families) {
    if (type && type->name == f.name) return f.family;
  }
  throw InputError(InputLocation{}, "unknown Butcher tableau family '" + name +
                                        "'; accepted: gauss, radau, radau_iia, lobatto_iiia, "
                                        "lobatto_iiic, sdirk");
}

std::string_view tableau_family_name(TableauFamily family) { return info(family).name; }

const model::IntegratorType& integrator_type(TableauFamily family) {
  const model::IntegratorType* type = model::find_integrator_type(info(family).name);
  CATENA_ASSERT(type, "TableauFamily without an entry in the integrator catalogue");
  return *type;
}

Eigen::MatrixXd a_squared(const ButcherTableau& tableau) {
  const MatrixL a = tableau.A.cast<Real>();
  return to_double(MatrixL(a * a));
}

}  // namespace catena::solvers
