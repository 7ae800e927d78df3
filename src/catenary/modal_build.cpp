#include "catena/catenary/modal_build.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <variant>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/state_view.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/modes/modal_analysis.hpp"
#include "modal_static_correction.hpp"

namespace catena::catenary {
namespace {

using solvers::ModalModel;

// The nodes of each pantograph: those reached from its head through elements, springs to
// ground and all (the contact is not an element, so the wire is not reached).
std::set<int> pantograph_nodes(const model::Model& m) {
  std::vector<std::vector<int>> neighbours(m.nodes.size());
  for (const model::ElementDesc& e : m.elements)
    for (int a : e.nodes)
      for (int b : e.nodes)
        if (a != b) neighbours[static_cast<std::size_t>(a)].push_back(b);
  std::set<int> found;
  std::vector<int> todo;
  for (const model::MovingContact& c : m.contacts) todo.push_back(c.head_node);
  while (!todo.empty()) {
    const int n = todo.back();
    todo.pop_back();
    if (!found.insert(n).second) continue;
    for (int k : neighbours[static_cast<std::size_t>(n)]) todo.push_back(k);
  }
  for (const model::MovingContact& c : m.contacts)
    for (int e : m.paths[static_cast<std::size_t>(c.path)].elements)
      for (int n : m.elements[static_cast<std::size_t>(e)].nodes)
        if (found.count(n))
          throw InputError({m.source_file, 0, "pantographs"},
                           "pantograph '" + c.name +
                               "' is joined to its wire by an element: the modal model keeps "
                               "the pantographs out of the catenary's modes, so they may touch "
                               "the wire only through the contact");
  return found;
}

// Nodal positions and slopes (3 + 3 per node, in `nodes` order) of a state or a change of
// state, on every rank.
std::vector<double> node_values(const assembly::StateView& view, const assembly::DofMap& dofs,
                                Vec x, bool change, const std::map<int, std::size_t>& slot,
                                MPI_Comm comm) {
  std::vector<double> positions, slopes;
  if (change)
    view.owned_node_changes(x, positions, slopes);
  else
    view.owned_node_values(x, positions, slopes);
  std::vector<double> out(6 * slot.size(), 0.0);
  const std::vector<int>& owned = dofs.owned_nodes();
  for (std::size_t k = 0; k < owned.size(); ++k) {
    const auto it = slot.find(owned[k]);
    if (it == slot.end()) continue;
    for (int d = 0; d < 3; ++d) {
      out[6 * it->second + static_cast<std::size_t>(d)] =
          positions[3 * k + static_cast<std::size_t>(d)];
      out[6 * it->second + 3 + static_cast<std::size_t>(d)] =
          slopes[3 * k + static_cast<std::size_t>(d)];
    }
  }
  if (!out.empty())
    MPI_Allreduce(MPI_IN_PLACE, out.data(), static_cast<int>(out.size()), MPI_DOUBLE, MPI_SUM,
                  comm);
  return out;
}

// Dense block of A over the global indices `dofs` (every rank the whole block).
Eigen::MatrixXd dense_block(Mat A, const std::vector<PetscInt>& dofs, MPI_Comm comm) {
  const auto n = static_cast<Eigen::Index>(dofs.size());
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> block =
      Eigen::MatrixXd::Zero(n, n);
  PetscInt first = 0, end = 0;
  CATENA_PETSC(MatGetOwnershipRange(A, &first, &end));
  for (Eigen::Index i = 0; i < n; ++i) {
    const PetscInt row = dofs[static_cast<std::size_t>(i)];
    if (row < first || row >= end) continue;
    CATENA_PETSC(MatGetValues(A, 1, &row, static_cast<PetscInt>(n), dofs.data(), &block(i, 0)));
  }
  if (n > 0)
    MPI_Allreduce(MPI_IN_PLACE, block.data(), static_cast<int>(n * n), MPI_DOUBLE, MPI_SUM, comm);
  return block;
}

Eigen::VectorXd vector_entries(Vec v, const std::vector<PetscInt>& dofs, MPI_Comm comm) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(dofs.size()));
  PetscInt first = 0, end = 0;
  CATENA_PETSC(VecGetOwnershipRange(v, &first, &end));
  const double* a = nullptr;
  CATENA_PETSC(VecGetArrayRead(v, &a));
  for (std::size_t k = 0; k < dofs.size(); ++k)
    if (dofs[k] >= first && dofs[k] < end) out(static_cast<Eigen::Index>(k)) = a[dofs[k] - first];
  CATENA_PETSC(VecRestoreArrayRead(v, &a));
  if (out.size() > 0)
    MPI_Allreduce(MPI_IN_PLACE, out.data(), static_cast<int>(out.size()), MPI_DOUBLE, MPI_SUM,
                  comm);
  return out;
}

