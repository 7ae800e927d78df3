#include "window_statics.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/model/catenary_window.hpp"
#include "catena/model/unknown_kinds.hpp"
#include "static_phase.hpp"

namespace catena::app {
namespace {

constexpr double kAgreement = 1e-5;  // m (a slope's: the same over 1 m of wire)
constexpr int kMaxRounds = 50;

// Collective. The position and slope r_x of `nodes` in q (free there), on every rank.
std::vector<StaticHolds::End> ends_of(const assembly::SecondOrderSystem& system, Vec q,
                                      const std::vector<int>& nodes) {
  const assembly::DofMap& dofs = system.dof_map();
  const int rank = mpi_rank(system.comm());
  std::vector<double> values(6 * nodes.size(), 0.0);
  const PetscScalar* x = nullptr;
  CATENA_PETSC(VecGetArrayRead(q, &x));
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (dofs.node_owner(nodes[i]) != rank) continue;
    const model::UnknownKindInfo& kind = model::kind_info(dofs.node_kind(nodes[i]));
    const model::Node& node = system.model().nodes[static_cast<std::size_t>(nodes[i])];
    for (int d = 0; d < 6; ++d) {
      const int component = d < 3 ? kind.position + d : kind.gradients + d - 3;
      const PetscInt g = dofs.global_dof(nodes[i], component);
      // A fixed component (the plane of a 2D catenary) is the reference's.
      values[6 * i + static_cast<std::size_t>(d)] = g >= 0  ? x[g - dofs.first_owned()]
                                                    : d < 3 ? node.position[d]
                                                            : node.tangent[d - 3];
    }
  }
  CATENA_PETSC(VecRestoreArrayRead(q, &x));
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM,
                system.comm());
  std::vector<StaticHolds::End> out;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    out.push_back({nodes[i], Vec3(values[6 * i], values[6 * i + 1], values[6 * i + 2]),
                   Vec3(values[6 * i + 3], values[6 * i + 4], values[6 * i + 5])});
  return out;
}

}  // namespace

