// A moving load alone: where it acts as it travels and the generalised force it applies.
#include <gtest/gtest.h>

#include <vector>

#include "catena/couplings/moving_load.hpp"
#include "catena/elements/hermite.hpp"
#include "model_builders.hpp"

namespace catena {
namespace {

using couplings::MovingLoad;

struct LoadModel {
  model::Model m;
  model::MovingLoad load;
  LoadModel() {
    model::CableProps cable;
    cable.EA = 1e7;
    cable.mass_per_length = 1.0;
    test::add_line(m, {0, 0, 0}, {8, 0, 0}, 4, cable);  // elements of 2 m
    test::set_reference_frames(m);
    load.elements = {0, 1, 2, 3};
    load.force = Vec3(0, 10.0, -100.0);
    load.speed = 10.0;
    load.start = 1.0;
    load.start_time = 0.2;
  }
};

TEST(MovingLoad, ActsOnTheElementUnderItOnlyWhileOnThePath) {
  LoadModel lm;
  const MovingLoad load(lm.m, lm.load, {true, true, true, true});
  std::vector<int> active;
  load.active_dofs(0.1, active);  // before start_time
  EXPECT_TRUE(active.empty());
  load.active_dofs(0.25, active);  // s = 1.5 m: element 0
  ASSERT_EQ(active.size(), 12u);
  EXPECT_EQ(load.dofs()[static_cast<size_t>(active[0])].index, 0);
  EXPECT_EQ(load.dofs()[static_cast<size_t>(active[6])].index, 1);
  load.active_dofs(0.3, active);  // s = 2 m, the boundary: the first element
  EXPECT_EQ(load.dofs()[static_cast<size_t>(active[0])].index, 0);
  load.active_dofs(0.95, active);  // s = 8.5 m: off the end
  EXPECT_TRUE(active.empty());
}

TEST(MovingLoad, AnotherRanksElementIsNotActedOn) {
  LoadModel lm;
  const MovingLoad load(lm.m, lm.load, {false, true, false, false});
  EXPECT_EQ(load.dofs().size(), 12u);
  std::vector<int> active;
  load.active_dofs(0.25, active);  // on element 0: evaluated elsewhere
  EXPECT_TRUE(active.empty());
  load.active_dofs(0.45, active);  // s = 3.5 m: element 1
  EXPECT_EQ(active.size(), 12u);
}

TEST(MovingLoad, GeneralisedForceIsMinusShapeTransposeTimesF) {
  LoadModel lm;
  const MovingLoad load(lm.m, lm.load, {true, true, true, true});
  const double t = 0.27;  // s = 1.7 m, x = 1.7 m into element 0 (L = 2 m)
  std::vector<double> f(12), K(144, 1.0), q(12, 0.0);
  couplings::Scratch scratch;
  const couplings::MatrixRequest r{{1.0, 1.0, 1.0}, K.data()};
  load.evaluate({q, {}, {}, t}, f.data(), {&r, 1}, scratch);
  const elements::HermiteAt h = elements::hermite_at(1.7, 2.0);
  for (int a = 0; a < 4; ++a)
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(f[3 * a + d], -h.s[a] * lm.load.force[d], 1e-12);
  // The position blocks carry the whole force (S1 + S3 = 1); it adds no stiffness.
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(f[d] + f[6 + d], -lm.load.force[d], 1e-12);
  for (double x : K) EXPECT_EQ(x, 0.0);
}

}  // namespace
}  // namespace catena
