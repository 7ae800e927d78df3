#include "modal_setup.hpp"

#include <cstdio>
#include <filesystem>
#include <span>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "catena/assembly/node_order.hpp"
#include "catena/assembly/petsc_call.hpp"
#include "catena/catenary/modal_build.hpp"
#include "catena/core/error.hpp"
#include "catena/io/modal_basis.hpp"
#include "catena/solvers/modal/modal_integrator.hpp"
#include "catena/solvers/modes/modes_check.hpp"
#include "log_stage.hpp"
#include "output_preflight.hpp"
#include "run_info.hpp"

namespace catena::app {
namespace {

// A stored mode is this structure's when its relative residual and modal mass are within
// this of exact: the eigen-solve converges to 1e-10, and a change of the structure that
// moves the modes (a tension, a stiffness, a mass 10⁻⁶ off) shows far above it.
constexpr double kBasisTolerance = 1e-7;

struct Source {
  solvers::Modes modes;
  std::string how;  // for the summary line
};

void print(int rank, const std::string& line) {
  if (rank != 0) return;
  std::printf("%s\n", line.c_str());
  std::fflush(stdout);
}

solvers::Modes compute(const catenary::ModalStructure& s, Vec q0, const model::Model& m,
                       double cutoff) {
  return solvers::compute_modes_below(s.matrices.K.get(), s.matrices.M.get(), s.catenary_dofs,
                                      cutoff, q0, m.source_file, "analysis.modal_cutoff");
}

// The basis file's modes as vectors laid out as q0, checked against the structure.
solvers::Modes read_checked(MPI_Comm comm, const catenary::ModalStructure& s, Vec q0,
                            const model::Model& m, const assembly::NodeOrder& order, double cutoff,
                            const std::string& path) {
  io::ModalBasis basis = io::read_modal_basis(comm, path, m, {order.n_rows, order.owned}, cutoff);
  if (basis.frequency.empty()) {
    std::ostringstream why;
    why << "this modal basis holds no mode below " << cutoff
        << " Hz (analysis.modal_cutoff); raise the cut-off frequency";
    throw InputError({path, 0, "analysis.modal_basis"}, why.str());
  }
  solvers::Modes modes;
  modes.frequency = basis.frequency;
  std::vector<Vec> shapes;
  for (std::vector<double>& values : basis.shapes) {
    VecHandle v;
    CATENA_PETSC(VecDuplicate(q0, v.out()));
    double* a = nullptr;
    CATENA_PETSC(VecGetArray(v.get(), &a));
    std::copy(values.begin(), values.end(), a);
    CATENA_PETSC(VecRestoreArray(v.get(), &a));
    std::vector<double>().swap(values);  // not held twice
    shapes.push_back(v.get());
    modes.shape.push_back(std::move(v));
  }
  const std::string mismatch =
      solvers::modes_mismatch(s.matrices.K.get(), s.matrices.M.get(), s.catenary_dofs, cutoff,
                              modes.frequency, shapes, kBasisTolerance);
  if (!mismatch.empty())
    throw InputError({path, 0, "analysis.modal_basis"},
                     "the modes in this file are not this scene's: " + mismatch +
                         ". Name another file, or delete this one: the run then computes the "
                         "modes and writes them there");
  return modes;
}

void write(MPI_Comm comm, const solvers::Modes& modes, const model::Model& m,
           const assembly::NodeOrder& order, double cutoff, const std::string& path) {
  std::vector<const double*> arrays;
  std::vector<std::span<const double>> shapes;
  for (const VecHandle& v : modes.shape) {
    const double* a = nullptr;
    CATENA_PETSC(VecGetArrayRead(v.get(), &a));
    arrays.push_back(a);
    shapes.emplace_back(a, order.owned.size());
  }
  try {
    io::write_modal_basis(comm, path, m, {order.n_rows, order.owned}, cutoff, modes.frequency,
                          shapes, code_version());
  } catch (...) {
    for (std::size_t k = 0; k < arrays.size(); ++k)
      CATENA_PETSC(VecRestoreArrayRead(modes.shape[k].get(), &arrays[k]));
    throw;
  }
  for (std::size_t k = 0; k < arrays.size(); ++k)
    CATENA_PETSC(VecRestoreArrayRead(modes.shape[k].get(), &arrays[k]));
}

Source modes_for(assembly::SecondOrderSystem& system, const catenary::ModalStructure& s, Vec q0,
                 int rank) {
  const model::Model& m = system.model();
  MPI_Comm comm = system.comm();
  const double cutoff = m.dynamic_options.modal_cutoff;
  const std::string& path = m.dynamic_options.modal_basis;
  char line[256];
  const double start = MPI_Wtime();
  std::error_code unreadable;  // an unreadable path counts as absent; the write then says why
  int exists = path.empty() ? 0 : std::filesystem::exists(path, unreadable) ? 1 : 0;
  MPI_Bcast(&exists, 1, MPI_INT, 0, comm);
  if (exists) {
    std::snprintf(line, sizeof line, "modal model: modes below %g Hz from %s...", cutoff,
                  path.c_str());
    print(rank, line);
    const assembly::NodeOrder order = assembly::node_order(system.dof_map());
    Source out{read_checked(comm, s, q0, m, order, cutoff, path), {}};
    std::snprintf(line, sizeof line, "read from %s and checked in %.2f s", path.c_str(),
                  MPI_Wtime() - start);
    out.how = line;
    return out;
  }
  // (Whether the file can be written was checked before any solving: check_modal_basis_path.)
  std::snprintf(line, sizeof line, "modal model: modes below %g Hz (spectrum slicing)...", cutoff);
  print(rank, line);
  Source out{compute(s, q0, m, cutoff), {}};
  double worst = 0.0;
  for (double r : out.modes.residual) worst = std::max(worst, r);
  std::snprintf(line, sizeof line, "eigen-solve %.2f s (%d restarts, largest residual %.1e)",
                MPI_Wtime() - start, out.modes.n_iterations, worst);
  out.how = line;
  if (!path.empty()) {
    const double written = MPI_Wtime();
    const assembly::NodeOrder order = assembly::node_order(system.dof_map());
    write(comm, out.modes, m, order, cutoff, path);
    std::snprintf(line, sizeof line, ", written to %s in %.2f s (runs that name it reuse them)",
                  path.c_str(), MPI_Wtime() - written);
    out.how += line;
  }
  return out;
}

}  // namespace

std::unique_ptr<solvers::TimeIntegrator> make_modal_integrator(assembly::SecondOrderSystem& system,
                                                               Vec q0, int rank) {
  const double cutoff = system.model().dynamic_options.modal_cutoff;
  const LogStage stage("Modes");
  catenary::ModalStructure structure = catenary::modal_structure(system, q0);
  Source source = modes_for(system, structure, q0, rank);
  catenary::ModalBuildReport report;
  solvers::ModalModel model = catenary::build_modal_model(system, q0, std::move(structure),
                                                          std::move(source.modes), cutoff, &report);
  const std::vector<double> f = model.frequency_hz;
  const std::size_t n_pantograph_dofs = model.pantograph_dofs.size();
  const std::size_t n_droppers = model.dynamics.droppers.size();
  auto integrator = std::make_unique<solvers::ModalIntegrator>(std::move(model));
  // The droppers' responses along the contacts' paths for the run's fixed step, before the
  // steps (adaptive steps each form what they need).
  const double prepared = MPI_Wtime();
  const model::IntegratorOptions& stepping = system.model().dynamic_options.integrator;
  if (!stepping.adaptive) integrator->prepare(stepping.dt);
  if (rank == 0) {
    std::printf(
        "modal model: %zu modes (%.3f to %.3f Hz), %zu pantograph DOFs, %zu droppers that may "
        "go slack; %s; static correction %.2f s (%d solves), rest of the build %.2f s\n",
        f.size(), f.front(), f.back(), n_pantograph_dofs, n_droppers, source.how.c_str(),
        report.correction_seconds, report.correction_solves,
        report.seconds - report.correction_seconds + (MPI_Wtime() - prepared));
    std::fflush(stdout);
  }
  return integrator;
}

}  // namespace catena::app
