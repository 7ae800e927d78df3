#include "fd_jacobian.hpp"

#include <algorithm>
#include <cmath>

namespace catena::test {

std::vector<double> central_difference_jacobian(
    const std::function<void(const std::vector<double>&, std::vector<double>&)>& fn,
    const std::vector<double>& x, int n_out, double h) {
  const int m = static_cast<int>(x.size());
  std::vector<double> jac(static_cast<size_t>(n_out) * m);
  std::vector<double> xp = x, fp(n_out), fm(n_out);
  for (int j = 0; j < m; ++j) {
    const double step = h * std::max(1.0, std::abs(x[j]));
    xp[j] = x[j] + step;
    fn(xp, fp);
    xp[j] = x[j] - step;
    fn(xp, fm);
    xp[j] = x[j];
    for (int i = 0; i < n_out; ++i)
      jac[static_cast<size_t>(i) * m + j] = (fp[i] - fm[i]) / (2 * step);
  }
  return jac;
}

double relative_max_difference(const std::vector<double>& a, const std::vector<double>& b,
                               double floor) {
  double scale = floor, diff = 0.0;
  for (size_t i = 0; i < b.size(); ++i) {
    scale = std::max(scale, std::abs(b[i]));
    diff = std::max(diff, std::abs(a[i] - b[i]));
  }
  return diff / scale;
}

}  // namespace catena::test
