#include "moving_load_reader.hpp"

#include <map>
#include <string>
#include <variant>
#include <vector>

#include "catena/model/path_stations.hpp"
#include "did_you_mean.hpp"
#include "line_path_reader.hpp"
#include "number_format.hpp"
#include "speed_reader.hpp"

namespace catena::model::detail {

void read_moving_loads(const Field& moving_loads, SceneBuild& build) {
  Model& model = build.model;
  if (model.analysis != AnalysisType::dynamic) {
    if (moving_loads.present())
      moving_loads.fail(
          "'moving_loads' apply to analysis.type: dynamic only (this scene is "
          "static); set analysis.type: dynamic with a duration, or remove the key");
    return;
  }
  const std::vector<Field> entries = moving_loads.items();
  if (entries.empty()) return;
  const LineTable lines = named_lines(build);
  std::map<std::string, Field> first_with_name;
  for (const Field& entry : entries) {
    entry.expect_map("a moving load {name, line, force, speed, start, start_time}");
    entry.check_keys({"name", "line", "force", "speed", "speed_kmh", "start", "start_time"});
    MovingLoad load;
    const Field name = entry.child("name");
    load.name = name.text();
    const auto [first, inserted] = first_with_name.emplace(load.name, name);
    if (!inserted)
      name.fail("duplicate moving load name '" + load.name + "' (first used at " +
                first->second.path() + ", line " + std::to_string(first->second.location().line) +
                "); moving load names must be unique");
    load.elements = read_path(entry.child("line"), lines, model, "moving loads");
    load.force = entry.child("force").vec3(RealRange::any("N"));
    load.speed = read_speed(entry);
    const double length = path_stations(model, load.elements).length();
    load.start =
        entry.child("start").real_or(0.0, RealRange::between(0.0, true, length, true, "m"));
    load.start_time = entry.child("start_time")
                          .real_or(0.0, RealRange::between(
                                            0.0, true, model.dynamic_options.duration, false, "s"));
    model.moving_loads.push_back(std::move(load));
  }
}

}  // namespace catena::model::detail
