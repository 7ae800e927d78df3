#pragma once
// Steps the modal model (modal_model.hpp) on plain arrays: each mode and the pantographs'
// DOFs by their exact step under loads linear over the step (exact_step.hpp), the contact
// and slack-dropper forces at the step's end solved together with it.
//
// The end-of-step state is affine in the unknown site forces λ (F per contact, ΔT per
// dropper): η₁ = η_free + Gu1 ∘ Σ λ_l w_l (w: ψ(s₁) for a contact, −d for a dropper), and
// the pantographs' u₁ likewise. The site laws are piecewise linear in λ, so a semi-smooth
// Newton iteration on r(λ) = λ − law(λ) over the sites that are (or become) active ends
// after a few iterations with the exact answer of the discrete system: contact loss and
// slack droppers are decided at the step's end, implicitly, so neither limits the step
// (an explicit force with the dropper's 10⁵ N/m against a mode's mass would). A dropper
// joins the iteration when its correction turns active. Every measure the laws read is
// affine in λ, so its change per unit λ is formed once per step (from products D (G ∘ w)
// kept per step size) and the iteration works on a few numbers per site: a step costs
// one product, D η_free (D: droppers × modes), and O(modes) per site force. That product
// is the step's largest part; it is made with D in single precision (single_precision_rows
// .hpp), and each elongation the step uses (a dropper in the iteration, or one whose slack
// test lies within the rounding's bound) is formed again from D's exact row, so the step's
// result is the double-precision one.
#include <Eigen/Dense>
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "catena/solvers/modal/exact_step.hpp"
#include "catena/solvers/modal/modal_model.hpp"
#include "catena/solvers/modal/single_precision_rows.hpp"

namespace catena::solvers {

struct ModalState {
  double t = 0.0;
  Eigen::VectorXd eta, eta_dot;       // modal coordinates (kg^½ m) and their rates
  Eigen::VectorXd u, u_dot;           // pantograph DOFs' displacements from q0 and velocities
  std::vector<double> contact_force;  // N, per contact (≥ 0)
  // N, per dropper: the correction ΔT = T − T_modes (modal_model.hpp, ModalDropper), 0 while
  // the modes have it right
  std::vector<double> slack;
};

struct ModalStepResult {
  bool converged = false;
  int iterations = 0;  // of the site forces' Newton iteration
  std::string failure;
};

class ModalStepper {
 public:
  explicit ModalStepper(ModalDynamics dynamics);

  const ModalDynamics& dynamics() const { return d_; }
  // The state at rest in the static equilibrium at time t (all displacements zero), its site
  // forces settled.
  ModalState rest(double t) const;
  // Sets s's contact forces and dropper slack from its positions and velocities (a state
  // given from outside, e.g. a restart).
  void settle_forces(ModalState& s) const;
  // One step of h from `from` into `to`.
  ModalStepResult step(const ModalState& from, double h, ModalState& to);
  // Forms, for steps of h, every path row's dropper products at once (blocked products, a
  // fraction of a second on EN 50318) instead of each when a contact first reaches its row,
  // so that those steps cost the same all along the line (real-time runs) and a run's
  // stepping time is its steps'. Optional; other step sizes stay lazy.
  void prepare(double h);
  // η̈ and ü at s.
  void accelerations(const ModalState& s, Eigen::VectorXd& eta_ddot, Eigen::VectorXd& u_ddot) const;
  // Contact c's penetration δ (m) at s (positive: in contact), for tests and output.
  double penetration(const ModalState& s, std::size_t c) const;

 private:
  // A contact's wire at the contact point at time t: on its path or not, ψ_i and ∂ψ_i/∂s,
  // the static wire height w0 and its slope.
  struct Site {
    bool on_path = false;
    Eigen::VectorXd psi, dpsi;
    // The path rows (ModalContact::rows) ψ and ψ' interpolate, with the Hermite weights.
    int rows[4] = {0, 0, 0, 0};
    double s[4] = {0, 0, 0, 0}, ds[4] = {0, 0, 0, 0};
    double w0 = 0.0, dw0 = 0.0;
    // Static correction (zero without): the residual flexibility of the point with itself
    // and with each dropper's elongation, and its residual static displacement.
    double r_self = 0.0, r_static = 0.0;
    Eigen::VectorXd r_dropper;
  };
  Site site(std::size_t c, double t) const;
  // site(c, t), kept for two times (the later one replaced by a newer time, the earlier
  // one first: a step's start is the previous step's end); a site is a function of the
  // time only.
  const Site& cached_site(std::size_t c, double t) const;
  struct Measures {
    double delta = 0.0, rate = 0.0;  // contact
  };
  // From the wire's modal height ψ·η, rate ψ·η̇ and slope ψ'·η at the point, the head's
  // height head·u and rate head·u̇; `residual`: the wire's residual (static correction)
  // displacement at the point.
  Measures contact_measures(std::size_t c, const Site& at, double wire, double wire_rate,
                            double wire_slope, double head, double head_rate,
                            double residual) const;
  Measures contact_measures(std::size_t c, const Site& at, const ModalState& s,
                            double residual) const;
  // The droppers' elongations from their modal part D η with the static correction's part
  // for the site forces (contact forces per contact, slack per dropper).
  Eigen::VectorXd elongations(const Eigen::VectorXd& modal, const std::vector<const Site*>& sites,
                              const std::vector<double>& contact_force,
                              const std::vector<double>& slack) const;
  double contact_law(std::size_t c, const Measures& m) const;
  // Dropper j's correction ΔT at elongation ε and rate ε̇, 0 when the modes have it right.
  double dropper_law(Eigen::Index j, double eps, double rate) const;
  // Modal load p and the pantographs' M⁻¹ × load g at s (the sites at s.t).
  void loads(const ModalState& s, Eigen::VectorXd& p, Eigen::VectorXd& g) const;
  struct Propagator {
    double h = 0.0;
    Eigen::ArrayXd Euu, Euv, Evu, Evv, Gu0, Gu1, Gv0, Gv1;  // per mode
    ExactStep pantograph;
    // The droppers' end elongations and rates per unit modal load: per unit load on each
    // dropper, D diag(Gu1) Dᵀ and D diag(Gv1) Dᵀ; per contact and path row r (filled when the
    // contact first reaches r), D (Gu1 ∘ row_r) and D (Gv1 ∘ row_r).
    Eigen::MatrixXd dropper_u, dropper_v;
    std::vector<std::vector<Eigen::VectorXd>> row_u, row_v;
    // Per contact: the pantographs' end state per unit contact force (load −head).
    std::vector<Eigen::VectorXd> head_u, head_v;
  };
  Propagator& propagator(double h);
  void row_products(Propagator& P, std::size_t c, int row) const;

  ModalDynamics d_;
  SinglePrecisionRows::RowMajorMatrix D_;  // droppers × modes
  SinglePrecisionRows D_single_;           // D_ rounded, for the product with η_free
  Eigen::VectorXd dropper_tension_, dropper_stiffness_, dropper_damping_;
  Eigen::VectorXd dropper_sign_;  // ∂ΔT/∂T_elastic where active: −1 in the modes, +1 not
  Eigen::MatrixXd Mp_inverse_;
  Eigen::VectorXd constant_g_;           // M_p⁻¹ (−f0_p)
  std::vector<Propagator> propagators_;  // the steps used so far (usually one or two)
  struct CachedSite {
    double t = std::numeric_limits<double>::quiet_NaN();  // NaN: empty (equals no time)
    Site site;
  };
  mutable std::vector<std::array<CachedSite, 2>> site_cache_;  // per contact
};

}  // namespace catena::solvers
