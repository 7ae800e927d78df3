// Every Butcher tableau make_tableau offers is checked against what it claims:
//  - order p: every rooted-tree condition bᵀΦ(t) = 1/γ(t) of order ≤ p holds (the trees
//    are enumerated here, 1205 of them up to order 10), and B(p + 1) fails, so p is exact;
//  - stage order q: C(q) holds and C(q + 1) fails; row sums of A equal c;
//  - stiff accuracy exactly where claimed; A-stability (|R(iy)| ≤ 1 on a sweep and the poles
//    of R in the right half-plane); R(−1e8) ≈ 0 for the L-stable ones and ≈ ±1 otherwise;
//  - closed-form tableaus from Hairer & Wanner II, Sect. IV.5, and RADAU5's error estimate;
//  - unsupported stage counts and family names are rejected with the accepted values.
// Tolerances: 1e-13 for order and stage-order conditions (double sums of O(1) terms; the
// measured worst is 1.1e-16); 1e-15 for closed forms (a few ulps of O(1) numbers).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <utility>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/solvers/time/irk/butcher_tableau.hpp"

namespace {

using catena::InputError;
using catena::solvers::a_squared;
using catena::solvers::ButcherTableau;
using catena::solvers::make_tableau;
using catena::solvers::parse_tableau_family;
using catena::solvers::tableau_family_name;
using catena::solvers::TableauFamily;

constexpr double condition_tol = 1e-13;
constexpr double exact_tol = 1e-15;
// A condition "fails" when its residual is far above rounding. The smallest failing
// residual is Σ b_i c_i^10 − 1/11 = 1.4e-6 for Gauss s = 5; satisfied ones are ≤ 1.1e-16.
constexpr double failure_threshold = 1e-9;

// ---------------------------------------------------------------------------------------
// Rooted trees (Butcher; HW I, Sect. II.2). A tree is its root's multiset of subtrees,
// stored as indices into the list, non-increasing, so each tree appears once.
struct RootedTree {
  std::vector<int> children;
  int order = 1;       // number of vertices |t|
  double density = 1;  // γ(t) = |t| Π γ(children)
};

void choose_children(const std::vector<RootedTree>& trees, int remaining, int max_index,
                     std::vector<int>& chosen, std::vector<std::vector<int>>& out) {
  if (remaining == 0) {
    out.push_back(chosen);
    return;
  }
  for (int k = max_index; k >= 0; --k) {
    if (trees[k].order > remaining) continue;
    chosen.push_back(k);
    choose_children(trees, remaining - trees[k].order, k, chosen, out);
    chosen.pop_back();
  }
}

// All rooted trees of order ≤ max_order, ordered by order.
std::vector<RootedTree> rooted_trees(int max_order) {
  std::vector<RootedTree> trees{RootedTree{}};
  for (int n = 2; n <= max_order; ++n) {
    std::vector<std::vector<int>> child_sets;
    std::vector<int> chosen;
    choose_children(trees, n - 1, static_cast<int>(trees.size()) - 1, chosen, child_sets);
    for (auto& children : child_sets) {
      RootedTree t{children, n, static_cast<double>(n)};
      for (const int k : children) t.density *= trees[k].density;
      trees.push_back(std::move(t));
    }
  }
  return trees;
}

const std::vector<RootedTree>& trees_to_order_10() {
  static const std::vector<RootedTree> trees = rooted_trees(10);
  return trees;
}

// max over trees t with |t| ≤ max_order of |bᵀΦ(t) − 1/γ(t)|, where Φ(t) = Π_u (A Φ(u))
// componentwise over the root's subtrees u.
double max_tree_residual(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, int max_order) {
  const auto& trees = trees_to_order_10();
  std::vector<Eigen::VectorXd> a_phi;  // A Φ(t), reused by every tree having t as subtree
  double worst = 0;
  for (const auto& t : trees) {
    if (t.order > max_order) break;
    Eigen::VectorXd phi = Eigen::VectorXd::Ones(b.size());
    for (const int k : t.children) phi = phi.cwiseProduct(a_phi[k]);
    a_phi.push_back(a * phi);
    worst = std::max(worst, std::abs(b.dot(phi) - 1 / t.density));
  }
  return worst;
}

// |Σ b_i c_i^{k−1} − 1/k| for k = p + 1: the bushy tree of order p + 1.
double quadrature_residual(const ButcherTableau& t, int k) {
  return std::abs(t.b.dot(t.c.array().pow(k - 1).matrix()) - 1.0 / k);
}

// max_i |Σ_j a_ij c_j^{q−1} − c_i^q / q|: the q-th condition of C(q).
double stage_residual(const ButcherTableau& t, int q) {
  const Eigen::VectorXd lhs = t.A * t.c.array().pow(q - 1).matrix();
  const Eigen::VectorXd rhs = t.c.array().pow(q) / q;
  return (lhs - rhs).cwiseAbs().maxCoeff();
}

double max_stage_residual(const ButcherTableau& t, int q) {
  double worst = 0;
  for (int k = 1; k <= q; ++k) worst = std::max(worst, stage_residual(t, k));
  return worst;
}

// R(z) = 1 + z bᵀ(I − zA)⁻¹𝟙.
std::complex<double> stability(const ButcherTableau& t, std::complex<double> z) {
  using Cplx = std::complex<double>;
  const Eigen::Index s = t.stages;
  const Eigen::MatrixXcd m = Eigen::MatrixXcd::Identity(s, s) - z * t.A.cast<Cplx>();
  const Eigen::VectorXcd x = m.partialPivLu().solve(Eigen::VectorXcd::Ones(s));
  return 1.0 + z * t.b.cast<Cplx>().dot(x);
}

// ---------------------------------------------------------------------------------------
struct Case {
  TableauFamily family;
  int stages;
};

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (int s = 1; s <= 5; ++s) cases.push_back({TableauFamily::gauss, s});
  for (int s = 1; s <= 5; ++s) cases.push_back({TableauFamily::radau_iia, s});
  for (int s = 2; s <= 5; ++s) cases.push_back({TableauFamily::lobatto_iiia, s});
  for (int s = 2; s <= 5; ++s) cases.push_back({TableauFamily::lobatto_iiic, s});
  cases.push_back({TableauFamily::sdirk, 3});
  return cases;
}

