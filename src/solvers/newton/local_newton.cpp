#include "catena/solvers/newton/local_newton.hpp"

#include <petsclog.h>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <vector>

#include "catena/assembly/petsc_call.hpp"

namespace catena::solvers {
namespace {

PetscLogEvent local_newton_event() {
  static const PetscLogEvent event = [] {
    PetscClassId id = 0;
    PetscLogEvent e = 0;
    PetscClassIdRegister("CatenaLocal", &id);
    PetscLogEventRegister("CatLocalNewton", id, &e);
    return e;
  }();
  return event;
}

// The owned array of a vector for the lifetime of the object.
class OwnedArray {
 public:
  explicit OwnedArray(Vec v) : v_(v) { CATENA_PETSC(VecGetArray(v_, &data_)); }
  ~OwnedArray() { VecRestoreArray(v_, &data_); }
  OwnedArray(const OwnedArray&) = delete;
  OwnedArray& operator=(const OwnedArray&) = delete;
  double* data() const { return data_; }

 private:
  Vec v_;
  PetscScalar* data_ = nullptr;
};

// The entries of r (n owned) that the windows must hold so that the rest has a norm of at
// most `budget`: all |r_i| ≥ τ, τ the largest power of two with Σ_{|r_i| < τ} r_i² ≤
// budget² (one pass, binned by exponent). Scattered small entries (the wake behind a
// moving load, round-off) stay outside, where a threshold relative to ‖r‖∞ would seed
// windows around them and widen them needlessly.
std::vector<PetscInt> large_entries(const double* r, PetscInt n, double budget) {
  constexpr int kBins = 2100;  // exponents −1074 … 1024, offset
  constexpr int kOffset = 1075;
  std::vector<double> squares(kBins, 0.0);
  for (PetscInt i = 0; i < n; ++i) {
    if (r[i] == 0.0) continue;
    int e = 0;
    std::frexp(r[i], &e);  // |r| ∈ [2^(e−1), 2^e)
    squares[static_cast<size_t>(std::clamp(e + kOffset, 0, kBins - 1))] += r[i] * r[i];
  }
  double below = 0.0;
  int cut = 0;  // bins < cut stay outside
  while (cut < kBins && below + squares[static_cast<size_t>(cut)] <= budget * budget)
    below += squares[static_cast<size_t>(cut++)];
  const double tau = std::ldexp(1.0, cut - kOffset - 1);  // the lower edge of bin `cut`
  std::vector<PetscInt> seeds;
  for (PetscInt i = 0; i < n; ++i)
    if (r[i] != 0.0 && std::abs(r[i]) >= tau) seeds.push_back(i);
  return seeds;
}

}  // namespace

LocalNewton::LocalNewton(assembly::SecondOrderSystem& system, const LocalNewtonSettings& settings)
    : system_(system), settings_(settings), layers_(settings.layers) {
  system_.prepare_local_patches();
  worn_limit_ = settings_.worn_fraction * static_cast<double>(system_.dof_map().n_global());
}

void LocalNewton::save_resume_state(ResumeState& out) const {
  out.integers["local_newton.layers"] = layers_;
  out.integers["local_newton.misses"] = misses_;
  out.integers["local_newton.skip"] = skip_;
  out.reals["local_newton.worked_since_tangent"] = worked_since_tangent_;
  out.integers["local_newton.attempts"] = counters_.attempts;
  out.integers["local_newton.successes"] = counters_.successes;
  out.integers["local_newton.iterations"] = counters_.iterations;
  out.integers["local_newton.unknowns"] = counters_.unknowns;
}

void LocalNewton::restore_resume_state(const ResumeState& in) {
  // A run saved without local corrections (-hht_local_newton_layers 0) restores none.
  if (!in.integers.contains("local_newton.layers")) return;
  layers_ = static_cast<int>(in.integer("local_newton.layers"));
  misses_ = static_cast<int>(in.integer("local_newton.misses"));
  skip_ = static_cast<int>(in.integer("local_newton.skip"));
  worked_since_tangent_ = in.real("local_newton.worked_since_tangent");
  counters_.attempts = in.integer("local_newton.attempts");
  counters_.successes = in.integer("local_newton.successes");
  counters_.iterations = in.integer("local_newton.iterations");
  counters_.unknowns = in.integer("local_newton.unknowns");
}

bool LocalNewton::correct(Vec a, Vec r, Vec q, Vec v, Vec f, const Coefficients& c, double atol,
                          double* norm) {
  PetscLogEventBegin(local_newton_event(), 0, 0, 0, 0);
  struct EndEvent {
    ~EndEvent() { PetscLogEventEnd(local_newton_event(), 0, 0, 0, 0); }
  } end_event;
  // Where corrections keep failing (a residual spread over the system, or windows that
  // cannot be owned alone: constraints, contacts across ranks), try ever more rarely: after k
  // failures in a row, skip the next 2^k − 1 calls (at most 63). Same decision on every rank.
  if (skip_ > 0) {
    --skip_;
    return false;
  }
  ++counters_.attempts;
  // A window too narrow for this step's coupling length (it grows with h) stalls: try once
  // more twice as wide, and keep the width that worked for the next solves.
  Outcome outcome = attempt({a, r, q, v, f}, c, atol, layers_, norm);
  if (outcome == Outcome::too_narrow && 2 * layers_ <= settings_.max_layers) {
    outcome = attempt({a, r, q, v, f}, c, atol, 2 * layers_, norm);
    if (outcome == Outcome::converged) layers_ *= 2;
  }
  if (outcome != Outcome::converged) {
    misses_ = std::min(misses_ + 1, 6);
    skip_ = (1 << misses_) - 1;
    return false;
  }
  misses_ = 0;
  ++counters_.successes;
  return true;
}

LocalNewton::Outcome LocalNewton::attempt(const Vectors& vecs, const Coefficients& c, double atol,
                                          int layers, double* norm) {
  const MPI_Comm comm = system_.comm();
  PetscInt n = 0;
  CATENA_PETSC(VecGetLocalSize(vecs.r, &n));
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);