// The scene's droppers the modal model corrects when they go slack: its tension-only bars.
std::vector<int> tension_only_bars(const model::Model& m) {
  std::vector<int> bars;
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const model::ElementProps& props = *m.elements[e].props;
    if (const auto* bar = std::get_if<model::BarProps>(&props); bar && bar->tension_only)
      bars.push_back(static_cast<int>(e));
    if (const auto* cable = std::get_if<model::CableProps>(&props); cable && cable->tension_only)
      throw InputError({m.source_file, 0, "analysis.structure"},
                       "the modal model corrects slack droppers that are bars; element " +
                           std::to_string(m.elements[e].id) +
                           " is a tension-only cable (catenary.droppers.model: cable): use "
                           "the bar droppers, or analysis.structure: linear or nonlinear");
  }
  return bars;
}

// The load vector Σ_k w_k e_k over the free DOFs of `node`'s position (offset 0) or slope
// (offset: the kind's gradients) along `direction`.
detail::SiteVector site_vector(const assembly::DofMap& dofs, int node, bool slope,
                               const Vec3& direction, double sign, detail::SiteVector out = {}) {
  const model::UnknownKindInfo& kind = model::kind_info(dofs.node_kind(node));
  const int offset = slope ? kind.gradients : kind.position;
  if (offset < 0) return out;
  for (int k = 0; k < 3; ++k)
    if (const PetscInt g = dofs.global_dof(node, offset + k); g >= 0) {
      out.dofs.push_back(g);
      out.weights.push_back(sign * direction[k] * dofs.coefficient(node, offset + k));
    }
  return out;
}

}  // namespace

ModalStructure modal_structure(assembly::SecondOrderSystem& system, Vec q0) {
  const model::Model& m = system.model();
  if (system.has_constraints())
    throw InputError({m.source_file, 0, "analysis.structure"},
                     "the modal model needs a structure without constraints (Lagrange "
                     "multipliers); hold nodes with supports, or use analysis.structure: "
                     "linear or nonlinear");
  if (!m.moving_loads.empty())
    throw InputError({m.source_file, 0, "analysis.structure"},
                     "the modal model couples pantographs, not moving loads; use "
                     "analysis.structure: linear or nonlinear with moving_loads");
  const assembly::DofMap& dofs = system.dof_map();
  ModalStructure out{system.structure_matrices(q0), {}, {}};
  // The pantographs' DOFs, and the catenary's: every other owned free DOF.
  for (int n : pantograph_nodes(m))
    for (int k = 0; k < dofs.node_dofs(n); ++k)
      if (const PetscInt g = dofs.global_dof(n, k); g >= 0) out.pantograph_dofs.push_back(g);
  std::sort(out.pantograph_dofs.begin(), out.pantograph_dofs.end());
  const std::set<PetscInt> held(out.pantograph_dofs.begin(), out.pantograph_dofs.end());
  for (PetscInt g = dofs.first_owned(); g < dofs.first_owned() + dofs.n_owned(); ++g)
    if (!held.count(g)) out.catenary_dofs.push_back(g);
  return out;
}