class EveryTableau : public ::testing::TestWithParam<Case> {
 protected:
  ButcherTableau t = make_tableau(GetParam().family, GetParam().stages);
};

TEST(RootedTrees, CountsMatchOeisA000081) {
  const std::vector<int> expected{1, 1, 2, 4, 9, 20, 48, 115, 286, 719};
  std::vector<int> count(10, 0);
  for (const auto& t : trees_to_order_10()) ++count[t.order - 1];
  EXPECT_EQ(count, expected);
}

TEST_P(EveryTableau, DescribesItself) {
  EXPECT_EQ(t.stages, GetParam().stages);
  EXPECT_EQ(t.family, GetParam().family);
  EXPECT_EQ(t.name, std::string(tableau_family_name(t.family)) + "_" + std::to_string(t.stages));
  ASSERT_EQ(t.A.rows(), t.stages);
  ASSERT_EQ(t.A.cols(), t.stages);
  ASSERT_EQ(t.b.size(), t.stages);
  ASSERT_EQ(t.c.size(), t.stages);
}

TEST_P(EveryTableau, SatisfiesEveryTreeConditionUpToItsOrder) {
  ASSERT_LE(t.order, 10);
  EXPECT_LT(max_tree_residual(t.A, t.b, t.order), condition_tol) << t.name;
}

TEST_P(EveryTableau, OrderIsExact) {
  EXPECT_GT(quadrature_residual(t, t.order + 1), failure_threshold) << t.name;
}

TEST_P(EveryTableau, StageOrderIsExact) {
  EXPECT_LT(max_stage_residual(t, t.stage_order), condition_tol) << t.name;
  EXPECT_GT(stage_residual(t, t.stage_order + 1), failure_threshold) << t.name;
}

TEST_P(EveryTableau, RowSumsAreNodes) {
  EXPECT_LT((t.A.rowwise().sum() - t.c).cwiseAbs().maxCoeff(), exact_tol) << t.name;
}

TEST_P(EveryTableau, StiffAccuracyExactlyWhereClaimed) {
  const Eigen::VectorXd last_row = t.A.row(t.stages - 1).transpose();
  if (t.stiffly_accurate) {
    EXPECT_EQ(last_row, t.b) << t.name;  // bitwise: y1 is the last stage value
    EXPECT_EQ(t.c(t.stages - 1), 1.0) << t.name;
  } else {
    EXPECT_GT((last_row - t.b).cwiseAbs().maxCoeff(), failure_threshold) << t.name;
  }
}

