#pragma once
// The modal model's static correction (solvers/modal/modal_model.hpp, "Static correction"):
// R = K⁻¹ − Σ φ φᵀ/ω² between the sites, from one factorisation of the catenary's
// stiffness and a solve per site, in blocks of right-hand sides (catenary/modal_build.cpp
// builds the sites).
#include <petscmat.h>

#include <vector>

#include "catena/solvers/modal/modal_model.hpp"

namespace catena::catenary::detail {

// A site as a load vector over the free DOFs: Σ weight·e_dof (a DOF may repeat).
struct SiteVector {
  std::vector<PetscInt> dofs;
  std::vector<double> weights;
};

// The sites of one contact: two per path node (up·r, up·r_x), in the contact's row order.
struct ContactSites {
  std::vector<SiteVector> node_sites;  // 2 per path node
};

// Collective. K: the structure's stiffness (not changed); f0: its force at q0 (the constant
// load is −f0); `held`: the pantographs' DOFs (out of the catenary). Fills the static
// correction of every contact of `model` and of its droppers (dropper_sites: one per
// dropper, its elongation). Returns the number of solves.
int add_static_correction(Mat K, Vec f0, const std::vector<PetscInt>& held,
                          const std::vector<ContactSites>& contact_sites,
                          const std::vector<SiteVector>& dropper_sites, solvers::ModalModel& model);

}  // namespace catena::catenary::detail
