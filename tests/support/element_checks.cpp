#include "element_checks.hpp"

#include "fd_jacobian.hpp"

namespace catena::test {

std::vector<double> element_force(const elements::Element& e, const std::vector<double>& q,
                                  const std::vector<double>& v, elements::LoadPath path) {
  std::vector<double> f(e.n_dofs());
  elements::LocalState s{q, v, path};
  e.evaluate(s, {true, false, false}, {f.data(), nullptr, nullptr});
  return f;
}

JacobianCheck check_element_jacobians(const elements::Element& e, const std::vector<double>& q,
                                      const std::vector<double>& v, elements::LoadPath path,
                                      double h) {
  const int n = e.n_dofs();
  std::vector<double> f(n), K(n * n), C(n * n);
  e.evaluate({q, v, path}, {true, true, true}, {f.data(), K.data(), C.data()});
  const auto K_fd = central_difference_jacobian(
      [&](const std::vector<double>& x, std::vector<double>& out) {
        out = element_force(e, x, v, path);
      },
      q, n, h);
  const auto C_fd = central_difference_jacobian(
      [&](const std::vector<double>& x, std::vector<double>& out) {
        out = element_force(e, q, x, path);
      },
      v, n, h);
  return {relative_max_difference(K, K_fd), relative_max_difference(C, C_fd)};
}

}  // namespace catena::test
