#pragma once
// This rank's share of a static solution, in the form the HDF5 writer consumes. Every
// node and element is written by exactly one rank (its owner); the union over ranks is
// complete. Arrays are flat, row-major, in the order of owned_nodes / owned_elements.
#include <string>
#include <vector>

namespace catena::io {

struct StaticResult {
  std::vector<int> owned_nodes;   // node indices (into Model::nodes), ascending
  std::vector<double> positions;  // 3 per owned node, m
  std::vector<double> slopes;     // 3 per owned node: ∂r/∂x (−); zeros where a node has none

  std::vector<int> owned_elements;   // element indices (into Model::elements), ascending
  std::vector<double> axial_force;   // 1 per owned element, N (tension positive), mid-point
  std::vector<double> axial_strain;  // 1 per owned element, −
  // Section resultants at the mid-point (elements::SectionResult): 3, 3 and 1 per owned
  // element, global frame; zero for elements without bending.
  std::vector<double> shear_force;     // N
  std::vector<double> bending_moment;  // N·m
  std::vector<double> torsion;         // N·m

  std::vector<int> support_nodes;       // owned nodes with fixed DOFs, elastic supports or surfaces
  std::vector<double> reaction_force;   // 3 per support node, N (force of support on node)
  std::vector<double> reaction_moment;  // 3 per support node, N·m (from fixed slope DOFs)

  double load_factor = 1.0;  // reached load level (1 = full load)
  int n_load_steps = 0;
  int n_newton_iterations = 0;
  double residual_norm = 0.0;
};

// Facts about the run stored as file attributes.
struct RunInfo {
  std::string code_version;
  std::string command_line;
  std::string petsc_options;
  std::string run_id;  // dynamic runs: pairs the output with its checkpoint (run_files.hpp)
  int n_ranks = 1;
  int n_dofs = 0;
};

}  // namespace catena::io