  const OwnedArray a(vecs.a), r(vecs.r), q(vecs.q), v(vecs.v), f(vecs.f);
  const std::vector<PetscInt> seeds =
      large_entries(r.data(), n, settings_.outside_fraction * atol / std::sqrt(ranks));
  const assembly::LocalPatch patch = system_.local_patch(seeds, layers, c.t);
  const size_t nu = patch.unknowns.size(), nr = patch.rows.size();

  // What the windows cannot change must already meet the tolerance (with a margin for the
  // rows at the windows' edges, which the correction moves too).
  double sums[3] = {0.0, 0.0, static_cast<double>(nu)};  // outside², inside², unknowns
  for (PetscInt i = 0, next = 0; i < n; ++i) {           // unknowns ascending: `next` walks them
    const bool inside = next < static_cast<PetscInt>(nu) && patch.unknowns[next] == i;
    sums[inside ? 1 : 0] += r.data()[i] * r.data()[i];
    if (inside) ++next;
  }
  double global[3] = {0.0, 0.0, 0.0};
  MPI_Allreduce(sums, global, 3, MPI_DOUBLE, MPI_SUM, comm);
  const double total_unknowns = global[2];
  if (total_unknowns == 0.0) return Outcome::no_window;
  if (total_unknowns >
      settings_.max_window_fraction * static_cast<double>(system_.dof_map().n_global()))
    return Outcome::too_wide;
  if (std::sqrt(std::max(global[0], 0.0)) > 0.9 * atol) return Outcome::too_narrow;
  double previous = std::sqrt(std::max(global[0], 0.0) + global[1]);

  // Kept for an undo: the unknowns' a, q, v and the rows' r, f.
  std::vector<double> saved_a(nu), saved_q(nu), saved_v(nu), saved_r(nr), saved_f(nr);
  for (size_t i = 0; i < nu; ++i) {
    const PetscInt u = patch.unknowns[i];
    saved_a[i] = a.data()[u];
    saved_q[i] = q.data()[u];
    saved_v[i] = v.data()[u];
  }
  for (size_t i = 0; i < nr; ++i) {
    saved_r[i] = r.data()[patch.rows[i]];
    saved_f[i] = f.data()[patch.rows[i]];
  }

