#include "overrides.hpp"

#include <cstdint>
#include <optional>

#include "catena/core/error.hpp"

namespace catena::model::detail {
namespace {

// One step of an override path: a map key or a list index.
struct PathStep {
  std::string key;  // empty for an index step
  std::size_t index = 0;
  bool is_index = false;
};

const char* const syntax_help =
    "expected 'dotted.path=value', e.g. --set output.file=run.h5 or "
    "--set lines[0].elements=200";

// Reports a malformed override; `path` is the part of the path reached so far.
class OverrideError {
 public:
  OverrideError(const std::string& file_label, const std::string& text)
      : file_label_(file_label), text_(text) {}
  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    throw InputError(InputLocation{file_label_, 0, path},
                     "invalid --set '" + text_ + "': " + problem);
  }

 private:
  const std::string& file_label_;
  const std::string& text_;
};

std::vector<PathStep> parse_path(const std::string& path, const OverrideError& error) {
  std::vector<PathStep> steps;
  std::size_t i = 0;
  bool expect_key = true;  // at the start and after '.'
  while (i < path.size()) {
    if (path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos) error.fail("", "unclosed '[' in path '" + path + "'");
      const std::string digits = path.substr(i + 1, close - i - 1);
      const std::optional<std::int64_t> index = parse_integer(digits);
      if (!index || *index < 0 || digits.front() == '+')
        error.fail("", "list index '" + digits + "' is not an integer >= 0");
      steps.push_back(PathStep{"", static_cast<std::size_t>(*index), true});
      i = close + 1;
      expect_key = false;
    } else if (path[i] == '.') {
      if (expect_key) error.fail("", "empty key in path '" + path + "'; " + syntax_help);
      expect_key = true;
      ++i;
    } else {
      if (!expect_key) error.fail("", "expected '.' or '[' after ']' in path '" + path + "'");
      const std::size_t end = path.find_first_of(".[]", i);
      const std::size_t stop = end == std::string::npos ? path.size() : end;
      if (stop == i) error.fail("", "unexpected ']' in path '" + path + "'");
      steps.push_back(PathStep{path.substr(i, stop - i), 0, false});
      i = stop;
      expect_key = false;
    }
  }
  if (expect_key) error.fail("", "path '" + path + "' ends with '.'; " + syntax_help);
  return steps;
}

std::string describe_node(const YAML::Node& node) {
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a map";
  if (node.IsScalar()) return "the value '" + node.Scalar() + "'";
  return "empty";
}

// Applies one override. yaml-cpp nodes are handles: `Node::reset` re-points a handle,
// whereas `operator=` would overwrite the node it refers to.
// "path=~": the key is removed, so that its default applies (a key of the scene that a
// changed setting no longer takes, e.g. integrator.alpha when `catena study` varies
// integrator.type). A path that is not there is nothing to remove; a list item is refused
// (the items after it would change their indices).
AppliedOverride remove_key(YAML::Node& root, const std::vector<PathStep>& steps,
                           const std::string& text, const OverrideError& error) {
  YAML::Node current;
  current.reset(root);
  std::string reached;
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const PathStep& step = steps[s];
    if (step.is_index) {
      if (s + 1 == steps.size())
        error.fail(reached, "'~' removes a key; a list item cannot be removed");
      if (!current.IsSequence() || step.index >= current.size())
        return AppliedOverride{reached, text};
      reached = join_index(reached, step.index);
      YAML::Node next = current[step.index];
      current.reset(next);
      continue;
    }
    if (!current.IsMap()) return AppliedOverride{reached, text};
    reached = join_key(reached, step.key);
    if (s + 1 == steps.size()) {
      current.remove(step.key);
      break;
    }
    const YAML::Node& const_current = current;  // const lookup: does not insert the key
    const YAML::Node next = const_current[step.key];
    if (!next.IsDefined()) return AppliedOverride{reached, text};
    current.reset(next);
  }
  return AppliedOverride{reached, text};
}

AppliedOverride apply_one(YAML::Node& root, const std::string& text,
                          const std::string& file_label) {
  const OverrideError error(file_label, text);
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos) error.fail("", std::string("no '=' found; ") + syntax_help);
  const std::string path = text.substr(0, equals);
  if (path.empty()) error.fail("", std::string("empty path; ") + syntax_help);
  const std::vector<PathStep> steps = parse_path(path, error);

  YAML::Node value;
  try {
    value.reset(YAML::Load(text.substr(equals + 1)));
  } catch (const YAML::Exception& e) {
    error.fail(path, "value is not valid YAML (" + e.msg + ")");
  }

  if (text.substr(equals + 1) == "~") return remove_key(root, steps, text, error);

  YAML::Node current;
  current.reset(root);
  std::string reached;  // canonical path of `current`
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const PathStep& step = steps[s];
    const bool last = s + 1 == steps.size();
    const std::string where = reached.empty() ? "the scene" : "'" + reached + "'";
    if (step.is_index) {
      if (!current.IsSequence())
        error.fail(reached, where + " is " + describe_node(current) +
                                ", not a list; it has no item [" + std::to_string(step.index) +
                                "]");
      if (step.index >= current.size())
        error.fail(reached, "index " + std::to_string(step.index) + " out of range: " + where +
                                " has " + std::to_string(current.size()) +
                                (current.size() == 1 ? " item" : " items"));
      reached = join_index(reached, step.index);
      if (last) {
        current[step.index] = value;
      } else {
        YAML::Node next = current[step.index];
        current.reset(next);
      }
      continue;
    }
    if (current.IsSequence())
      error.fail(reached, where + " is a list; index it as " + reached + "[N]");
    if (!current.IsMap())
      error.fail(reached,
                 where + " is " + describe_node(current) + ", it has no key '" + step.key + "'");
    reached = join_key(reached, step.key);
    if (last) {
      current[step.key] = value;
      break;
    }
    const YAML::Node& const_current = current;  // const lookup: does not insert the key
    const YAML::Node existing = const_current[step.key];
    if (!existing.IsDefined() || existing.IsNull())
      current[step.key] = YAML::Node(YAML::NodeType::Map);
    const YAML::Node next = current[step.key];
    current.reset(next);
  }
  return AppliedOverride{reached, text};
}

}  // namespace

std::vector<AppliedOverride> apply_overrides(YAML::Node& root,
                                             const std::vector<std::string>& overrides,
                                             const std::string& file_label) {
  std::vector<AppliedOverride> applied;
  applied.reserve(overrides.size());
  for (const std::string& text : overrides) applied.push_back(apply_one(root, text, file_label));
  return applied;
}

}  // namespace catena::model::detail
