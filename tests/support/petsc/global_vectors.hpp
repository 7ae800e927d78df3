#pragma once
// Test vectors whose values do not depend on the partition, so that a test run on 1, 2 and
// 3 ranks sees the same one, and the norm tests compare with.
#include <petscvec.h>

namespace catena::test {

// Collective. x_i += amplitude · sin(k·i + phase) over the owned global indices i.
void add_wave(Vec x, double amplitude, double k, double phase);

// Collective. max_i |x_i|.
double max_abs(Vec x);

}  // namespace catena::test