TEST_P(EveryTableau, AStableOnTheImaginaryAxisWithPolesOnTheRight) {
  ASSERT_TRUE(t.a_stable);
  // |y| from 1e-3 to 1e6, 20 points per decade (worst measured: 1 + 1.8e-15, Gauss s = 5).
  double worst = 0;
  for (int k = -60; k <= 120; ++k) {
    for (const double sign : {-1.0, 1.0}) {
      const double y = sign * std::pow(10.0, 0.05 * k);
      worst = std::max(worst, std::abs(stability(t, {0.0, y})));
    }
  }
  EXPECT_LE(worst, 1 + 1e-12) << t.name;
  // R is analytic in Re z < 0 when its poles 1/λ(A) are in Re z > 0, i.e. Re λ > 0.
  const Eigen::VectorXcd lambda = t.A.eigenvalues();
  for (const auto& l : lambda) {
    if (std::abs(l) > 1e-12) {
      EXPECT_GT(l.real(), 0.0) << t.name;
    }
  }
}

TEST_P(EveryTableau, StabilityAtInfinity) {
  const std::complex<double> r = stability(t, -1e8);
  EXPECT_LT(std::abs(r.imag()), 1e-12);
  if (t.l_stable) {
    EXPECT_LT(std::abs(r), 1e-6) << t.name;
  } else {
    // R(∞) = (−1)^s for Gauss, (−1)^{s−1} for Lobatto IIIA (diagonal Padé approximants).
    const int power = t.family == TableauFamily::gauss ? t.stages : t.stages - 1;
    EXPECT_NEAR(r.real(), power % 2 == 0 ? 1.0 : -1.0, 1e-6) << t.name;
  }
}

TEST_P(EveryTableau, ASquaredIsTheKFormPositionMatrix) {
  const Eigen::MatrixXd a2 = a_squared(t);
  EXPECT_LT((a2 - t.A * t.A).cwiseAbs().maxCoeff(), exact_tol) << t.name;
  // A²𝟙 = Ac, and with C(2) = c²/2: the position stage is exact for constant acceleration.
  const Eigen::VectorXd row_sums = a2.rowwise().sum();
  EXPECT_LT((row_sums - t.A * t.c).cwiseAbs().maxCoeff(), exact_tol) << t.name;
  if (t.stage_order >= 2) {
    const Eigen::VectorXd half_c2 = t.c.array().square() / 2;
    EXPECT_LT((row_sums - half_c2).cwiseAbs().maxCoeff(), exact_tol) << t.name;
  }
}

TEST_P(EveryTableau, EmbeddedEstimateOnlyForOddRadau) {
  const bool expected = t.family == TableauFamily::radau_iia && t.stages % 2 == 1;
  EXPECT_EQ(t.b_embedded.has_value(), expected) << t.name;
  EXPECT_EQ(t.e_embedded.has_value(), expected) << t.name;
  EXPECT_EQ(t.embedded_order, expected ? t.stages : 0) << t.name;
  if (!expected) return;
  const Eigen::Index s = t.stages;
  const Eigen::VectorXd& b_hat = *t.b_embedded;
  // The embedded method as an (s+1)-stage tableau with an explicit first stage at c = 0.
  Eigen::MatrixXd a(s + 1, s + 1);
  a.setZero();
  a.bottomRightCorner(s, s) = t.A;
  Eigen::VectorXd b(s + 1), c(s + 1);
  b << t.gamma0, b_hat;
  c << 0.0, t.c;
  EXPECT_LT(max_tree_residual(a, b, t.embedded_order), condition_tol) << t.name;
  EXPECT_GT(std::abs(b.dot(c.array().pow(s).matrix()) - 1.0 / static_cast<double>(s + 1)),
            failure_threshold)
      << t.name;
  // γ0 is the real eigenvalue of A, and e = A⁻ᵀ(b̂ − b).
  const Eigen::MatrixXd shifted = t.A - t.gamma0 * Eigen::MatrixXd::Identity(s, s);
  EXPECT_LT(shifted.jacobiSvd().singularValues()(s - 1), 1e-14) << t.name;
  EXPECT_LT((t.A.transpose() * *t.e_embedded - (b_hat - t.b)).cwiseAbs().maxCoeff(), condition_tol)
      << t.name;
}

INSTANTIATE_TEST_SUITE_P(Catena, EveryTableau, ::testing::ValuesIn(all_cases()),
                         [](const ::testing::TestParamInfo<Case>& param_info) {
                           const Case& c = param_info.param;
                           return std::string(tableau_family_name(c.family)) + "_" +
                                  std::to_string(c.stages);
                         });

