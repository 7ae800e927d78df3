#pragma once
// How often a pantograph lost contact and struck the wire again, counted from the contact
// force after each accepted step (zero while the head is off the wire).
//
// Why count them: a strike is an impact far shorter and sharper than the contact spring's
// own mode, and where a run has many of them how much contact is lost depends on the step
// and the method far more than the filtered force does. Measured on a single wire with 100
// times EN 50318's contact stiffness (meshes/pantograph_wire.yaml, contact.stiffness 5·10⁶
// N/m, 1.5 s; docs/accuracy.md, "Repeated strikes"): Radau IIA s = 3 gives 81 strikes and
// 2.27 % loss of contact at dt 0.1 and 0.05 ms alike, while at 0.05 ms HHT gives 44 and
// 1.07 %, BDF-2 20 and 0.93 %, Park 78 and 2.33 % — with the 20 Hz σ within 1 % of Radau's
// for all of them and no roughness warning. No property of one run tells which count is
// right; a run at another step or with another method does (catena study, --error-bar). So
// a run with kRepeated strikes or more says so. A head that leaves the wire once and comes
// back once (past the wire's wave speed: one loss, at most one strike, the same for every
// method) is not warned of. Counted over the steps this process ran (a restart counts
// afresh), for penalty contacts (a bilateral contact's force is a multiplier of either sign).
//
// Not collective: plain numbers.
#include <cstddef>

namespace catena::post {

class ContactStrikes {
 public:
  static constexpr std::size_t kRepeated = 3;

  // The contact force after the next accepted step, N.
  void add(double force) {
    const bool off = !(force > 0.0);
    if (started_ && !off_ && off) ++losses_;
    if (off_ && !off && losses_ > strikes_) ++strikes_;  // a landing after a counted loss
    off_ = off;
    started_ = true;
  }

  // Returns to the wire after a counted loss of contact (a head that starts off the wire,
  // or whose path begins later, lands without one: not a strike).
  std::size_t strikes() const { return strikes_; }
  // Losses of contact (transitions from on the wire to off it).
  std::size_t losses() const { return losses_; }
  bool repeated() const { return strikes_ >= kRepeated; }

 private:
  bool started_ = false, off_ = false;
  std::size_t strikes_ = 0, losses_ = 0;
};

}  // namespace catena::post
