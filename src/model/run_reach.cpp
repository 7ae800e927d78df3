#include "run_reach.hpp"

#include <algorithm>

#include "catenary_builder.hpp"
#include "number_format.hpp"
#include "speed_reader.hpp"

namespace catena::model::detail {

RunReach read_run_reach(const Field& scene, const Field& why) {
  const Field analysis = scene.child("analysis");
  const std::string type = analysis.child("type").text_or("static");
  if (type != "dynamic")
    why.fail(
        "'auto' sizes the line to a dynamic run (the distance the pantographs travel in "
        "analysis.duration); this scene's analysis is '" +
        type + "'. Give the span count (an integer) instead");
  RunReach reach;
  reach.duration = analysis.child("duration").real(RealRange::positive("s"));
  bool any = false;
  for (const Field& entry : scene.child("pantographs").items()) {
    if (!entry.is_map() || entry.child("path").text_or("") != kContactWirePath) continue;
    const double v = read_path_velocity(entry);
    const double start = entry.child("start").real_or(0.0, RealRange::any("m"));
    const double farthest = std::max(start, start + v * reach.duration);
    if (!any || farthest > reach.farthest) {
      reach.farthest = farthest;
      reach.pantograph = entry.child("name").text_or("");
    }
    any = true;
  }
  if (!any)
    why.fail(
        "'auto' sizes the line to the distance the pantographs travel, but no pantograph "
        "runs on the contact wire (pantographs: [{path: contact_wire, ...}]). Give the "
        "span count (an integer) instead");
  if (reach.farthest <= 0.0)
    why.fail("'auto': the pantographs never reach the contact wire (farthest point " +
             format_number(reach.farthest) + " m); give the span count instead");
  return reach;
}

}  // namespace catena::model::detail