// ---------------------------------------------------------------------------------------
// Closed forms (HW II, Sect. IV.5; Butcher, Ch. 3), evaluated in long double before
// rounding, so the reference itself is accurate to half an ulp.
void expect_tableau(const ButcherTableau& t, const std::vector<std::vector<long double>>& a,
                    const std::vector<long double>& b, const std::vector<long double>& c) {
  const Eigen::Index s = static_cast<Eigen::Index>(b.size());
  ASSERT_EQ(t.stages, s);
  for (Eigen::Index i = 0; i < s; ++i) {
    EXPECT_NEAR(t.b(i), static_cast<double>(b[i]), exact_tol) << t.name << " b" << i;
    EXPECT_NEAR(t.c(i), static_cast<double>(c[i]), exact_tol) << t.name << " c" << i;
    for (Eigen::Index j = 0; j < s; ++j) {
      EXPECT_NEAR(t.A(i, j), static_cast<double>(a[i][j]), exact_tol) << t.name << " a" << i << j;
    }
  }
}

TEST(KnownTableaus, Gauss) {
  expect_tableau(make_tableau(TableauFamily::gauss, 1), {{0.5L}}, {1.0L}, {0.5L});
  const long double r3 = std::sqrt(3.0L);
  expect_tableau(make_tableau(TableauFamily::gauss, 2),
                 {{0.25L, 0.25L - r3 / 6}, {0.25L + r3 / 6, 0.25L}}, {0.5L, 0.5L},
                 {0.5L - r3 / 6, 0.5L + r3 / 6});
  const long double r15 = std::sqrt(15.0L);
  expect_tableau(make_tableau(TableauFamily::gauss, 3),
                 {{5.0L / 36, 2.0L / 9 - r15 / 15, 5.0L / 36 - r15 / 30},
                  {5.0L / 36 + r15 / 24, 2.0L / 9, 5.0L / 36 - r15 / 24},
                  {5.0L / 36 + r15 / 30, 2.0L / 9 + r15 / 15, 5.0L / 36}},
                 {5.0L / 18, 4.0L / 9, 5.0L / 18}, {0.5L - r15 / 10, 0.5L, 0.5L + r15 / 10});
}

TEST(KnownTableaus, RadauIIA) {
  expect_tableau(make_tableau(TableauFamily::radau_iia, 1), {{1.0L}}, {1.0L}, {1.0L});
  expect_tableau(make_tableau(TableauFamily::radau_iia, 2),
                 {{5.0L / 12, -1.0L / 12}, {0.75L, 0.25L}}, {0.75L, 0.25L}, {1.0L / 3, 1.0L});
  const long double r6 = std::sqrt(6.0L);
  expect_tableau(make_tableau(TableauFamily::radau_iia, 3),
                 {{(88 - 7 * r6) / 360, (296 - 169 * r6) / 1800, (-2 + 3 * r6) / 225},
                  {(296 + 169 * r6) / 1800, (88 + 7 * r6) / 360, (-2 - 3 * r6) / 225},
                  {(16 - r6) / 36, (16 + r6) / 36, 1.0L / 9}},
                 {(16 - r6) / 36, (16 + r6) / 36, 1.0L / 9}, {(4 - r6) / 10, (4 + r6) / 10, 1.0L});
}

TEST(KnownTableaus, LobattoIIIA) {
  expect_tableau(make_tableau(TableauFamily::lobatto_iiia, 2), {{0.0L, 0.0L}, {0.5L, 0.5L}},
                 {0.5L, 0.5L}, {0.0L, 1.0L});
  expect_tableau(
      make_tableau(TableauFamily::lobatto_iiia, 3),
      {{0.0L, 0.0L, 0.0L}, {5.0L / 24, 1.0L / 3, -1.0L / 24}, {1.0L / 6, 2.0L / 3, 1.0L / 6}},
      {1.0L / 6, 2.0L / 3, 1.0L / 6}, {0.0L, 0.5L, 1.0L});
}

TEST(KnownTableaus, LobattoIIIC) {
  expect_tableau(make_tableau(TableauFamily::lobatto_iiic, 2), {{0.5L, -0.5L}, {0.5L, 0.5L}},
                 {0.5L, 0.5L}, {0.0L, 1.0L});
  expect_tableau(make_tableau(TableauFamily::lobatto_iiic, 3),
                 {{1.0L / 6, -1.0L / 3, 1.0L / 6},
                  {1.0L / 6, 5.0L / 12, -1.0L / 12},
                  {1.0L / 6, 2.0L / 3, 1.0L / 6}},
                 {1.0L / 6, 2.0L / 3, 1.0L / 6}, {0.0L, 0.5L, 1.0L});
}

