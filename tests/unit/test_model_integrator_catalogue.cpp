// The integrator catalogue (model/integrator_catalogue.hpp), the one table of integrator
// facts that the scene reader and the solvers both ask: names and the radau alias, stage
// ranges, where an embedded estimate exists, and the combinations refused (constraints,
// the embedded estimate with constraints, the decoupled stage solve). That the facts agree
// with the tableaus themselves is test_solvers_integrator_catalogue's.
#include <gtest/gtest.h>

#include <string>

#include "catena/model/integrator_catalogue.hpp"

namespace {

using catena::model::default_stages;
using catena::model::find_integrator_type;
using catena::model::has_embedded_estimate;
using catena::model::IntegratorMethod;
using catena::model::IntegratorOptions;
using catena::model::IntegratorType;
using catena::model::refuse_integrator;
using catena::model::stages_accepted;

const IntegratorType& type(const std::string& name) {
  const IntegratorType* t = find_integrator_type(name);
  EXPECT_NE(t, nullptr) << name;
  return *t;
}

IntegratorOptions options(const std::string& name, int stages) {
  IntegratorOptions o;
  o.type = name;
  o.stages = stages;
  return o;
}

TEST(IntegratorCatalogue, RadauIsAnAliasOfRadauIia) {
  EXPECT_EQ(&type("radau"), &type("radau_iia"));
  EXPECT_EQ(type("radau").name, "radau_iia");
  EXPECT_EQ(find_integrator_type("radau_iiia"), nullptr);
  EXPECT_EQ(find_integrator_type(""), nullptr);
  EXPECT_EQ(catena::model::integrator_type_list(),
            "hht, central_difference, rattle, gauss, radau (= radau_iia), lobatto_iiia, "
            "lobatto_iiic, sdirk, bdf, park, abm, petsc");
  EXPECT_EQ(catena::model::integrator_names(IntegratorMethod::irk),
            "gauss, radau, lobatto_iiia, lobatto_iiic, sdirk");
}

TEST(IntegratorCatalogue, StageRangesPerFamily) {
  for (const char* name : {"gauss", "radau_iia"}) {
    EXPECT_FALSE(stages_accepted(type(name), 0)) << name;
    EXPECT_TRUE(stages_accepted(type(name), 1)) << name;
    EXPECT_TRUE(stages_accepted(type(name), 5)) << name;
    EXPECT_FALSE(stages_accepted(type(name), 6)) << name;
  }
  for (const char* name : {"lobatto_iiia", "lobatto_iiic"}) {
    EXPECT_FALSE(stages_accepted(type(name), 1)) << name;
    EXPECT_TRUE(stages_accepted(type(name), 2)) << name;
    EXPECT_TRUE(stages_accepted(type(name), 5)) << name;
    EXPECT_FALSE(stages_accepted(type(name), 6)) << name;
  }
  EXPECT_FALSE(stages_accepted(type("sdirk"), 2));
  EXPECT_TRUE(stages_accepted(type("sdirk"), 3));
  EXPECT_FALSE(stages_accepted(type("sdirk"), 4));
  EXPECT_EQ(default_stages(type("sdirk"), 5), 3);  // its only stage count
  EXPECT_EQ(default_stages(type("radau"), 5), 5);  // the fallback (the options' default)
  EXPECT_TRUE(stages_accepted(type("hht"), 99));   // no stages: nothing to refuse
}

TEST(IntegratorCatalogue, EmbeddedEstimates) {
  EXPECT_TRUE(has_embedded_estimate(type("hht"), 0, false));
  EXPECT_TRUE(has_embedded_estimate(type("hht"), 0, true));
  EXPECT_TRUE(has_embedded_estimate(type("central_difference"), 0, false));
  for (int s = 1; s <= 5; ++s) {
    EXPECT_EQ(has_embedded_estimate(type("radau"), s, false), s % 2 == 1) << s;
    EXPECT_FALSE(has_embedded_estimate(type("radau"), s, true)) << s;  // index-3 filter
    EXPECT_FALSE(has_embedded_estimate(type("gauss"), s, false)) << s;
  }
  for (const char* name : {"lobatto_iiia", "lobatto_iiic", "sdirk", "petsc"})
    EXPECT_FALSE(has_embedded_estimate(type(name), 3, false)) << name;
}

TEST(IntegratorCatalogue, KeysThatApply) {
  EXPECT_TRUE(type("hht").takes_alpha);
  EXPECT_TRUE(type("petsc").takes_alpha);
  EXPECT_FALSE(type("radau").takes_alpha);
  EXPECT_TRUE(type("hht").takes_local_newton);
  EXPECT_TRUE(type("hht").takes_linearly_implicit);
  // Central differences: HHT's class with α = 0, β = 0, γ = ½; Newton for the implicit part.
  EXPECT_EQ(type("central_difference").method, IntegratorMethod::hht);
  EXPECT_TRUE(type("central_difference").takes_newton);
  EXPECT_FALSE(type("central_difference").takes_alpha);
  EXPECT_FALSE(type("central_difference").takes_local_newton);
  EXPECT_FALSE(type("central_difference").takes_linearly_implicit);
  EXPECT_FALSE(type("gauss").takes_local_newton);
  EXPECT_FALSE(type("petsc").takes_newton);
  EXPECT_TRUE(type("sdirk").takes_newton);
}

TEST(IntegratorCatalogue, RefusesEmbeddedEstimateOfRadauWithConstraints) {
  IntegratorOptions o = options("radau_iia", 3);
  o.adaptive = true;
  o.error_estimate = "embedded";
  EXPECT_FALSE(refuse_integrator(o, 0).has_value());
  const auto refusal = refuse_integrator(o, 1);
  ASSERT_TRUE(refusal.has_value());
  EXPECT_EQ(refusal->key, "error_estimate");
  EXPECT_NE(refusal->why.find("radau_iia with 3 stages has no embedded error estimate with "
                              "constraints"),
            std::string::npos)
      << refusal->why;
  EXPECT_NE(refusal->why.find("use step_doubling or auto"), std::string::npos) << refusal->why;
  o.error_estimate = "step_doubling";
  EXPECT_FALSE(refuse_integrator(o, 1).has_value());
}

TEST(IntegratorCatalogue, RefusesEmbeddedEstimateWhereThereIsNone) {
  IntegratorOptions o = options("radau_iia", 2);
  o.error_estimate = "embedded";
  const auto refusal = refuse_integrator(o, 0);
  ASSERT_TRUE(refusal.has_value());
  EXPECT_EQ(refusal->key, "error_estimate");
  EXPECT_EQ(refusal->why,
            "radau_iia with 2 stages has no embedded error estimate (hht, central_difference, "
            "radau with 1, 3 or 5 stages, bdf, park and abm have); use step_doubling or auto");
  o.type = "hht";
  EXPECT_FALSE(refuse_integrator(o, 0).has_value());
  EXPECT_FALSE(refuse_integrator(o, 2).has_value());
}

TEST(IntegratorCatalogue, RefusesConstraintsForLobattoIiiaAndPetsc) {
  for (const char* name : {"lobatto_iiia", "petsc", "central_difference"}) {
    EXPECT_FALSE(refuse_integrator(options(name, 3), 0).has_value()) << name;
    const auto refusal = refuse_integrator(options(name, 3), 2);
    ASSERT_TRUE(refusal.has_value()) << name;
    EXPECT_EQ(refusal->key, "type");
    EXPECT_NE(refusal->why.find("integrator type '" + std::string(name) +
                                "' takes no Lagrange-multiplier constraints (the scene has 2)"),
              std::string::npos)
        << refusal->why;
    EXPECT_NE(refusal->why.find("with constraints use hht, rattle, gauss, radau, lobatto_iiic, "
                                "sdirk, bdf, park or abm"),
              std::string::npos)
        << refusal->why;
  }
  EXPECT_NE(refuse_integrator(options("lobatto_iiia", 3), 1)->why.find("explicit first stage"),
            std::string::npos);
  for (const char* name : {"hht", "gauss", "radau", "lobatto_iiic", "sdirk", "bdf", "park", "abm"})
    EXPECT_FALSE(refuse_integrator(options(name, 3), 4).has_value()) << name;
}

// The multistep methods: no step doubling (it would restart the history every step), and
// BDF above order 2 only with adaptive steps (a fixed-step run's start bounds it to 2).
TEST(IntegratorCatalogue, RefusesStepDoublingAndFixedHighOrderForMultistep) {
  for (const char* name : {"bdf", "park", "abm"}) {
    IntegratorOptions o = options(name, 3);
    o.adaptive = true;
    o.error_estimate = "step_doubling";
    const auto refusal = refuse_integrator(o, 0);
    ASSERT_TRUE(refusal.has_value()) << name;
    EXPECT_EQ(refusal->key, "error_estimate");
    EXPECT_NE(refusal->why.find(std::string(name) + " is a multistep method"), std::string::npos)
        << refusal->why;
    o.error_estimate = "auto";
    EXPECT_FALSE(refuse_integrator(o, 0).has_value()) << name;
    o.error_estimate = "embedded";
    EXPECT_FALSE(refuse_integrator(o, 0).has_value()) << name;
  }
  IntegratorOptions o = options("bdf", 3);
  for (int order = 1; order <= 5; ++order) {
    o.order = order;
    o.adaptive = false;
    const auto refusal = refuse_integrator(o, 0);
    EXPECT_EQ(refusal.has_value(), order > 2) << order;
    if (refusal) {
      EXPECT_EQ(refusal->key, "order");
      EXPECT_NE(refusal->why.find("needs adaptive: true"), std::string::npos) << refusal->why;
    }
    o.adaptive = true;
    EXPECT_FALSE(refuse_integrator(o, 0).has_value()) << order;
  }
  EXPECT_EQ(type("bdf").max_order, 5);
  EXPECT_EQ(type("abm").max_order, 2);
  EXPECT_EQ(type("park").max_order, 0);
  EXPECT_FALSE(type("hht").multistep);
}

TEST(IntegratorCatalogue, RefusesDecoupledWhereItIsNotExact) {
  IntegratorOptions o = options("sdirk", 3);
  o.linear_algebra = "decoupled";
  auto refusal = refuse_integrator(o, 0);
  ASSERT_TRUE(refusal.has_value());
  EXPECT_EQ(refusal->key, "linear_algebra");
  EXPECT_NE(refusal->why.find("sdirk's A has a triple eigenvalue"), std::string::npos);
  o.type = "lobatto_iiia";
  refusal = refuse_integrator(o, 0);
  ASSERT_TRUE(refusal.has_value());
  EXPECT_NE(refusal->why.find("lobatto_iiia's A is singular"), std::string::npos);
  o.type = "radau_iia";
  EXPECT_FALSE(refuse_integrator(o, 0).has_value());
  o.newton = "full";
  refusal = refuse_integrator(o, 0);
  ASSERT_TRUE(refusal.has_value());
  EXPECT_NE(refusal->why.find("full Newton"), std::string::npos);
  o.type = "hht";  // not an IRK type: linear_algebra does not apply (the reader says so)
  EXPECT_FALSE(refuse_integrator(o, 0).has_value());
}

}  // namespace
