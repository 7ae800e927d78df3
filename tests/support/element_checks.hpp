#pragma once
// Generic checks of an element kernel against central finite differences.
#include <vector>

#include "catena/elements/element.hpp"

namespace catena::test {

struct JacobianCheck {
  double stiffness = 0.0;  // relative max difference of K vs FD of f in q
  double damping = 0.0;    // relative max difference of C vs FD of f in v
};

// f evaluated at (q, v, load_factor).
std::vector<double> element_force(const elements::Element& e, const std::vector<double>& q,
                                  const std::vector<double>& v, elements::LoadPath path);

JacobianCheck check_element_jacobians(const elements::Element& e, const std::vector<double>& q,
                                      const std::vector<double>& v, elements::LoadPath path,
                                      double h = 1e-6);

// The same with the prestrain in place and the loads scaled by `load_factor`.
inline std::vector<double> element_force(const elements::Element& e, const std::vector<double>& q,
                                         const std::vector<double>& v, double load_factor) {
  return element_force(e, q, v, elements::LoadPath(load_factor));
}
inline JacobianCheck check_element_jacobians(const elements::Element& e,
                                             const std::vector<double>& q,
                                             const std::vector<double>& v, double load_factor,
                                             double h = 1e-6) {
  return check_element_jacobians(e, q, v, elements::LoadPath(load_factor), h);
}

}  // namespace catena::test
