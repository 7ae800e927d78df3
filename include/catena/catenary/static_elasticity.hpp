#pragma once
// Static elasticity of a structure along a path of cable/beam elements (EN 50119 /
// EN 50318's "elasticity" of a contact line): at each position x along the path, the
// displacement of the path at x, in the direction of a static probe force F applied at x,
// per newton of F,
//
//   e(x) = F̂ · (r_F(x) − r_0(x)) / |F|        (m/N; "uplift" u(x) = e(x)·|F|, m)
//
// r_0: the static equilibrium of the model (StaticSolver from the reference
// configuration, the load path included); r_F: the equilibrium with F added at x. The
// response is the structure's, nonlinearity included (a tension-only dropper may go slack
// under the probe), so e depends on |F|: weakly while every dropper stays taut, strongly
// once droppers beside the point go slack.
//
// Beside it, the linear elasticity, the limit of e as |F| → 0 (what EN 50119 means by the
// elasticity of a contact line as it hangs):
//
//   e_lin(x) = Pᵀ K₀⁻¹ P / |F|²
//
// with K₀ the static tangent at r_0 (one LDLᵀ factorisation for every point, options
// prefix -elasticity_linear_) and P the probe's generalised force below. Each point also
// counts the tension-only elements (droppers) that are taut at r_0 and slack at r_F (axial
// strain below zero): where any are, e(x) is no longer the line's small-force elasticity.
//
// The probe is a model::MovingLoad along the path, spread onto the nodes of the element
// holding x by the cable shape functions exactly as the system spreads every moving load
// (SecondOrderSystem's moving loads), evaluated where it stands at x. The uplift is read
// with the same weights, u = Pᵀ(q_F − q_0)/|F| with P the probe's generalised force: the
// displacement work-conjugate to F, i.e. r(x) interpolated as the force is spread.
//
// Each r_F is found by Newton's method at the end of the load path starting from r_0
// (ReusableNewton, options prefix -elasticity_: one LDLᵀ factorisation is reused from point
// to point while it contracts, refreshed when it does not, e.g. when droppers go slack);
// when Newton fails the probe force is applied in halving increments.
#include <mpi.h>

#include <vector>

#include "catena/core/vec3.hpp"
#include "catena/model/model.hpp"
#include "catena/solvers/statics/static_solver.hpp"

namespace catena::catenary {

struct ElasticityProbe {
  // The path: cable/beam element indices in path order, consecutive elements sharing a
  // node or ending at coincident nodes (model::ElementPath); arc length is measured on the
  // reference geometry as for moving loads.
  std::vector<int> path;
  std::vector<double> positions;       // m, arc lengths along the path, each in [0, length]
  Vec3 force = Vec3(0.0, 0.0, 100.0);  // N, the probe force (nonzero); a dead load
};

struct ElasticityPoint {
  double position = 0.0;           // m along the path
  double uplift = 0.0;             // m, displacement at `position` along the force
  double elasticity = 0.0;         // m/N, uplift / |force|
  double linear_elasticity = 0.0;  // m/N, Pᵀ K₀⁻¹ P / |force|²: the limit of small forces
  int slackened = 0;               // tension-only elements taut at r_0, slack under the probe
  int newton_iterations = 0;
  int increments = 0;  // load increments of the probe force (1 unless Newton needed more)
};

struct ElasticityReport {
  std::vector<ElasticityPoint> points;  // per ElasticityProbe::positions, same order
  solvers::StaticReport base;           // the equilibrium without the probe
  long newton_iterations = 0;           // over all points
  long factorizations = 0;              // of the Newton matrix, over all points
};

// Collective: every rank passes the same model and probe and gets the same report.
// `model`'s moving loads and moving contacts are left out (the structure alone, as it
// stands statically; a pantograph's own nodes are the caller's to remove). Throws what
// StaticSolver throws for the base equilibrium, and NumericalError when the probe force
// cannot be applied at a point (Newton fails at an increment of 1/64 of it) or the
// tangent at r_0 cannot be factored or solved.
ElasticityReport static_elasticity(MPI_Comm comm, const model::Model& model,
                                   const ElasticityProbe& probe);

// Not collective. Arc length along `path` (reference geometry: the chords of its
// elements' end nodes, as for moving loads) at which node `node` is the first node of an
// element or the last node of one; −1 if it is on none.
double path_arc_length_at(const model::Model& model, const std::vector<int>& path, int node);

}  // namespace catena::catenary
