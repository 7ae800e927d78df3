#pragma once
// Whether the time step resolves a contact force, measured from the force itself.
//
// Over the accepted steps k, the second difference d_k = F_{k+1} − 2 F_k + F_{k−1} against
// the force's own spread: the roughness r = rms(d) / std(F). A sine of angular frequency ω
// stepped every h has r = 4 sin²(ωh/2) ≈ (ωh)², so r measures how many steps a period of
// the force's content gets: r = 0.5 is 8.7 steps per period, r ≈ 2–4 a force that jumps
// from step to step (a period of two steps gives 4).
//
// Measured (docs/accuracy.md, "Where each method stops working"): resolved runs stay far
// below the limit — EN 50318 at 300 km/h with HHT at 0.25–1 ms, the linear and modal
// models: r ≤ 0.04; Radau IIA s = 3 at 2 and 4 ms: 0.14 and 0.42, with σ within 0.06 % of
// the reference — while the contact spring's own mode left unresolved chatters: EN 50318
// at 250 km/h with a contact stiffness of 5·10⁶ N/m (100 times EN 50318's) under HHT at
// dt 0.5 ms gives r = 0.85 (CTest extremes_en50318_contact_x100 checks the warning).
// Above kUnresolved the force statistics are the step's, not the structure's.
//
// Not collective: plain numbers.
#include <cstddef>

namespace catena::post {

class ContactResolution {
 public:
  static constexpr double kUnresolved = 0.5;

  // The contact force after the next accepted step, N.
  void add(double force);

  std::size_t steps() const { return n_; }
  // rms second difference / standard deviation; 0 until three steps and a spread > 0.
  double roughness() const;
  bool unresolved() const { return roughness() > kUnresolved; }

 private:
  std::size_t n_ = 0;
  double mean_ = 0.0, m2_ = 0.0;  // Welford's running mean and sum of squared deviations
  double previous_ = 0.0, before_ = 0.0;
  double d2_sum_ = 0.0;  // Σ d_k²
};

}  // namespace catena::post
