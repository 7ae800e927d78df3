// The real block-diagonal form A = T D T⁻¹ of every Butcher matrix the decoupled IRK stage
// solve uses (Gauss 1–5, Radau IIA 1–5, Lobatto IIIC 2–5), and its refusal where the
// transformation does not exist (Lobatto IIIA: A singular; SDIRK: a triple eigenvalue, A
// not diagonalisable):
//  - T D T⁻¹ = A to 1e-15 and T T⁻¹ = I to cond(T)·ε (max entry; evaluated in long double
//    from the rounded double T, D, T⁻¹, so the bound is the decomposition's, not the
//    check's; measured worst 7.5e-16 and 4.4e-15, Gauss 5, cond(T) = 155);
//  - D's blocks are [λ] and [α −β; β α] with β > 0, and their eigenvalues are A's, found
//    independently by Eigen's complex eigensolver on A in double (to 1e-13);
//  - the number of real eigenvalues is s mod 2 (Gauss and Radau IIA: HW II, IV.8; Lobatto
//    IIIC measured here), and for Radau IIA with odd s the real one is γ0 of the embedded
//    estimate (the estimate's matrix is the real block's).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <complex>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "catena/solvers/time/irk/butcher_tableau.hpp"
#include "catena/solvers/time/irk/tableau_decomposition.hpp"

