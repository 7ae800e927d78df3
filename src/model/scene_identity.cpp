#include "catena/model/scene_identity.hpp"

#include <yaml-cpp/yaml.h>

#include <optional>
#include <set>

namespace catena::model {
namespace {

void remove_key(YAML::Node root, const char* section, const char* key) {
  if (!root.IsMap()) return;
  YAML::Node s = root[section];
  if (s && s.IsMap() && s[key]) s.remove(key);
}

std::string shown(const YAML::Node& n) {
  if (!n || n.IsNull()) return "nothing";
  YAML::Emitter e;
  e << YAML::Flow << n;
  std::string text = e.c_str();
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return "'" + text + "'";
}

std::string joined(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

// The first difference between two trees, by key path (scene.md's notation: a.b[2].c).
std::optional<std::string> first_difference(const YAML::Node& a, const YAML::Node& b,
                                            const std::string& path) {
  const auto differ = [&] {
    return (path.empty() ? std::string("the scene") : path) + ": " + shown(a) + " here, " +
           shown(b) + " in the checkpoint";
  };
  if (!a || !b || a.Type() != b.Type()) return differ();
  if (a.IsScalar()) {
    if (a.Scalar() != b.Scalar()) return differ();
    return std::nullopt;
  }
  if (a.IsSequence()) {
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
      if (auto d = first_difference(a[i], b[i], path + "[" + std::to_string(i) + "]")) return d;
    if (a.size() != b.size())
      return path + ": " + std::to_string(a.size()) + " entries here, " + std::to_string(b.size()) +
             " in the checkpoint";
    return std::nullopt;
  }
  if (a.IsMap()) {
    std::set<std::string> seen;
    for (const auto& kv : a) {
      const std::string key = kv.first.as<std::string>();
      seen.insert(key);
      if (auto d = first_difference(kv.second, b[key], joined(path, key))) return d;
    }
    for (const auto& kv : b) {
      const std::string key = kv.first.as<std::string>();
      if (!seen.count(key)) return first_difference(a[key], kv.second, joined(path, key));
    }
  }
  return std::nullopt;
}

}  // namespace

std::string scene_identity(const std::string& source_text) {
  YAML::Node root = YAML::Load(source_text);
  remove_key(root, "analysis", "duration");
  for (const char* key : {"file", "flush_wall_seconds", "checkpoint_wall_seconds"})
    remove_key(root, "output", key);
  YAML::Emitter emitter;
  emitter << root;
  return std::string(emitter.c_str()) + "\n";
}

std::string first_identity_difference(const std::string& here, const std::string& there) {
  if (here == there) return "";
  const std::optional<std::string> d = first_difference(YAML::Load(here), YAML::Load(there), "");
  // Equal trees with unequal text (key order, number spelling): say so rather than nothing.
  return d ? *d : "the same keys and values, written differently";
}

}  // namespace catena::model