  // ‖r‖² on this rank = the rows the windows cannot change (fixed) + the patch's rows.
  double fixed_rows = 0.0;
  for (PetscInt i = 0, next = 0; i < n; ++i) {  // rows ascending: `next` walks them
    if (next < static_cast<PetscInt>(nr) && patch.rows[next] == i)
      ++next;
    else
      fixed_rows += r.data()[i] * r.data()[i];
  }

  std::vector<double> f_old(nr), f_new(nr), inertia(nr);
  if (nu > 0) system_.patch_force(patch, q.data(), v.data(), f_old.data());
  const assembly::JacobianCoefficients jc{c.c_f * c.c_q, c.c_f * c.c_v, 1.0, 0.0, 0.0};
  Outcome outcome = Outcome::too_narrow;
  for (int it = 1; it <= settings_.max_iterations; ++it) {
    ++counters_.iterations;
    worked_since_tangent_ += total_unknowns;
    counters_.unknowns += static_cast<long>(total_unknowns);
    int failed = 0;
    if (nu > 0) {
      // Newton on the window: the unknowns' block of M + c_f (c_q K + c_v C), fresh.
      std::vector<Eigen::Triplet<double>> triplets;
      for (const assembly::PatchEntry& e : system_.patch_matrix(patch, q.data(), v.data(), jc))
        triplets.emplace_back(static_cast<int>(e.row), static_cast<int>(e.col), e.value);
      const auto size = static_cast<Eigen::Index>(nu);
      Eigen::SparseMatrix<double> J(size, size);
      J.setFromTriplets(triplets.begin(), triplets.end());
      Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
      lu.compute(J);
      Eigen::VectorXd rhs(size), delta;
      for (size_t i = 0; i < nu; ++i)
        rhs[static_cast<Eigen::Index>(i)] = -r.data()[patch.unknowns[i]];
      if (lu.info() == Eigen::Success) delta = lu.solve(rhs);
      if (lu.info() != Eigen::Success || !delta.allFinite()) {
        failed = 1;
      } else {
        for (size_t i = 0; i < nu; ++i) {
          const PetscInt u = patch.unknowns[i];
          const double d = delta[static_cast<Eigen::Index>(i)];
          a.data()[u] += d;
          q.data()[u] += c.c_q * d;
          v.data()[u] += c.c_v * d;
        }
        // R changes by M δ + c_f Δf, only in the rows of the window's kernels.
        system_.patch_force(patch, q.data(), v.data(), f_new.data());
        system_.patch_mass_product(patch, delta.data(), inertia.data());
        for (size_t i = 0; i < nr; ++i) {
          const PetscInt row = patch.rows[i];
          const double df = f_new[i] - f_old[i];
          r.data()[row] += inertia[i] + c.c_f * df;
          f.data()[row] += df;
        }
        std::swap(f_old, f_new);
      }
    }
    double local[2] = {fixed_rows, static_cast<double>(failed)};
    for (PetscInt row : patch.rows) local[0] += r.data()[row] * r.data()[row];
    MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, comm);
    const double now = std::sqrt(global[0]);
    if (global[1] > 0.0 || !std::isfinite(now)) {
      outcome = Outcome::failed;
      break;
    }
    if (now <= atol) {
      *norm = now;
      return Outcome::converged;
    }
    if (now > 0.5 * previous) break;  // stalled: Newton on a wide enough window contracts fast
    previous = now;
  }
  // Undo.
  for (size_t i = 0; i < nu; ++i) {
    const PetscInt u = patch.unknowns[i];
    a.data()[u] = saved_a[i];
    q.data()[u] = saved_q[i];
    v.data()[u] = saved_v[i];
  }
  for (size_t i = 0; i < nr; ++i) {
    r.data()[patch.rows[i]] = saved_r[i];
    f.data()[patch.rows[i]] = saved_f[i];
  }
  return outcome;
}

}  // namespace catena::solvers