namespace {

using catena::solvers::decompose_butcher_matrix;
using catena::solvers::make_tableau;
using catena::solvers::TableauDecomposition;
using catena::solvers::TableauFamily;
using Real = long double;
using MatrixL = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;

struct Case {
  TableauFamily family;
  int stages;
};

std::string label(const Case& c) { return make_tableau(c.family, c.stages).name; }

std::vector<Case> decouplable() {
  std::vector<Case> cases;
  for (int s = 1; s <= 5; ++s) cases.push_back({TableauFamily::gauss, s});
  for (int s = 1; s <= 5; ++s) cases.push_back({TableauFamily::radau_iia, s});
  for (int s = 2; s <= 5; ++s) cases.push_back({TableauFamily::lobatto_iiic, s});
  return cases;
}

double max_abs(const MatrixL& m) { return static_cast<double>(m.cwiseAbs().maxCoeff()); }

// Sorted by (real, imaginary) part, for comparing eigenvalue lists.
std::vector<std::complex<double>> sorted(std::vector<std::complex<double>> v) {
  std::sort(v.begin(), v.end(), [](auto a, auto b) {
    return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag();
  });
  return v;
}

class Decouplable : public testing::TestWithParam<Case> {};

TEST_P(Decouplable, ReproducesTheButcherMatrix) {
  const auto tableau = make_tableau(GetParam().family, GetParam().stages);
  const int s = tableau.stages;
  std::string why;
  const auto form = decompose_butcher_matrix(tableau.A, &why);
  ASSERT_TRUE(form.has_value()) << tableau.name << ": " << why;
  const MatrixL T = form->T.cast<Real>(), T_inv = form->T_inv.cast<Real>(),
                D = form->D.cast<Real>(), A = tableau.A.cast<Real>();
  const double reproduction = max_abs(T * D * T_inv - A);
  const double inverse = max_abs(T * T_inv - MatrixL::Identity(s, s));
  std::printf("  %s: |T D T^-1 - A| = %.2e, |T T^-1 - I| = %.2e, cond(T) = %.2f\n",
              tableau.name.c_str(), reproduction, inverse, form->condition);
  EXPECT_LE(reproduction, 1e-15);
  // T⁻¹ rounded to double carries cond(T)·ε relative to T's scale (cond 155 for Gauss 5:
  // 4.4e-15 measured), the bound any rounded inverse has.
  EXPECT_LE(inverse, form->condition * std::numeric_limits<double>::epsilon());
  EXPECT_LT(form->condition, 1000.0);

  // Block structure and eigenvalues.
  int covered = 0, n_real = 0;
  std::vector<std::complex<double>> from_blocks;
  for (const auto& b : form->blocks) {
    EXPECT_EQ(b.offset, covered);
    covered += b.size;
    if (b.size == 1) {
      ++n_real;
      from_blocks.emplace_back(form->D(b.offset, b.offset), 0.0);
    } else {
      ASSERT_EQ(b.size, 2);
      const double alpha = form->D(b.offset, b.offset), beta = form->D(b.offset + 1, b.offset);
      EXPECT_GT(beta, 0.0);
      EXPECT_NEAR(form->D(b.offset + 1, b.offset + 1), alpha, 1e-15);
      EXPECT_NEAR(form->D(b.offset, b.offset + 1), -beta, 1e-15);
      from_blocks.emplace_back(alpha, beta);
      from_blocks.emplace_back(alpha, -beta);
    }
  }
  EXPECT_EQ(covered, s);
  EXPECT_EQ(n_real, s % 2);
  for (int i = 0; i < s; ++i)
    for (int j = 0; j < s; ++j) {
      bool in_block = false;
      for (const auto& b : form->blocks)
        in_block = in_block || (i >= b.offset && i < b.offset + b.size && j >= b.offset &&
                                j < b.offset + b.size);
      if (!in_block) {
        EXPECT_EQ(form->D(i, j), 0.0) << "(" << i << ", " << j << ")";
      }
    }
  const Eigen::EigenSolver<Eigen::MatrixXd> independent(tableau.A, false);
  std::vector<std::complex<double>> expected;
  for (int i = 0; i < s; ++i) expected.push_back(independent.eigenvalues()(i));
  const auto a = sorted(from_blocks), e = sorted(expected);
  double closest = 1e300;
  for (int i = 0; i < s; ++i) {
    EXPECT_LT(std::abs(a[static_cast<size_t>(i)] - e[static_cast<size_t>(i)]), 1e-13)
        << tableau.name << " eigenvalue " << i;
    for (int j = 0; j < i; ++j)
      closest = std::min(closest, std::abs(e[static_cast<size_t>(i)] - e[static_cast<size_t>(j)]));
  }
  if (s > 1)
    std::printf("  %s: closest eigenvalue pair %.3e apart\n", tableau.name.c_str(), closest);
  if (tableau.family == TableauFamily::radau_iia && tableau.b_embedded) {
    ASSERT_EQ(form->blocks.front().size, 1);
    EXPECT_NEAR(form->D(0, 0), tableau.gamma0, 1e-15 * tableau.gamma0);
  }
}

INSTANTIATE_TEST_SUITE_P(Catena, Decouplable, testing::ValuesIn(decouplable()),
                         [](const testing::TestParamInfo<Case>& param) {
                           return label(param.param);
                         });

TEST(TableauDecomposition, RefusesLobattoIIIA) {
  for (int s = 2; s <= 5; ++s) {
    std::string why;
    EXPECT_FALSE(decompose_butcher_matrix(make_tableau(TableauFamily::lobatto_iiia, s).A, &why));
    EXPECT_NE(why.find("singular"), std::string::npos) << why;
  }
}

TEST(TableauDecomposition, RefusesSdirk) {
  std::string why;
  EXPECT_FALSE(decompose_butcher_matrix(make_tableau(TableauFamily::sdirk, 3).A, &why));
  EXPECT_NE(why.find("repeated"), std::string::npos) << why;
}

TEST(TableauDecomposition, RefusesAJordanBlock) {
  Eigen::Matrix2d jordan;
  jordan << 0.5, 1.0, 0.0, 0.5;
  std::string why;
  EXPECT_FALSE(decompose_butcher_matrix(jordan, &why));
  EXPECT_NE(why.find("repeated"), std::string::npos) << why;
}

// A matrix built from a known T and D comes back with the same eigenvalues, whatever
// scaling and phase of the columns the decomposition chooses.
TEST(TableauDecomposition, RecoversAConstructedMatrix) {
  Eigen::Matrix3d T, D;
  T << 1.0, 0.3, -0.2, 0.4, 1.0, 0.5, -0.1, 0.2, 1.0;
  D << 0.25, 0.0, 0.0, 0.0, 0.1, -0.3, 0.0, 0.3, 0.1;
  const Eigen::Matrix3d A = T * D * T.inverse();
  const auto form = decompose_butcher_matrix(A);
  ASSERT_TRUE(form.has_value());
  ASSERT_EQ(form->blocks.size(), 2u);
  EXPECT_NEAR(form->D(0, 0), 0.25, 1e-14);
  EXPECT_NEAR(form->D(1, 1), 0.1, 1e-14);
  EXPECT_NEAR(form->D(2, 1), 0.3, 1e-14);
  EXPECT_LT((form->T * form->D * form->T_inv - A).cwiseAbs().maxCoeff(), 1e-14);
}

}  // namespace