ModalModel build_modal_model(assembly::SecondOrderSystem& system, Vec q0, ModalStructure structure,
                             solvers::Modes modes, double cutoff, ModalBuildReport* report) {
  const double start = MPI_Wtime();
  const model::Model& m = system.model();
  MPI_Comm comm = system.comm();
  const assembly::DofMap& dofs = system.dof_map();
  const std::vector<int> bars = tension_only_bars(m);
  assembly::SecondOrderSystem::StructureMatrices& S = structure.matrices;

  ModalModel out;
  out.cutoff_hz = cutoff;
  out.pantograph_dofs = std::move(structure.pantograph_dofs);
  CATENA_PETSC(VecDuplicate(q0, out.q0.out()));
  CATENA_PETSC(VecCopy(q0, out.q0.get()));

  // Per mode: ω, ζ = φᵀ C φ / 2ω, the constant load −φᵀ f0.
  const auto n = static_cast<PetscInt>(modes.shape.size());
  std::vector<Vec> shapes;
  for (const VecHandle& s : modes.shape) shapes.push_back(s.get());
  solvers::ModalDynamics& d = out.dynamics;
  d.constant_load.assign(static_cast<std::size_t>(n), 0.0);
  CATENA_PETSC(VecMDot(S.f0.get(), n, shapes.data(), d.constant_load.data()));
  for (double& p : d.constant_load) p = -p;
  VecHandle Cphi;
  CATENA_PETSC(VecDuplicate(q0, Cphi.out()));
  for (PetscInt i = 0; i < n; ++i) {
    const double omega = 2.0 * M_PI * modes.frequency[static_cast<std::size_t>(i)];
    CATENA_PETSC(MatMult(S.C.get(), shapes[static_cast<std::size_t>(i)], Cphi.get()));
    PetscScalar c = 0.0;
    CATENA_PETSC(VecDot(Cphi.get(), shapes[static_cast<std::size_t>(i)], &c));
    d.omega.push_back(omega);
    d.zeta.push_back(c / (2.0 * omega));
  }
  d.Mp = dense_block(S.M.get(), out.pantograph_dofs, comm);
  d.Cp = dense_block(S.C.get(), out.pantograph_dofs, comm);
  d.Kp = dense_block(S.K.get(), out.pantograph_dofs, comm);
  d.f0p = vector_entries(S.f0.get(), out.pantograph_dofs, comm);

  // Sites: the nodes of the contacts' paths and of the droppers, one slot each.
  std::map<int, std::size_t> slot;
  const auto add_node = [&](int node) { slot.emplace(node, slot.size()); };
  for (const model::MovingContact& c : m.contacts) {
    add_node(c.head_node);
    for (int e : m.paths[static_cast<std::size_t>(c.path)].elements)
      for (int node : m.elements[static_cast<std::size_t>(e)].nodes) add_node(node);
  }
  for (int e : bars)
    for (int node : m.elements[static_cast<std::size_t>(e)].nodes) add_node(node);
  const assembly::StateView view(system);
  const std::vector<double> reference = node_values(view, dofs, q0, false, slot, comm);
  std::vector<std::vector<double>> shape_rows;  // per mode: node_values of its shape
  for (Vec s : shapes) shape_rows.push_back(node_values(view, dofs, s, true, slot, comm));

  std::vector<detail::ContactSites> contact_sites;
  for (const model::MovingContact& c : m.contacts) {
    solvers::ModalContact k;
    k.name = c.name;
    const std::vector<int>& path = m.paths[static_cast<std::size_t>(c.path)].elements;
    k.stations = model::path_stations(m, path);
    std::map<int, int> path_node;  // node → its index among this path's nodes
    for (int e : path)
      for (int node : m.elements[static_cast<std::size_t>(e)].nodes)
        path_node.emplace(node, static_cast<int>(path_node.size()));
    for (int e : path) {
      k.node_a.push_back(path_node.at(m.elements[static_cast<std::size_t>(e)].nodes.front()));
      k.node_b.push_back(path_node.at(m.elements[static_cast<std::size_t>(e)].nodes.back()));
    }
    k.rows.assign(2 * path_node.size() * static_cast<std::size_t>(n), 0.0);
    k.reference.assign(2 * path_node.size(), 0.0);
    const auto up_dot = [&](const std::vector<double>& values, std::size_t at) {
      return c.up[0] * values[at] + c.up[1] * values[at + 1] + c.up[2] * values[at + 2];
    };
    detail::ContactSites sites;
    sites.node_sites.resize(2 * path_node.size());
    for (const auto& [node, index] : path_node) {
      sites.node_sites[2 * static_cast<std::size_t>(index)] =
          site_vector(dofs, node, false, c.up, 1.0);
      sites.node_sites[2 * static_cast<std::size_t>(index) + 1] =
          site_vector(dofs, node, true, c.up, 1.0);
      const std::size_t base = 6 * slot.at(node);
      const auto row = static_cast<std::size_t>(index);
      k.reference[2 * row] = up_dot(reference, base);
      k.reference[2 * row + 1] = up_dot(reference, base + 3);
      for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
        k.rows[2 * row * static_cast<std::size_t>(n) + i] = up_dot(shape_rows[i], base);
        k.rows[(2 * row + 1) * static_cast<std::size_t>(n) + i] = up_dot(shape_rows[i], base + 3);
      }
    }
    k.stiffness = c.stiffness;
    k.damping = c.damping;
    k.speed = c.speed;
    k.start = c.start;
    k.head = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(out.pantograph_dofs.size()));
    for (int j = 0; j < 3; ++j) {
      const PetscInt g = dofs.global_dof(c.head_node, j);
      if (g < 0) continue;
      const auto at = std::lower_bound(out.pantograph_dofs.begin(), out.pantograph_dofs.end(), g);
      k.head(at - out.pantograph_dofs.begin()) = c.up[j] * dofs.coefficient(c.head_node, j);
    }
    k.head_reference = up_dot(reference, 6 * slot.at(c.head_node));
    d.contacts.push_back(std::move(k));
    contact_sites.push_back(std::move(sites));
  }

  std::vector<detail::SiteVector> dropper_sites;
  for (int e : bars) {
    const model::ElementDesc& el = m.elements[static_cast<std::size_t>(e)];
    const auto& bar = std::get<model::BarProps>(*el.props);
    const std::size_t a = 6 * slot.at(el.nodes.front()), b = 6 * slot.at(el.nodes.back());
    Vec3 chord;
    for (int j = 0; j < 3; ++j)
      chord[j] =
          reference[b + static_cast<std::size_t>(j)] - reference[a + static_cast<std::size_t>(j)];
    const double length = chord.norm();
    const double l0 = bar.unstretched_length > 0.0
                          ? bar.unstretched_length
                          : (m.nodes[static_cast<std::size_t>(el.nodes.back())].position -
                             m.nodes[static_cast<std::size_t>(el.nodes.front())].position)
                                .norm();
    solvers::ModalDropper dr;
    dr.stiffness = bar.EA / l0;
    dr.tension = bar.EA * (length / l0 - 1.0);
    dr.damping = bar.damping;
    dr.in_modes = length >= l0;  // TensionBar: slack (no force, no stiffness) when l < l0
    const Vec3 dir = chord / length;
    for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
      double s = 0.0;
      for (int j = 0; j < 3; ++j)
        s += dir[j] * (shape_rows[i][b + static_cast<std::size_t>(j)] -
                       shape_rows[i][a + static_cast<std::size_t>(j)]);
      dr.elongation.push_back(s);
    }
    d.droppers.push_back(std::move(dr));
    dropper_sites.push_back(site_vector(dofs, el.nodes.back(), false, dir, 1.0,
                                        site_vector(dofs, el.nodes.front(), false, dir, -1.0)));
  }
  // Every mode's values at every site node (220 MB on EN 50318) are in the sites now.
  std::vector<std::vector<double>>().swap(shape_rows);
  const double correction_start = MPI_Wtime();
  const int solves = detail::add_static_correction(S.K.get(), S.f0.get(), out.pantograph_dofs,
                                                   contact_sites, dropper_sites, out);

  out.frequency_hz = modes.frequency;
  PetscInt n_local = 0;
  CATENA_PETSC(VecGetLocalSize(q0, &n_local));
  out.shapes = solvers::SinglePrecisionRows(n_local, n);
  for (PetscInt i = 0; i < n; ++i) {
    VecHandle& shape = modes.shape[static_cast<std::size_t>(i)];
    const double* a = nullptr;
    CATENA_PETSC(VecGetArrayRead(shape.get(), &a));
    out.shapes.set_column(i, a);
    CATENA_PETSC(VecRestoreArrayRead(shape.get(), &a));
    shape = VecHandle();  // freed as it is copied: the shapes are not held twice
  }
  out.M = std::move(S.M);
  if (report) {
    report->seconds = MPI_Wtime() - start;
    report->correction_seconds = MPI_Wtime() - correction_start;
    report->correction_solves = solves;
  }
  return out;
}

}  // namespace catena::catenary
