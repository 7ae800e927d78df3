#pragma once
// The initial estimate of catenary shape finding (docs/catenary.md "Shape finding"), two
// static problems on parts of the model:
//   1. the contact wire alone, held at its design heights at the dropper points (and at
//      the registrations whose height is held): the support reactions there are the
//      forces the droppers (and steady-arm preloads) must carry;
//   2. the messenger with its stitch wires (if any) under those dropper forces: where the
//      droppers' upper ends are.
// Each wire's prestrain is corrected until its mean axial force is its design tension.
#include <mpi.h>

#include <vector>

#include "catena/core/vec3.hpp"
#include "catena/model/model.hpp"
#include "static_snapshot.hpp"

namespace catena::catenary::detail {

struct ContactWireLoads {
  std::vector<double> dropper_force;       // N, upward, per CatenaryLayout::droppers
  std::vector<double> registration_force;  // N, upward, per CatenaryLayout::registrations
  int n_solves = 0;
};

// Collective. Problem 1. `dropper_weight`: N per dropper, the half of its weight that
// hangs on the contact wire (a bar lumps half its mass at each end).
ContactWireLoads solve_contact_wire_held(MPI_Comm comm, const model::Model& model,
                                         const std::vector<double>& dropper_weight,
                                         double tension_rtol);

struct MessengerShape {
  std::vector<Vec3> dropper_top;          // m, the upper node of each dropper
  double prestrain = 0.0;                 // the messenger's, giving its design tension
  std::vector<double> stitch_prestrains;  // per CatenaryLayout::stitch_wires, likewise
  int n_solves = 0;
};

// Collective. Problem 2: the messenger with its supports and masses and with its stitch
// wires hinged to it, each dropper pulling its upper node (on the messenger or a stitch
// wire) down with dropper_force + dropper_weight (N). The stitch wires carry their
// droppers to their clamps exactly as in the whole structure, so their droppers' upper
// ends come out as accurately as the messenger's.
MessengerShape solve_messenger_loaded(MPI_Comm comm, const model::Model& model,
                                      const std::vector<double>& dropper_force,
                                      const std::vector<double>& dropper_weight,
                                      double tension_rtol);

// Not collective. The next prestrain of a wire whose mean axial force is N at prestrain
// ε, aiming at tension T: a Newton step on N(ε) = EA (ε + s(N)), where the sag strain s of
// a hanging wire scales as 1/N², so dN/dε = EA / (1 + 2 EA s / N). `sag_strain` is s; for
// a wire whose ends stay put it is N/EA − ε, which the overload without it takes.
double corrected_prestrain(double prestrain, double mean_force, double tension, double EA,
                           double sag_strain);
double corrected_prestrain(double prestrain, double mean_force, double tension, double EA);

// Not collective. The sag strain of a wire (`cables`, in path order) in `snapshot`: the
// length of its deformed node polyline less its end-to-end chord, over its reference
// length. For a stitch wire N/EA − ε is not its sag strain: its ends ride on the messenger,
// whose kink at the support draws them together (by about a θ²/4 for slopes ±θ: 13.6 mm
// for an 18 m stitch on the EN 50318 messenger, more than its sag adds), so its sag is
// measured from its shape.
double sag_strain(const model::Model& model, const StaticSnapshot& snapshot,
                  const std::vector<int>& cables);

}  // namespace catena::catenary::detail