void solve_window_statics(assembly::SecondOrderSystem& system, Vec q, Vec q_line,
                          const CommandLine& cl) {
  const model::Model& m = system.model();
  const model::CatenaryWindow& w = *m.catenary->window;
  const std::vector<int> ahead = model::window_state_sources(m, model::WindowImage::ahead);
  const std::vector<int> behind = model::window_state_sources(m, model::WindowImage::behind);
  // Each absorbing end and its image inside the window, and the move between them.
  std::vector<int> ends, images;
  std::vector<double> dx;
  for (const model::AbsorbingEnd& end : m.absorbing_ends) {
    const int a = ahead[static_cast<std::size_t>(end.node)];
    const int b = behind[static_cast<std::size_t>(end.node)];
    ends.push_back(end.node);
    images.push_back(a != model::kWindowEnters ? a : b);
    dx.push_back(a != model::kWindowEnters ? -w.shift_x() : w.shift_x());
    if (images.back() == model::kWindowEnters)
      throw Error("catenary.window: an end of the window has no image inside it");
  }
  StaticHolds holds;
  holds.catenary_alone = true;
  for (const int end : ends) {  // first where the builder put them
    const model::Node& node = m.nodes[static_cast<std::size_t>(end)];
    holds.ends_at.push_back({end, node.position, node.tangent});
  }
  // The fixed point x = G(x) of the ends' places (x: each end's position and slope; G: where
  // a static solve holding them at x puts their images, moved a period). Plain iteration
  // took 8 solves on meshes/long_line_window.yaml, its last four each taking only a quarter
  // of the change off. Anderson acceleration (Walker & Ni, SIAM J. Numer. Anal. 49, 2011)
  // combines the last kDepth steps: with f = G(x) − x, the next x is G(x) − ΔG γ, where γ
  // fits ΔF γ to f in least squares (ΔF, ΔG: the differences of successive f and G). The
  // test of agreement is on f, as for the plain iteration, and the agreed step is G(x).
  constexpr int kDepth = 3;
  const Eigen::Index n = 6 * static_cast<Eigen::Index>(ends.size());
  Eigen::VectorXd x(n), f_previous, g_previous;
  for (std::size_t i = 0; i < ends.size(); ++i) {
    const Eigen::Index at = 6 * static_cast<Eigen::Index>(i);
    x.segment<3>(at) = holds.ends_at[i].position;
    x.segment<3>(at + 3) = holds.ends_at[i].slope;
  }
  std::vector<Eigen::VectorXd> f_steps, g_steps;  // the last kDepth ΔF and ΔG columns
  int round = 0;
  const double start = MPI_Wtime();
  double last_line = start;  // a progress line once cl.progress_seconds have passed
  for (double change = 1.0; change > kAgreement; ++round) {
    if (const double now = MPI_Wtime(); round > 0 && now - last_line >= cl.progress_seconds) {
      last_line = now;
      if (mpi_rank(system.comm()) == 0) {
        std::printf(
            "progress: window statics, static solve %d of the catenary alone, the ends %.3g mm "
            "from where the line has them (agreed at %.3g mm), wall %.0f s\n",
            round, 1e3 * change, 1e3 * kAgreement, now - start);
        std::fflush(stdout);
      }
    }
    if (round == kMaxRounds)
      throw NumericalError(
          "catenary.window: the window's ends did not settle where the line "
          "has them in " +
          std::to_string(kMaxRounds) + " static solves (last change " + std::to_string(change) +
          " m)");
    system.reference_state(q_line);
    solve_statics_holding(system, q_line, cl, holds);
    const std::vector<StaticHolds::End> at = ends_of(system, q_line, images);
    Eigen::VectorXd g(n);
    change = 0.0;
    for (std::size_t i = 0; i < ends.size(); ++i) {
      const Eigen::Index k = 6 * static_cast<Eigen::Index>(i);
      g.segment<3>(k) = at[i].position + Vec3(dx[i], 0.0, 0.0);
      g.segment<3>(k + 3) = at[i].slope;
      // A slope's change as the displacement it makes over a metre of wire.
      change = std::max({change, (g.segment<3>(k) - x.segment<3>(k)).norm(),
                         (g.segment<3>(k + 3) - x.segment<3>(k + 3)).norm()});
    }
    const Eigen::VectorXd f = g - x;
    x = g;
    if (change > kAgreement && f_previous.size() == n) {
      f_steps.push_back(f - f_previous);
      g_steps.push_back(g - g_previous);
      if (static_cast<int>(f_steps.size()) > kDepth) {
        f_steps.erase(f_steps.begin());
        g_steps.erase(g_steps.begin());
      }
      const Eigen::Index m_steps = static_cast<Eigen::Index>(f_steps.size());
      Eigen::MatrixXd dF(n, m_steps), dG(n, m_steps);
      for (Eigen::Index c = 0; c < m_steps; ++c) {
        dF.col(c) = f_steps[static_cast<std::size_t>(c)];
        dG.col(c) = g_steps[static_cast<std::size_t>(c)];
      }
      x -= dG * dF.colPivHouseholderQr().solve(f);
    }
    f_previous = f;
    g_previous = g;
    for (std::size_t i = 0; i < ends.size(); ++i) {
      const Eigen::Index k = 6 * static_cast<Eigen::Index>(i);
      holds.ends_at[i].position = x.segment<3>(k);
      holds.ends_at[i].slope = x.segment<3>(k + 3);
    }
  }
  double moved = 0.0;
  for (const StaticHolds::End& end : holds.ends_at)
    moved = std::max(moved,
                     (end.position - m.nodes[static_cast<std::size_t>(end.node)].position).norm());
  holds.catenary_alone = false;
  const solvers::StaticReport report = solve_statics_holding(system, q, cl, holds);
  if (mpi_rank(system.comm()) == 0) {
    std::printf(
        "window: its ends held where the line has them (%d static solves of the catenary "
        "alone; they moved up to %.3g mm from where the builder put them)\n",
        round, 1e3 * moved);
    std::printf("initial static equilibrium: %d load steps, %d Newton iterations, |f| = %.3e N\n",
                report.n_load_steps, report.n_newton_iterations, report.residual_norm);
    std::fflush(stdout);
  }
}

std::unique_ptr<WindowMover> start_window(assembly::SecondOrderSystem& system, Vec q,
                                          const CommandLine& cl) {
  VecHandle q_line = system.create_vector();
  solve_window_statics(system, q, q_line.get(), cl);
  return std::make_unique<WindowMover>(system, q_line.get());
}

}  // namespace catena::app
