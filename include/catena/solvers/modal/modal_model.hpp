#pragma once
// The modal model of a catenary under pantographs (analysis.structure: modal;
// docs/integrators.md, "Modal model"): the structure linearised about its static
// equilibrium q0 (solvers see it as M ü + C u̇ + K u + f0 = −contact and slack forces,
// u = q − q0), the catenary in its vibration modes below a cut-off frequency, the
// pantographs in their own DOFs, and the two non-linear parts as forces at a few sites:
//
//   catenary:    η̈_i + 2 ζ_i ω_i η̇_i + ω_i² η_i = p_i,   u_c = Σ φ_i η_i  (φ_iᵀ M φ_i = 1)
//                p_i = −φ_iᵀ f0 + Σ_c F_c ψ_ci(s_c(t)) − Σ_j ΔT_j d_ji
//   pantographs: M_p ü + C_p u̇ + K_p u + f0_p = −Σ_c F_c h_c
//
// with ψ_ci(s) = up·φ_i on the contact wire at the contact point s (the wire element's
// Hermite shape functions), d_ji = e_j·(φ_i(B) − φ_i(A)) dropper j's elongation per unit η_i,
// F_c the penalty contact force (model::MovingContact: F = max(0, k δ + c δ̇) while δ > 0)
// and ΔT_j the tension the modes get wrong for dropper j (ModalDropper: a dropper taut at q0
// going slack, or one slack at q0 pulled taut). This struct is the
// data; the catenary layer builds it (catenary/modal_build.hpp), ModalIntegrator steps it.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "catena/assembly/petsc_handle.hpp"
#include "catena/model/path_stations.hpp"
#include "catena/solvers/modal/single_precision_rows.hpp"

namespace catena::solvers {

// One pantograph's contact with its wire, in modal terms.
struct ModalContact {
  std::string name;
  model::PathStations stations;     // the wire's path
  std::vector<int> node_a, node_b;  // per path element: its end nodes' index in the rows below
  // Per path node n: rows[(2n) × n_modes + i] = up·φ_i(r_n), rows[(2n + 1) × n_modes + i] =
  // up·φ_i(r_n,x); reference[2n], reference[2n + 1]: up·r_n, up·r_n,x at q0.
  std::vector<double> rows, reference;
  double stiffness = 0.0, damping = 0.0, speed = 0.0, start = 0.0;
  // The truncated modes' static response (below): per path element, R over its four sites
  // (up·r_A, up·r_A,x, up·r_B, up·r_B,x), 16 values row-major; per path node, R between its
  // two sites and each dropper's elongation (2 × droppers values); per path node, the two
  // sites' residual displacement under the constant load.
  std::vector<double> residual, residual_dropper, residual_static;
  Eigen::VectorXd head;         // over the pantograph DOFs: up·(head displacement) = head·u
  double head_reference = 0.0;  // up·r_head at q0

  double position(double t) const { return start + speed * t; }
};

// A tension-only dropper (bar), linearised along its static direction e. Taut at q0, its
// linear part T0 + k ε + c ε̇ is in the modes (K and C), and the correction takes it back
// while it is slack (T0 + k ε < 0); slack at q0, nothing of it is in the modes, and the
// correction adds its tension while it is taut. Either way the correction is
// ΔT = T − T_modes, a tension along e, ≥ 0 but for the bar's damping (which acts while the
// strain says taut, as in the element: a fast-shortening taut bar pushes).
struct ModalDropper {
  std::vector<double> elongation;  // d_i = e·(φ_i(B) − φ_i(A)), m per unit η_i
  double tension = 0.0;            // T0 = EA (l/l0 − 1) at q0, N (< 0: slack there)
  double stiffness = 0.0;          // EA/l0, N/m
  double damping = 0.0;            // N·s/m, along the bar
  bool in_modes = true;            // taut at q0 (T0 ≥ 0)
};

// Static correction of the truncated modes (the mode-acceleration method; Craig & Kurdila,
// Fundamentals of Structural Dynamics, 2nd ed., Wiley 2006, §14.3): the modes above the
// cut-off answer a load quasi-statically, u_r = R f with the residual flexibility
// R = K⁻¹ − Σ_i φ_i φ_iᵀ / ω_i², so that u = Φ η + R f. Without it a penalty contact
// (50 kN/m) sees the wire stiffer than it is, by the flexibility of every mode left out.
// R is needed only between the sites (where the site forces act and their measures are
// taken), and is added to the compliance of the end-of-step solve; the rates of u_r are
// left out (quasi-static), and so is u_r in the output's fields.

// What the stepper needs (plain arrays: no PETSc).
struct ModalDynamics {
  // Catenary, per mode: ω (rad/s), ζ (from φᵀ C φ / 2ω: the off-diagonal modal damping is
  // left out) and the constant load −φᵀ f0.
  std::vector<double> omega, zeta, constant_load;
  // Pantographs: dense matrices over their DOFs.
  Eigen::MatrixXd Mp, Cp, Kp;
  Eigen::VectorXd f0p;
  std::vector<ModalContact> contacts;
  std::vector<ModalDropper> droppers;
  // R between the droppers' elongations, and each elongation's residual static part under
  // the constant load (empty: no static correction).
  Eigen::MatrixXd dropper_residual;
  Eigen::VectorXd dropper_residual_static;
  bool static_correction = false;

  int n_modes() const { return static_cast<int>(omega.size()); }
  int n_pantograph_dofs() const { return static_cast<int>(f0p.size()); }
};

// With what turns modal coordinates back into the system's vectors.
struct ModalModel {
  ModalDynamics dynamics;
  std::vector<double> frequency_hz;  // per mode
  double cutoff_hz = 0.0;
  // The modes over this rank's owned free DOFs (0 on the pantographs'), a row per DOF in
  // the vectors' local order and a column per mode: one block, so that rebuilding a state
  // reads it once (it is the largest thing the model holds: DOFs × modes). In single
  // precision (SinglePrecisionRows): a field rebuild streams the whole block, bound by
  // memory bandwidth, so half the bytes are about half its time (281 → 141 MB on EN 50318).
  // A rebuilt value q0 + φ̃_row·η is within bound(row)·‖η‖₂ of the double one (6·10⁻⁸ of
  // the motion's scale). The steps do not read it (their rows are ModalDynamics', in
  // double); the field samples, the registration heights and a restart's projection do.
  SinglePrecisionRows shapes;
  VecHandle q0;  // the static equilibrium (global)
  MatHandle M;   // mass matrix, to project a state onto the modes
  // The pantographs' DOFs: global indices, ascending, the same list on every rank.
  std::vector<PetscInt> pantograph_dofs;
};

}  // namespace catena::solvers
