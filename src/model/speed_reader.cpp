#include "speed_reader.hpp"

namespace catena::model::detail {
namespace {

constexpr double kMetresPerSecondPerKmh = 1.0 / 3.6;

}  // namespace

double read_speed(const Field& entry) {
  const Field speed = entry.child("speed"), speed_kmh = entry.child("speed_kmh");
  if (speed.present() && speed_kmh.present())
    speed_kmh.fail("both 'speed' (" + speed.value_text() + " m/s) and 'speed_kmh' (" +
                   speed_kmh.value_text() + " km/h) are given; expected exactly one of them");
  if (!speed.present() && !speed_kmh.present())
    entry.fail(
        "missing required key 'speed' (m/s, a finite number >= 0); or give 'speed_kmh' "
        "(km/h) instead");
  if (speed.present()) return speed.real(RealRange::non_negative("m/s"));
  return speed_kmh.real(RealRange::non_negative("km/h")) * kMetresPerSecondPerKmh;
}

double read_path_velocity(const Field& entry) {
  const double speed = read_speed(entry);
  const Field direction = entry.child("direction");
  const std::string text = direction.text_or("forward");
  if (text == "forward") return speed;
  if (text == "backward") return -speed;
  direction.fail("unknown direction '" + text +
                 "'; accepted: forward (toward increasing arc length along the path, the "
                 "default) or backward");
}

}  // namespace catena::model::detail
