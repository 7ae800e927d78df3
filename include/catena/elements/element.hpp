#pragma once
// The element kernel contract. Elements are pure functions of their own data (reference
// geometry, section, local state): no shared nodes, no globals, no I/O, no PETSc.
//
// Sign convention (shared by every kernel and every integrator):
//   residual  R(q, v, a) = M a + f(q, v) ,   f = f_int(q) + f_damp(q, v) − f_ext(q)
//   stiffness K = ∂f/∂q ,  damping C = ∂f/∂v ,  mass M constant (ANCF).
// Integrators ask for J = c_K·K + c_C·C + c_M·M; kernels never learn which scheme runs.
//
// Local DOF ordering is node-major: all of node 0's DOFs, then node 1's, ... Each node
// carries a prefix of the nodal layout [r (3), r_x (3), r_y (3), r_z (3)]; an element uses
// the first dofs_per_node() of them (3: a point, 6: cable node, 12: beam node).
#include <span>

#include "catena/core/vec3.hpp"

namespace catena::elements {

// What the caller wants evaluated.
struct Request {
  bool force = true;
  bool stiffness = false;  // K = ∂f/∂q
  bool damping = false;    // C = ∂f/∂v
};

// A point on the static load path; dynamics runs at its end {1, 1, 1}. The path first
// tensions the cables (prestrain: 0 → 1 of ε_t = max(ε_p, AncfCable::kPathPrestrain)),
// then puts on gravity and loads (loads: 0 → 1), then moves each cable's prestrain from ε_t
// to its scene value ε_p (release: 0 → 1). Loads applied to an unstressed or compressed
// straight cable meet no transverse stiffness, and the nearest equilibrium of a
// compressed one is the inverted arch: tension first avoids both.
struct LoadPath {
  double prestrain = 1.0;
  double loads = 1.0;
  double release = 1.0;

  LoadPath() = default;
  LoadPath(double prestrain_factor, double load_factor, double release_factor)
      : prestrain(prestrain_factor), loads(load_factor), release(release_factor) {}
  // Prestrain in place, loads scaled by `load_factor` (element tests, load stepping).
  explicit LoadPath(double load_factor) : loads(load_factor) {}
};

// Local state, node-major. `v` may be empty: then velocities are zero (statics).
struct LocalState {
  std::span<const double> q;
  std::span<const double> v;
  LoadPath path;
};

// Caller-owned output buffers of size n_dofs() (f) and n_dofs()² (K, C, row-major).
// Kernels overwrite (not add to) the requested buffers.
struct LocalOutput {
  double* f = nullptr;
  double* K = nullptr;
  double* C = nullptr;
};

// Section resultants reported for output at the element mid-point: the force and couple
// the part of the line beyond the section (towards the element's second node) applies to
// the part before it, in the global frame. Two-node elements without bending carry the
// axial force only.
struct SectionResult {
  double axial_force = 0.0;            // N, the section force along the tangent, tension > 0
  double axial_strain = 0.0;           // −, against the unstretched length
  Vec3 shear_force = Vec3::Zero();     // N, the section force ⊥ the tangent
  Vec3 bending_moment = Vec3::Zero();  // N·m, the couple ⊥ the tangent
  double torsion = 0.0;                // N·m, the couple about the tangent (beams)
};

class Element {
 public:
  virtual ~Element() = default;
  virtual int n_nodes() const = 0;
  virtual int dofs_per_node() const = 0;
  int n_dofs() const { return n_nodes() * dofs_per_node(); }

  // Not collective. Fills the requested blocks of f, K, C.
  virtual void evaluate(const LocalState& s, Request r, LocalOutput out) const = 0;
  // Not collective. False if C = ∂f/∂v is zero at every state (no damping in this kernel),
  // so callers may leave C out of their tangent assembly. The default (true) is always
  // safe; kernels without damping say so.
  virtual bool has_damping() const { return true; }
  // Constant (configuration-independent) mass matrix, row-major n_dofs()².
  virtual void mass(double* M) const = 0;
  // Resultants at the element mid-point for output.
  virtual SectionResult section_result(const LocalState& s) const = 0;
};

}  // namespace catena::elements
