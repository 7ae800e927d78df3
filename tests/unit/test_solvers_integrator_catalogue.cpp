// The integrator catalogue's facts (model/integrator_catalogue.hpp) against the solvers'
// own mathematics, so the table the scene reader goes by cannot drift from what runs:
//  - make_tableau accepts exactly the catalogue's stage counts;
//  - Radau IIA offers the embedded estimate exactly where its A has a real eigenvalue (γ0,
//    the estimate's filter), and make_tableau builds it exactly there;
//  - the constraint refusal is exactly the explicit first stage (A's zero first row);
//  - the decoupled refusal is exactly where A cannot be decomposed (tableau_decomposition).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <string>

#include "catena/core/error.hpp"
#include "catena/model/integrator_catalogue.hpp"
#include "catena/solvers/time/irk/butcher_tableau.hpp"
#include "catena/solvers/time/irk/tableau_decomposition.hpp"

namespace {

using catena::model::IntegratorMethod;
using catena::model::IntegratorType;
using catena::solvers::make_tableau;
using catena::solvers::parse_tableau_family;

TEST(IntegratorCatalogueAgainstTableaus, StageCountsAreThoseMakeTableauAccepts) {
  int families = 0;
  for (const IntegratorType& type : catena::model::integrator_types()) {
    if (type.method != IntegratorMethod::irk) continue;
    ++families;
    const auto family = parse_tableau_family(std::string(type.name));
    EXPECT_EQ(&catena::solvers::integrator_type(family), &type);
    for (int s = 0; s <= 7; ++s) {
      const bool accepted = catena::model::stages_accepted(type, s);
      if (accepted)
        EXPECT_NO_THROW(make_tableau(family, s)) << type.name << " " << s;
      else
        EXPECT_THROW(make_tableau(family, s), catena::InputError) << type.name << " " << s;
    }
  }
  EXPECT_EQ(families, 5);
}

TEST(IntegratorCatalogueAgainstTableaus, EmbeddedEstimateConstraintAndDecoupledFacts) {
  for (const IntegratorType& type : catena::model::integrator_types()) {
    if (type.method != IntegratorMethod::irk) continue;
    const auto family = parse_tableau_family(std::string(type.name));
    for (int s = type.min_stages; s <= type.max_stages; ++s) {
      const auto tableau = make_tableau(family, s);
      const bool embedded = catena::model::has_embedded_estimate(type, s, false);
      EXPECT_EQ(embedded, tableau.e_embedded.has_value()) << tableau.name;
      if (type.name == "radau_iia") {
        const Eigen::VectorXcd eigenvalues = tableau.A.eigenvalues();
        const bool real_eigenvalue = (eigenvalues.imag().array().abs() < 1e-12).any();
        EXPECT_EQ(embedded, real_eigenvalue) << tableau.name;
      }
      EXPECT_EQ(!type.constraint_refusal.empty(), tableau.A.row(0).isZero()) << tableau.name;
      EXPECT_EQ(!type.decoupled_refusal.empty(),
                !catena::solvers::decompose_butcher_matrix(tableau.A).has_value())
          << tableau.name;
    }
  }
}

}  // namespace
