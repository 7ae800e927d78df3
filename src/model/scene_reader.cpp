// The scene reader's driver: text → YAML tree → --set overrides → validated Model. Each
// part of the scene is read by its own reader (section_reader, node_reader, ...); this
// file fixes the order, which matters: line ids come after explicit ids, explicit elements
// may name line nodes, supports need the nodes' DOF counts, the free-body check needs
// everything.
#include "catena/model/scene_reader.hpp"

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "analysis_reader.hpp"
#include "attachment_reader.hpp"
#include "body_reader.hpp"
#include "catena/core/error.hpp"
#include "catena/model/node_kinds.hpp"
#include "catenary_reader.hpp"
#include "catenary_window_reader.hpp"
#include "constraint_reader.hpp"
#include "dynamics_reader.hpp"
#include "element_reader.hpp"
#include "free_body_check.hpp"
#include "joint_reader.hpp"
#include "line_generator.hpp"
#include "memory_check.hpp"
#include "moving_load_reader.hpp"
#include "nodal_frames.hpp"
#include "node_reader.hpp"
#include "overrides.hpp"
#include "pantograph_reader.hpp"
#include "scene_build.hpp"
#include "section_reader.hpp"
#include "slider_reader.hpp"
#include "surface_reader.hpp"

namespace catena::model {
namespace {

using detail::Field;

const std::vector<std::string>& top_level_keys() {
  static const std::vector<std::string> keys{
      "name",     "gravity",          "sections", "nodes",         "lines",       "elements",
      "supports", "elastic_supports", "loads",    "masses",        "constraints", "moving_loads",
      "bodies",   "sliders",          "joints",   "analysis",      "integrator",  "output",
      "catenary", "pantographs",      "surfaces", "absorbing_ends"};
  return keys;
}

// One YAML document whose root is a map; yaml-cpp's exceptions become InputErrors.
YAML::Node load_document(const std::string& text, const std::string& file_label) {
  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(text);
  } catch (const YAML::Exception& e) {
    const int line = e.mark.is_null() ? 0 : e.mark.line + 1;
    throw InputError(InputLocation{file_label, line, ""}, "YAML syntax error: " + e.msg);
  }
  if (documents.empty() || documents.front().IsNull())
    throw InputError(InputLocation{file_label, 0, ""},
                     "scene is empty (no keys); see docs/scene.md");
  if (documents.size() > 1)
    throw InputError(InputLocation{file_label, 0, ""},
                     "the text holds " + std::to_string(documents.size()) +
                         " YAML documents (separated by '---'); a scene is one document");
  const YAML::Node& root = documents.front();
  if (!root.IsMap()) {
    const int line = root.Mark().is_null() ? 0 : root.Mark().line + 1;
    throw InputError(InputLocation{file_label, line, ""},
                     "a scene is a map of keys (name, sections, nodes, lines, ...), got " +
                         std::string(root.IsSequence() ? "a list" : "a single value"));
  }
  return root;
}

// Reads every part of the scene into build.model, in the order the parts depend on.
void read_model(const Field& scene, detail::SceneBuild& build, const MemoryBudget& budget) {
  scene.check_keys(top_level_keys());
  Model& model = build.model;
  model.name = scene.child("name").text_or("");
  model.gravity = scene.child("gravity").vec3_or(model.gravity, detail::RealRange::any("m/s^2"));

  const detail::SectionTable sections = detail::read_sections(scene.child("sections"));
  detail::read_nodes(scene.child("nodes"), build);
  std::vector<detail::PendingElement> explicit_elements =
      detail::read_elements(scene.child("elements"), sections);
  detail::check_lines_fit(scene.child("lines"), sections, build, budget);  // before building
  detail::generate_lines(scene.child("lines"), sections, build,
                         detail::max_element_id(explicit_elements));
  detail::add_explicit_elements(std::move(explicit_elements), build);
  detail::read_catenary(scene.child("catenary"), scene, build, budget);
  if (model.nodes.empty())
    scene.child("nodes").fail(
        "the scene defines no nodes; add 'nodes' (and 'lines' or "
        "'elements' between them), see docs/scene.md");

  detail::check_element_lengths(build);
  detail::assign_nodal_frames(build);
  detail::read_bodies(scene.child("bodies"), build);
  detail::read_sliders(scene.child("sliders"), build);
  detail::read_supports(scene.child("supports"), node_kinds(model), build);
  detail::read_elastic_supports(scene.child("elastic_supports"), build);
  detail::read_constraints(scene.child("constraints"), build);
  detail::add_body_frame_constraints(scene.child("bodies"), build);
  detail::add_slider_constraints(build);
  detail::read_joints(scene.child("joints"), build);
  detail::read_absorbing_ends(scene.child("absorbing_ends"), build);
  detail::read_loads(scene.child("loads"), build);
  detail::read_masses(scene.child("masses"), build);
  detail::read_surfaces(scene.child("surfaces"), build);
  detail::check_sliders_carried(scene.child("sliders"), build);
  model.analysis = detail::read_analysis(scene.child("analysis"), model.static_options);
  detail::read_output(scene.child("output"), model.output);
  detail::read_dynamics(scene, model);
  detail::read_moving_loads(scene.child("moving_loads"), build);
  detail::read_pantographs(scene.child("pantographs"), build);
  detail::check_window_scene(scene, model);
  detail::check_no_free_body(build);
  detail::check_model_fits(scene, build, budget);
}

// The text stored with the results: the file itself, or, with overrides, the tree after
// them re-emitted (comments are lost) so that the stored scene reproduces the run alone.
std::string source_text_after(const std::string& text, const std::string& file_label,
                              const YAML::Node& root, const std::vector<std::string>& overrides) {
  if (overrides.empty()) return text;
  std::string header = "Scene " + file_label + " with command-line overrides:";
  for (const std::string& o : overrides) header += "\n  --set " + o;
  header += "\nRe-emitted by Catena: the original's comments are not kept.";
  YAML::Emitter emitter;
  emitter << YAML::Comment(header) << YAML::Newline << root;
  return std::string(emitter.c_str()) + "\n";
}

// The model's vectors grew by push_back to up to twice their size, and every rank keeps
// the model for the whole run: give back the spare capacity (on the 10 km benchmark line,
// 25 536 unused element slots, about 5 MiB a rank).
void release_spare_capacity(Model& model) {
  model.nodes.shrink_to_fit();
  model.elements.shrink_to_fit();
  for (ElementPath& path : model.paths) path.elements.shrink_to_fit();
}

}  // namespace

