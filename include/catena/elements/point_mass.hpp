#pragma once
// A point mass on a node's position (clamp masses, registration masses) and a constant
// (dead) nodal force. Both scale their loads with the load factor.
//   PointMass:  M = m·I3,  f = −λ·m·g       NodalForce: f = −λ·F
// Units: m [kg], g [m/s²], F [N].
#include "catena/core/vec3.hpp"
#include "catena/elements/element.hpp"

namespace catena::elements {

class PointMass final : public Element {
 public:
  PointMass(double mass, const Vec3& gravity) : mass_(mass), gravity_(gravity) {}
  int n_nodes() const override { return 1; }
  int dofs_per_node() const override { return 3; }
  void evaluate(const LocalState& s, Request r, LocalOutput out) const override;
  bool has_damping() const override { return false; }
  void mass(double* M) const override;
  SectionResult section_result(const LocalState&) const override { return {}; }

 private:
  double mass_;
  Vec3 gravity_;
};

class NodalForce final : public Element {
 public:
  explicit NodalForce(const Vec3& force) : force_(force) {}
  int n_nodes() const override { return 1; }
  int dofs_per_node() const override { return 3; }
  void evaluate(const LocalState& s, Request r, LocalOutput out) const override;
  bool has_damping() const override { return false; }
  void mass(double* M) const override;
  SectionResult section_result(const LocalState&) const override { return {}; }

 private:
  Vec3 force_;
};

}  // namespace catena::elements