TEST(KnownTableaus, AlexanderSdirk) {
  const ButcherTableau t = make_tableau(TableauFamily::sdirk, 3);
  const double g = t.A(0, 0);
  EXPECT_NEAR(g, 0.4358665215, 1e-10);  // HW II, Sect. IV.6
  EXPECT_LT(std::abs(((g - 3) * g + 1.5) * g - 1.0 / 6), 1e-16);
  const long double gl = g;
  expect_tableau(t,
                 {{gl, 0.0L, 0.0L},
                  {(1 - gl) / 2, gl, 0.0L},
                  {-(6 * gl * gl - 16 * gl + 1) / 4, (6 * gl * gl - 20 * gl + 5) / 4, gl}},
                 {-(6 * gl * gl - 16 * gl + 1) / 4, (6 * gl * gl - 20 * gl + 5) / 4, gl},
                 {gl, (1 + gl) / 2, 1.0L});
}

// RADAU5 (HW II, Sect. IV.8): γ0 = (6 + 81^{1/3} − 9^{1/3})/30, the real eigenvalue of A,
// and e = γ0 (−13 − 7√6, −13 + 7√6, −1)/3.
TEST(KnownTableaus, Radau5ErrorEstimate) {
  const ButcherTableau t = make_tableau(TableauFamily::radau_iia, 3);
  const long double gamma0 = (6 + std::cbrt(81.0L) - std::cbrt(9.0L)) / 30;
  EXPECT_NEAR(t.gamma0, static_cast<double>(gamma0), exact_tol);
  const long double r6 = std::sqrt(6.0L);
  const Eigen::Vector3d e(static_cast<double>(gamma0 * (-13 - 7 * r6) / 3),
                          static_cast<double>(gamma0 * (-13 + 7 * r6) / 3),
                          static_cast<double>(-gamma0 / 3));
  ASSERT_TRUE(t.e_embedded.has_value());
  EXPECT_LT((*t.e_embedded - e).cwiseAbs().maxCoeff(), 1e-14);
  // Implicit Euler (s = 1): γ0 = 1 and b̂ = 0, i.e. the explicit Euler step.
  const ButcherTableau euler = make_tableau(TableauFamily::radau_iia, 1);
  EXPECT_EQ(euler.gamma0, 1.0);
  EXPECT_LT(std::abs((*euler.b_embedded)(0)), exact_tol);
}

// ---------------------------------------------------------------------------------------
void expect_rejected(TableauFamily family, int stages, const std::string& accepted) {
  try {
    make_tableau(family, stages);
    ADD_FAILURE() << tableau_family_name(family) << " accepted " << stages << " stages";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(std::string(tableau_family_name(family))), std::string::npos) << what;
    EXPECT_NE(what.find(std::to_string(stages) + " stages"), std::string::npos) << what;
    EXPECT_NE(what.find("accepted stage counts: " + accepted), std::string::npos) << what;
  }
}

TEST(UnsupportedStages, ThrowInputErrorWithTheAcceptedRange) {
  for (const int s : {-1, 0, 6, 100}) {
    expect_rejected(TableauFamily::gauss, s, "1 to 5");
    expect_rejected(TableauFamily::radau_iia, s, "1 to 5");
  }
  for (const int s : {0, 1, 6}) {
    expect_rejected(TableauFamily::lobatto_iiia, s, "2 to 5");
    expect_rejected(TableauFamily::lobatto_iiic, s, "2 to 5");
  }
  for (const int s : {1, 2, 4}) expect_rejected(TableauFamily::sdirk, s, "3");
}

TEST(ParseTableauFamily, AcceptsTheDocumentedNames) {
  EXPECT_EQ(parse_tableau_family("gauss"), TableauFamily::gauss);
  EXPECT_EQ(parse_tableau_family("radau"), TableauFamily::radau_iia);
  EXPECT_EQ(parse_tableau_family("radau_iia"), TableauFamily::radau_iia);
  EXPECT_EQ(parse_tableau_family("lobatto_iiia"), TableauFamily::lobatto_iiia);
  EXPECT_EQ(parse_tableau_family("lobatto_iiic"), TableauFamily::lobatto_iiic);
  EXPECT_EQ(parse_tableau_family("sdirk"), TableauFamily::sdirk);
  for (const auto& c : all_cases()) {
    EXPECT_EQ(parse_tableau_family(std::string(tableau_family_name(c.family))), c.family);
  }
}

TEST(ParseTableauFamily, RejectsOthersListingTheAcceptedNames) {
  for (const std::string bad : {"", "Gauss", "radau5", "lobatto", "bdf2"}) {
    try {
      parse_tableau_family(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("'" + bad + "'"), std::string::npos) << what;
      EXPECT_NE(what.find("gauss, radau, radau_iia, lobatto_iiia, lobatto_iiic, sdirk"),
                std::string::npos)
          << what;
    }
  }
}

}  // namespace
