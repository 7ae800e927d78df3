#include "catena/solvers/modal/modal_stepper.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "catena/core/error.hpp"
#include "catena/elements/hermite.hpp"

namespace catena::solvers {
namespace {

constexpr int kMaxIterations = 50;
// |λ − law(λ)| ≤ kTolerance (1 + |λ|) per site: far below the forces' round-off relevance.
constexpr double kTolerance = 1e-10;

}  // namespace

ModalStepper::ModalStepper(ModalDynamics dynamics) : d_(std::move(dynamics)) {
  const int n = d_.n_modes();
  CATENA_ASSERT(n > 0 && static_cast<int>(d_.zeta.size()) == n &&
                    static_cast<int>(d_.constant_load.size()) == n,
                "ModalStepper: one ω, ζ and constant load per mode");
  const auto n_droppers = static_cast<Eigen::Index>(d_.droppers.size());
  D_.resize(n_droppers, n);
  dropper_tension_.resize(n_droppers);
  dropper_stiffness_.resize(n_droppers);
  dropper_damping_.resize(n_droppers);
  dropper_sign_.resize(n_droppers);
  for (Eigen::Index j = 0; j < n_droppers; ++j) {
    const ModalDropper& dr = d_.droppers[static_cast<std::size_t>(j)];
    CATENA_ASSERT(static_cast<int>(dr.elongation.size()) == n, "a dropper row per mode");
    D_.row(j) = Eigen::Map<const Eigen::RowVectorXd>(dr.elongation.data(), n);
    dropper_tension_(j) = dr.tension;
    dropper_stiffness_(j) = dr.stiffness;
    dropper_damping_(j) = dr.damping;
    dropper_sign_(j) = dr.in_modes ? -1.0 : 1.0;
  }
  D_single_ = SinglePrecisionRows(D_);
  const int np = d_.n_pantograph_dofs();
  if (np > 0) {
    Eigen::FullPivLU<Eigen::MatrixXd> lu(d_.Mp);
    if (!lu.isInvertible())
      throw NumericalError(
          "modal model: the pantographs' mass matrix is singular (a pantograph DOF without "
          "mass); give every stage a mass");
    Mp_inverse_ = lu.inverse();
    constant_g_ = Mp_inverse_ * (-d_.f0p);
  }
  for (const ModalContact& c : d_.contacts)
    if (c.head.size() != np)
      throw NumericalError("modal model: a contact's head row is not over the pantograph DOFs");
}

ModalStepper::Site ModalStepper::site(std::size_t c, double t) const {
  const ModalContact& k = d_.contacts[c];
  Site at;
  const double s = k.position(t);
  if (!k.stations.contains(s)) return at;
  at.on_path = true;
  const std::size_t e = k.stations.element_at(s);
  const double L = k.stations.element_length(e);
  const elements::HermiteAt h =
      elements::hermite_at(std::clamp(s - k.stations.start[e], 0.0, L), L);
  const int n = d_.n_modes();
  // Blocks r_A, r_A,x, r_B, r_B,x carry S1..S4 (elements/hermite.hpp).
  const int row[4] = {2 * k.node_a[e], 2 * k.node_a[e] + 1, 2 * k.node_b[e], 2 * k.node_b[e] + 1};
  at.psi = Eigen::VectorXd::Zero(n);
  at.dpsi = Eigen::VectorXd::Zero(n);
  for (int b = 0; b < 4; ++b) {
    at.rows[b] = row[b];
    at.s[b] = h.s[b];
    at.ds[b] = h.ds[b];
    const Eigen::Map<const Eigen::VectorXd> r(k.rows.data() + static_cast<std::size_t>(row[b]) * n,
                                              n);
    at.psi += h.s[b] * r;
    at.dpsi += h.ds[b] * r;
    at.w0 += h.s[b] * k.reference[static_cast<std::size_t>(row[b])];
    at.dw0 += h.ds[b] * k.reference[static_cast<std::size_t>(row[b])];
  }
  if (d_.static_correction) {
    const double* R = k.residual.data() + 16 * e;
    const auto nd = static_cast<Eigen::Index>(d_.droppers.size());
    at.r_dropper = Eigen::VectorXd::Zero(nd);
    for (int b = 0; b < 4; ++b) {
      for (int b2 = 0; b2 < 4; ++b2) at.r_self += h.s[b] * R[4 * b + b2] * h.s[b2];
      at.r_static += h.s[b] * k.residual_static[static_cast<std::size_t>(row[b])];
      if (nd > 0)
        at.r_dropper +=
            h.s[b] * Eigen::Map<const Eigen::VectorXd>(
                         k.residual_dropper.data() + static_cast<std::size_t>(row[b]) * nd, nd);
    }
  }
  return at;
}

const ModalStepper::Site& ModalStepper::cached_site(std::size_t c, double t) const {
  if (site_cache_.size() != d_.contacts.size()) site_cache_.resize(d_.contacts.size());
  std::array<CachedSite, 2>& slots = site_cache_[c];
  for (CachedSite& slot : slots)
    if (slot.t == t) return slot.site;
  CachedSite& older = std::isnan(slots[0].t)    ? slots[0]
                      : std::isnan(slots[1].t)  ? slots[1]
                      : slots[0].t < slots[1].t ? slots[0]
                                                : slots[1];
  older.t = t;
  older.site = site(c, t);
  return older.site;
}

ModalStepper::Measures ModalStepper::contact_measures(std::size_t c, const Site& at, double wire,
                                                      double wire_rate, double wire_slope,
                                                      double head, double head_rate,
                                                      double residual) const {
  const ModalContact& k = d_.contacts[c];
  Measures m;
  // δ = up·r_head − w(s); δ̇ = up·ṙ_head − (∂w/∂t at the material point) − speed ∂w/∂s.
  m.delta = k.head_reference + head - (at.w0 + wire + residual);
  m.rate = head_rate - wire_rate - k.speed * (at.dw0 + wire_slope);
  return m;
}

ModalStepper::Measures ModalStepper::contact_measures(std::size_t c, const Site& at,
                                                      const ModalState& s, double residual) const {
  const ModalContact& k = d_.contacts[c];
  const bool pantograph = s.u.size() > 0;
  return contact_measures(c, at, at.psi.dot(s.eta), at.psi.dot(s.eta_dot), at.dpsi.dot(s.eta),
                          pantograph ? k.head.dot(s.u) : 0.0,
                          pantograph ? k.head.dot(s.u_dot) : 0.0, residual);
}

double ModalStepper::contact_law(std::size_t c, const Measures& m) const {
  const ModalContact& k = d_.contacts[c];
  if (m.delta <= 0.0) return 0.0;
  return std::max(0.0, k.stiffness * m.delta + k.damping * m.rate);
}

Eigen::VectorXd ModalStepper::elongations(const Eigen::VectorXd& modal,
                                          const std::vector<const Site*>& sites,
                                          const std::vector<double>& contact_force,
                                          const std::vector<double>& slack) const {
  Eigen::VectorXd eps = modal;
  if (!d_.static_correction) return eps;
  eps += d_.dropper_residual_static;
  for (std::size_t c = 0; c < sites.size(); ++c)
    if (sites[c]->on_path && contact_force[c] != 0.0) eps += contact_force[c] * sites[c]->r_dropper;
  for (std::size_t j = 0; j < slack.size(); ++j)
    if (slack[j] != 0.0) eps -= slack[j] * d_.dropper_residual.col(static_cast<Eigen::Index>(j));
  return eps;
}

double ModalStepper::dropper_law(Eigen::Index j, double eps, double rate) const {
  const double elastic = dropper_tension_(j) + dropper_stiffness_(j) * eps;
  // Taut at q0 (sign −1): active while slack; slack at q0 (+1): active while taut.
  if (dropper_sign_(j) * elastic <= 0.0) return 0.0;
  return dropper_sign_(j) * (elastic + dropper_damping_(j) * rate);
}

double ModalStepper::penetration(const ModalState& s, std::size_t c) const {
  const Site at = site(c, s.t);
  if (!at.on_path) return 0.0;
  const double residual =
      at.r_self * s.contact_force[c] + at.r_static -
      (at.r_dropper.size() > 0 ? at.r_dropper.dot(Eigen::Map<const Eigen::VectorXd>(
                                     s.slack.data(), static_cast<Eigen::Index>(s.slack.size())))
                               : 0.0);
  return contact_measures(c, at, s, residual).delta;
}

ModalState ModalStepper::rest(double t) const {
  ModalState s;
  s.t = t;
  s.eta = Eigen::VectorXd::Zero(d_.n_modes());
  s.eta_dot = Eigen::VectorXd::Zero(d_.n_modes());
  s.u = Eigen::VectorXd::Zero(d_.n_pantograph_dofs());
  s.u_dot = Eigen::VectorXd::Zero(d_.n_pantograph_dofs());
  settle_forces(s);
  return s;
}

void ModalStepper::settle_forces(ModalState& s) const {
  // Each contact alone with its own static correction (F = k δ with δ = δ_modes − r F, the
  // coupling through other sites' residual flexibility left out), then the droppers.
  std::vector<const Site*> sites(d_.contacts.size());
  s.contact_force.assign(d_.contacts.size(), 0.0);
  for (std::size_t c = 0; c < d_.contacts.size(); ++c) {
    sites[c] = &cached_site(c, s.t);
    if (!sites[c]->on_path) continue;
    const Measures m = contact_measures(c, *sites[c], s, sites[c]->r_static);
    const double k = d_.contacts[c].stiffness;
    const double F = contact_law(c, m) / (1.0 + k * sites[c]->r_self);
    s.contact_force[c] = m.delta - sites[c]->r_self * F > 0.0 ? F : 0.0;
  }
  s.slack.assign(d_.droppers.size(), 0.0);
  if (d_.droppers.empty()) return;
  const Eigen::VectorXd eps = elongations(D_ * s.eta, sites, s.contact_force, s.slack);
  const Eigen::VectorXd rate = D_ * s.eta_dot;
  for (std::size_t j = 0; j < d_.droppers.size(); ++j) {
    const auto i = static_cast<Eigen::Index>(j);
    s.slack[j] = dropper_law(i, eps(i), rate(i));
  }
}

void ModalStepper::loads(const ModalState& s, Eigen::VectorXd& p, Eigen::VectorXd& g) const {
  const int n = d_.n_modes();
  p = Eigen::Map<const Eigen::VectorXd>(d_.constant_load.data(), n);
  Eigen::VectorXd head_load = Eigen::VectorXd::Zero(d_.n_pantograph_dofs());
  for (std::size_t c = 0; c < d_.contacts.size(); ++c) {
    if (s.contact_force[c] == 0.0) continue;
    const Site& at = cached_site(c, s.t);
    if (!at.on_path) continue;
    p += s.contact_force[c] * at.psi;
    head_load -= s.contact_force[c] * d_.contacts[c].head;
  }
  for (std::size_t j = 0; j < d_.droppers.size(); ++j)
    if (s.slack[j] != 0.0) p -= s.slack[j] * D_.row(static_cast<Eigen::Index>(j)).transpose();
  if (d_.n_pantograph_dofs() > 0) g = constant_g_ + Mp_inverse_ * head_load;
}

void ModalStepper::accelerations(const ModalState& s, Eigen::VectorXd& eta_ddot,
                                 Eigen::VectorXd& u_ddot) const {
  Eigen::VectorXd p, g;
  loads(s, p, g);
  const Eigen::Map<const Eigen::ArrayXd> omega(d_.omega.data(), d_.n_modes());
  const Eigen::Map<const Eigen::ArrayXd> zeta(d_.zeta.data(), d_.n_modes());
  eta_ddot = (p.array() - 2.0 * zeta * omega * s.eta_dot.array() - omega.square() * s.eta.array())
                 .matrix();
  if (d_.n_pantograph_dofs() > 0)
    u_ddot = g - Mp_inverse_ * (d_.Kp * s.u + d_.Cp * s.u_dot);
  else
    u_ddot.resize(0);
}

ModalStepper::Propagator& ModalStepper::propagator(double h) {
  for (Propagator& p : propagators_)
    if (p.h == h) return p;
  // Fixed steps use dt and, once, the cut last step; adaptive runs would fill this without
  // end, so only the latest few are kept.
  if (propagators_.size() >= 4) propagators_.erase(propagators_.begin());
  Propagator p;
  p.h = h;
  const int n = d_.n_modes();
  for (Eigen::ArrayXd* a : {&p.Euu, &p.Euv, &p.Evu, &p.Evv, &p.Gu0, &p.Gu1, &p.Gv0, &p.Gv1})
    a->resize(n);
  for (int i = 0; i < n; ++i) {
    const double w = d_.omega[static_cast<std::size_t>(i)];
    const ExactStep e = exact_step(Eigen::MatrixXd::Constant(1, 1, w * w),
                                   Eigen::MatrixXd::Constant(1, 1, 2.0 * d_.zeta[i] * w), h);
    p.Euu(i) = e.Euu(0, 0);
    p.Euv(i) = e.Euv(0, 0);
    p.Evu(i) = e.Evu(0, 0);
    p.Evv(i) = e.Evv(0, 0);
    p.Gu0(i) = e.Gu0(0, 0);
    p.Gu1(i) = e.Gu1(0, 0);
    p.Gv0(i) = e.Gv0(0, 0);
    p.Gv1(i) = e.Gv1(0, 0);
  }
  p.dropper_u = D_ * p.Gu1.matrix().asDiagonal() * D_.transpose();
  p.dropper_v = D_ * p.Gv1.matrix().asDiagonal() * D_.transpose();
  p.row_u.resize(d_.contacts.size());
  p.row_v.resize(d_.contacts.size());
  for (std::size_t c = 0; c < d_.contacts.size(); ++c) {
    p.row_u[c].resize(d_.contacts[c].reference.size());
    p.row_v[c].resize(d_.contacts[c].reference.size());
  }
  if (d_.n_pantograph_dofs() > 0) {
    p.pantograph = exact_step(Mp_inverse_ * d_.Kp, Mp_inverse_ * d_.Cp, h);
    for (const ModalContact& c : d_.contacts) {
      const Eigen::VectorXd g = Mp_inverse_ * (-c.head);
      p.head_u.push_back(p.pantograph.Gu1 * g);
      p.head_v.push_back(p.pantograph.Gv1 * g);
    }
  }
  propagators_.push_back(std::move(p));
  return propagators_.back();
}

void ModalStepper::row_products(Propagator& P, std::size_t c, int row) const {
  if (P.row_u[c][static_cast<std::size_t>(row)].size() > 0 || D_.rows() == 0) return;
  const int n = d_.n_modes();
  const Eigen::Map<const Eigen::ArrayXd> r(
      d_.contacts[c].rows.data() + static_cast<std::size_t>(row) * n, n);
  P.row_u[c][static_cast<std::size_t>(row)] = D_ * (P.Gu1 * r).matrix();
  P.row_v[c][static_cast<std::size_t>(row)] = D_ * (P.Gv1 * r).matrix();
}

void ModalStepper::prepare(double h) {
  Propagator& P = propagator(h);
  if (D_.rows() == 0) return;
  const int n = d_.n_modes();
  // row_products for all rows: (rows ∘ G) Dᵀ = rows (diag(G) Dᵀ), a block of rows at a time.
  const Eigen::MatrixXd u_weights = P.Gu1.matrix().asDiagonal() * D_.transpose();
  const Eigen::MatrixXd v_weights = P.Gv1.matrix().asDiagonal() * D_.transpose();
  constexpr Eigen::Index kBlock = 256;
  for (std::size_t c = 0; c < d_.contacts.size(); ++c) {
    const auto n_rows = static_cast<Eigen::Index>(d_.contacts[c].reference.size());
    const Eigen::Map<const SinglePrecisionRows::RowMajorMatrix> rows(d_.contacts[c].rows.data(),
                                                                     n_rows, n);
    for (Eigen::Index first = 0; first < n_rows; first += kBlock) {
      const Eigen::Index count = std::min(kBlock, n_rows - first);
      const Eigen::MatrixXd u = rows.middleRows(first, count) * u_weights;
      const Eigen::MatrixXd v = rows.middleRows(first, count) * v_weights;
      for (Eigen::Index r = 0; r < count; ++r) {
        const auto row = static_cast<std::size_t>(first + r);
        P.row_u[c][row] = u.row(r).transpose();
        P.row_v[c][row] = v.row(r).transpose();
      }
    }
  }
}

ModalStepResult ModalStepper::step(const ModalState& from, double h, ModalState& to) {
  Propagator& P = propagator(h);
  const int n = d_.n_modes();
  const int np = d_.n_pantograph_dofs();
  const std::size_t nc = d_.contacts.size();
  const Eigen::Index nd = D_.rows();
  Eigen::VectorXd p0, g0;
  loads(from, p0, g0);
  const Eigen::Map<const Eigen::ArrayXd> pc(d_.constant_load.data(), n);
  // The free end state: the loads at the end without the site forces.
  const Eigen::ArrayXd eta_free =
      P.Euu * from.eta.array() + P.Euv * from.eta_dot.array() + P.Gu0 * p0.array() + P.Gu1 * pc;
  const Eigen::ArrayXd rate_free =
      P.Evu * from.eta.array() + P.Evv * from.eta_dot.array() + P.Gv0 * p0.array() + P.Gv1 * pc;
  Eigen::VectorXd u_free, u_rate_free;
  if (np > 0) {
    const ExactStep& E = P.pantograph;
    u_free = E.Euu * from.u + E.Euv * from.u_dot + E.Gu0 * g0 + E.Gu1 * constant_g_;
    u_rate_free = E.Evu * from.u + E.Evv * from.u_dot + E.Gv0 * g0 + E.Gv1 * constant_g_;
  }
  to.t = from.t + h;

  // Every measure the site laws read (each contact's wire height, rate and slope, its head's
  // height and rate; each dropper's elongation and rate) is affine in the site forces λ:
  // its free value plus Σ λ_y × its change per unit λ_y. These are formed once per step —
  // the droppers' elongations by the product D η_free (their rates row by row, for the
  // droppers in the iteration only) and, per unknown, from products D (G ∘ w)
  // kept in the propagator — so the iteration itself never touches a modal vector.
  struct ContactTerms {
    double wire = 0.0, wire_rate = 0.0, wire_slope = 0.0;  // ψ·η, ψ·η̇, ψ'·η
    double head = 0.0, head_rate = 0.0;                    // head·u, head·u̇
  };
  std::vector<const Site*> sites(nc);
  std::vector<ContactTerms> free(nc);
  // Per contact on its path: D (Gu1 ∘ ψ), D (Gv1 ∘ ψ), D (Gu1 ∘ ψ').
  std::vector<Eigen::VectorXd> dropper_u(nc), dropper_v(nc), dropper_slope(nc);
  for (std::size_t c = 0; c < nc; ++c) {
    sites[c] = &cached_site(c, to.t);
    if (!sites[c]->on_path) continue;
    const Site& at = *sites[c];
    free[c].wire = at.psi.dot(eta_free.matrix());
    free[c].wire_rate = at.psi.dot(rate_free.matrix());
    free[c].wire_slope = at.dpsi.dot(eta_free.matrix());
    if (np > 0) {
      free[c].head = d_.contacts[c].head.dot(u_free);
      free[c].head_rate = d_.contacts[c].head.dot(u_rate_free);
    }
    if (nd == 0) continue;
    dropper_u[c] = dropper_v[c] = dropper_slope[c] = Eigen::VectorXd::Zero(nd);
    for (int b = 0; b < 4; ++b) {
      const int row = at.rows[b];
      row_products(P, c, row);
      dropper_u[c] += at.s[b] * P.row_u[c][static_cast<std::size_t>(row)];
      dropper_v[c] += at.s[b] * P.row_v[c][static_cast<std::size_t>(row)];
      dropper_slope[c] += at.ds[b] * P.row_u[c][static_cast<std::size_t>(row)];
    }
  }
  // Every dropper's elongation, to find those whose correction turns active; the rates
  // only of the droppers in the iteration (their damping), one row each. The product with
  // all the rows is made in single precision; `exact_elongation(j)` forms dropper j's anew
  // from its exact row (once) and returns the change, for every dropper the step's result
  // depends on: those in the iteration and those whose test the rounding could decide.
  Eigen::VectorXd eps_free;
  std::vector<char> exact(static_cast<std::size_t>(nd), 0);
  double rounding = 0.0;  // per unit bound: ‖η_free‖₂
  if (nd > 0) {
    D_single_.multiply(eta_free.matrix(), eps_free);
    rounding = eta_free.matrix().norm();
  }
  const auto exact_elongation = [&](Eigen::Index j) {
    if (exact[static_cast<std::size_t>(j)]) return 0.0;
    exact[static_cast<std::size_t>(j)] = 1;
    const double e = D_.row(j).dot(eta_free.matrix());
    const double change = e - eps_free(j);
    eps_free(j) = e;
    return change;
  };

  // The unknowns: the contacts on their paths, and the droppers whose correction is active
  // at the start or turns active during the iteration; per unit λ, the change of every
  // measure above.
  struct Unknown {
    bool contact = false;
    std::size_t index = 0;
    double lambda = 0.0;
    std::vector<ContactTerms> terms;  // per contact
    Eigen::VectorXd eps, eps_rate;    // per dropper
    double rate_free = 0.0;           // a dropper's: its free elongation rate D_j η̇_free
  };
  std::vector<Unknown> unknowns;
  std::vector<char> is_unknown(d_.droppers.size(), 0);
  const auto add = [&](bool contact, std::size_t index, double lambda) {
    Unknown y;
    y.contact = contact;
    y.index = index;
    y.lambda = lambda;
    y.terms.resize(nc);
    const auto j = static_cast<Eigen::Index>(index);
    for (std::size_t x = 0; x < nc; ++x) {
      if (!sites[x]->on_path) continue;
      ContactTerms& t = y.terms[x];
      if (contact) {
        // The modal load ψ_y: ψ_x·(G ∘ ψ_y) and ψ'_x·(G ∘ ψ_y); the head's load −head_y.
        const Eigen::ArrayXd gu = P.Gu1 * sites[index]->psi.array();
        t.wire = (sites[x]->psi.array() * gu).sum();
        t.wire_rate = (sites[x]->psi.array() * P.Gv1 * sites[index]->psi.array()).sum();
        t.wire_slope = (sites[x]->dpsi.array() * gu).sum();
        if (np > 0) {
          t.head = d_.contacts[x].head.dot(P.head_u[index]);
          t.head_rate = d_.contacts[x].head.dot(P.head_v[index]);
        }
      } else {
        // The modal load −D_j: ψ_x·(G ∘ −D_j) = −(D (G ∘ ψ_x))_j.
        t.wire = -dropper_u[x](j);
        t.wire_rate = -dropper_v[x](j);
        t.wire_slope = -dropper_slope[x](j);
      }
    }
    if (nd > 0) {
      y.eps = contact ? dropper_u[index] : Eigen::VectorXd(-P.dropper_u.col(j));
      y.eps_rate = contact ? dropper_v[index] : Eigen::VectorXd(-P.dropper_v.col(j));
    }
    if (!contact) y.rate_free = D_.row(j).dot(rate_free.matrix());
    unknowns.push_back(std::move(y));
  };
  for (std::size_t c = 0; c < nc; ++c)
    if (sites[c]->on_path) add(true, c, from.contact_force[c]);
  for (std::size_t j = 0; j < d_.droppers.size(); ++j)
    if (from.slack[j] != 0.0) {
      exact_elongation(static_cast<Eigen::Index>(j));
      add(false, j, from.slack[j]);
      is_unknown[j] = 1;
    }

  ModalStepResult result;
  Eigen::VectorXd residual, eps;
  Eigen::MatrixXd J;
  std::vector<double> forces(nc), slack(d_.droppers.size());
  for (int it = 0;; ++it) {
    // The site forces of this iterate, for the static correction.
    std::fill(forces.begin(), forces.end(), 0.0);
    std::fill(slack.begin(), slack.end(), 0.0);
    for (const Unknown& y : unknowns) (y.contact ? forces : slack)[y.index] = y.lambda;
    // Droppers whose correction turns active join the unknowns (at λ = 0; their residual
    // says by how much).
    if (nd > 0) {
      Eigen::VectorXd modal = eps_free;
      for (const Unknown& y : unknowns)
        if (y.lambda != 0.0) modal += y.lambda * y.eps;
      eps = elongations(modal, sites, forces, slack);
      for (std::size_t j = 0; j < d_.droppers.size(); ++j) {
        if (is_unknown[j]) continue;
        const auto i = static_cast<Eigen::Index>(j);
        const auto test = [&] {
          return dropper_sign_(i) * (dropper_tension_(i) + dropper_stiffness_(i) * eps(i));
        };
        // eps is affine in eps_free with slope 1: an exact eps_free(i) moves eps(i) alike.
        if (!exact[j] && std::abs(test()) <= dropper_stiffness_(i) * D_single_.bound(i) * rounding)
          eps(i) += exact_elongation(i);
        if (test() > 0.0) {
          eps(i) += exact_elongation(i);
          add(false, j, 0.0);
          is_unknown[j] = 1;
        }
      }
    }
    const auto m = static_cast<Eigen::Index>(unknowns.size());
    residual.resize(m);
    std::vector<char> active(static_cast<std::size_t>(m), 0);
    double worst = 0.0;
    for (Eigen::Index l = 0; l < m; ++l) {
      const Unknown& x = unknowns[static_cast<std::size_t>(l)];
      double law = 0.0;
      if (x.contact) {
        ContactTerms now = free[x.index];
        for (const Unknown& y : unknowns) {
          const ContactTerms& t = y.terms[x.index];
          now.wire += y.lambda * t.wire;
          now.wire_rate += y.lambda * t.wire_rate;
          now.wire_slope += y.lambda * t.wire_slope;
          now.head += y.lambda * t.head;
          now.head_rate += y.lambda * t.head_rate;
        }
        const Site& at = *sites[x.index];
        double wire_residual = at.r_self * x.lambda + at.r_static;
        if (at.r_dropper.size() > 0)
          for (std::size_t j = 0; j < slack.size(); ++j)
            wire_residual -= at.r_dropper(static_cast<Eigen::Index>(j)) * slack[j];
        law = contact_law(x.index,
                          contact_measures(x.index, at, now.wire, now.wire_rate, now.wire_slope,
                                           now.head, now.head_rate, wire_residual));
        active[static_cast<std::size_t>(l)] = law > 0.0;
      } else {
        const auto i = static_cast<Eigen::Index>(x.index);
        const double elastic = dropper_tension_(i) + dropper_stiffness_(i) * eps(i);
        if (dropper_sign_(i) * elastic > 0.0) {
          double rate = x.rate_free;
          for (const Unknown& y : unknowns) rate += y.lambda * y.eps_rate(i);
          law = dropper_law(i, eps(i), rate);
          active[static_cast<std::size_t>(l)] = 1;
        }
      }
      residual(l) = x.lambda - law;
      worst = std::max(worst, std::abs(residual(l)) / (1.0 + std::abs(x.lambda)));
    }
    if (worst <= kTolerance) {
      result.converged = true;
      result.iterations = it;
      break;
    }
    if (it == kMaxIterations) {
      std::ostringstream why;
      why << "modal model: the contact and slack-dropper forces did not settle in "
          << kMaxIterations << " iterations at t = " << to.t << " s (largest relative residual "
          << worst << ")";
      result.failure = why.str();
      result.iterations = it;
      return result;
    }
    // J = I − ∂law/∂λ over the unknowns (the active ones' rows).
    J = Eigen::MatrixXd::Identity(m, m);
    for (Eigen::Index l = 0; l < m; ++l) {
      if (!active[static_cast<std::size_t>(l)]) continue;
      const Unknown& x = unknowns[static_cast<std::size_t>(l)];
      for (Eigen::Index k = 0; k < m; ++k) {
        const Unknown& y = unknowns[static_cast<std::size_t>(k)];
        double d_law = 0.0;
        if (x.contact) {
          const ModalContact& c = d_.contacts[x.index];
          const Site& at = *sites[x.index];
          const ContactTerms& t = y.terms[x.index];
          double d_delta = t.head - t.wire;
          const double d_rate = t.head_rate - t.wire_rate - c.speed * t.wire_slope;
          // Static correction: the point's own residual flexibility, and a slack dropper's.
          if (d_.static_correction)
            d_delta -= y.contact ? (y.index == x.index ? at.r_self : 0.0)
                                 : -at.r_dropper(static_cast<Eigen::Index>(y.index));
          d_law = c.stiffness * d_delta + c.damping * d_rate;
        } else {
          const auto i = static_cast<Eigen::Index>(x.index);
          double d_eps = y.eps(i);
          if (d_.static_correction)
            d_eps += y.contact ? sites[y.index]->r_dropper(i)
                               : -d_.dropper_residual(i, static_cast<Eigen::Index>(y.index));
          d_law = dropper_sign_(i) *
                  (dropper_stiffness_(i) * d_eps + dropper_damping_(i) * y.eps_rate(i));
        }
        J(l, k) -= d_law;
      }
    }
    const Eigen::VectorXd step = J.partialPivLu().solve(-residual);
    for (Eigen::Index l = 0; l < m; ++l) unknowns[static_cast<std::size_t>(l)].lambda += step(l);
  }
  // The end state itself: the free one plus each site force's modal load through G.
  Eigen::ArrayXd load = Eigen::ArrayXd::Zero(n);
  to.u = u_free;
  to.u_dot = u_rate_free;
  to.contact_force.assign(nc, 0.0);
  to.slack.assign(d_.droppers.size(), 0.0);
  for (const Unknown& y : unknowns) {
    if (y.lambda == 0.0) continue;
    if (y.contact) {
      load += y.lambda * sites[y.index]->psi.array();
      if (np > 0) {
        to.u += y.lambda * P.head_u[y.index];
        to.u_dot += y.lambda * P.head_v[y.index];
      }
    } else {
      load -= y.lambda * D_.row(static_cast<Eigen::Index>(y.index)).transpose().array();
    }
    // A contact's force is ≥ 0 by its law (to round-off); a dropper's correction may be
    // negative: a taut bar's damping can outweigh its elastic tension, as in the element.
    (y.contact ? to.contact_force : to.slack)[y.index] =
        y.contact ? std::max(0.0, y.lambda) : y.lambda;
  }
  to.eta = (eta_free + P.Gu1 * load).matrix();
  to.eta_dot = (rate_free + P.Gv1 * load).matrix();
  return result;
}

}  // namespace catena::solvers