Model parse_scene(const std::string& text, const std::string& file_label,
                  const std::vector<std::string>& overrides, const MemoryBudget& budget) {
  check_scene_text(text, file_label);
  YAML::Node root = load_document(text, file_label);
  const detail::SceneSource source{file_label,
                                   detail::apply_overrides(root, overrides, file_label)};
  detail::SceneBuild build(source);
  read_model(Field::root(source, root), build, budget);
  build.model.source_file = file_label;
  build.model.source_text = source_text_after(text, file_label, root, overrides);
  release_spare_capacity(build.model);
  return std::move(build.model);
}

namespace {

// YAML takes CR LF, CR and LF as line breaks (YAML 1.2, section 5.4); yaml-cpp reads the
// first and last only, and a file saved with CR alone (classic Mac OS) failed as "illegal
// map value" at line 1. A CR not followed by LF becomes LF.
std::string with_line_feeds(std::string text) {
  for (std::size_t k = 0; k < text.size(); ++k)
    if (text[k] == '\r' && (k + 1 == text.size() || text[k + 1] != '\n')) text[k] = '\n';
  return text;
}

}  // namespace

std::string read_scene_file(const std::string& path) {
  namespace fs = std::filesystem;
  const auto fail = [&](const std::string& message) {
    throw InputError(InputLocation{path, 0, ""}, message);
  };
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) fail("cannot read scene: no such file");
  if (fs::is_directory(status)) fail("cannot read scene: this is a directory, not a file");
  if (!fs::is_regular_file(status))
    fail(
        "cannot read scene: not a regular file (a device, a pipe or a socket); accepted: a "
        "YAML text file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (!ec && size > max_scene_bytes)
    fail("scene file is " + std::to_string(size) + " bytes; at most " +
         std::to_string(max_scene_bytes) + " bytes (64 MiB) are accepted");

  std::ifstream in(path, std::ios::binary);
  if (!in) fail("cannot read scene: permission denied or unreadable");
  std::ostringstream contents;
  contents << in.rdbuf();
  if (in.bad()) fail("cannot read scene: read error");
  return with_line_feeds(contents.str());
}

Model read_scene(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_scene(read_scene_file(path), path, overrides);
}

}  // namespace catena::model
