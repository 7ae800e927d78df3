#pragma once
// Typed, located access to the scene's YAML tree. Every accessor either returns a value in
// the documented range or throws catena::InputError naming the file, the 1-based line, the
// dotted key ("lines[0].elements", "sections.cw.EA"), the offending value and what is
// accepted. yaml-cpp alone would throw BadConversion with none of these, so the scene
// reader never calls Node::as<T>() directly.
//
// Strictness, on purpose: a key written with no value is an error (not "use the
// default"); numbers must be plain YAML scalars ('5' in quotes is a string); duplicate
// keys are errors (yaml-cpp silently keeps the first); non-finite numbers are rejected.
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/core/vec3.hpp"
#include "number_format.hpp"

namespace catena::model::detail {

// One applied `--set path=value` override. Values set on the command line have no line in
// the file, so messages about them name the override instead.
struct AppliedOverride {
  std::string path;  // canonical dotted path, e.g. "lines[0].elements"
  std::string text;  // as given, e.g. "lines[0].elements=7"
};

// What every message needs to know about the document being read. Outlives all Fields.
struct SceneSource {
  std::string file_label;
  std::vector<AppliedOverride> overrides;
};

// Accepted interval of a real number (always finite); messages render it, e.g.
// "a finite number > 0 [N] (magnitude at most 1e+12)". The factories without an explicit
// maximum (any, positive, non_negative, greater_than) also bound the magnitude by the
// unit's physical bound (physical_bounds.hpp), so that no value near DBL_MAX gets in.
struct RealRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_inclusive = true;
  bool max_inclusive = true;
  std::string unit;  // SI unit shown in messages; "" = dimensionless
  double max_magnitude = std::numeric_limits<double>::infinity();  // |x| <= this

  static RealRange any(std::string unit);
  static RealRange positive(std::string unit);
  static RealRange non_negative(std::string unit);
  static RealRange greater_than(double min, std::string unit);
  static RealRange between(double min, bool min_inclusive, double max, bool max_inclusive,
                           std::string unit);

  bool contains(double x) const;
  std::string describe() const;
};

// Accepted interval of an integer, e.g. "an integer in [1, 10000000]" or
// "a node id (an integer)".
struct IntRange {
  std::int64_t min = std::numeric_limits<std::int64_t>::min();
  std::int64_t max = std::numeric_limits<std::int64_t>::max();
  std::string meaning;  // what the integer is, e.g. "a node id"; "" = just a number

  static IntRange any(std::string meaning);
  static IntRange between(std::int64_t min, std::int64_t max);

  bool contains(std::int64_t x) const { return x >= min && x <= max; }
  std::string describe() const;
};

// A located view of one value in the tree (or of a key that is absent). Cheap to copy:
// yaml-cpp nodes are shared handles.
class Field {
 public:
  // The document root; `source` must outlive every Field derived from it.
  static Field root(const SceneSource& source, const YAML::Node& node);

  const std::string& path() const { return path_; }
  // The key exists in its map (its value may still be null, which accessors reject).
  bool present() const { return node_.IsDefined(); }
  bool is_map() const { return node_.IsMap(); }
  bool is_list() const { return node_.IsSequence(); }
  bool is_scalar() const { return node_.IsScalar(); }
  const YAML::Node& node() const { return node_; }

  InputLocation location() const;
  // Throws InputError at this field; mentions any --set override involved.
  [[noreturn]] void fail(const std::string& message) const;

  // --- structure -------------------------------------------------------------------------
  // This must be a map (or absent); the child may be absent.
  Field child(std::string_view key) const;
  // Items of a list; an absent key gives no items. Present but not a list: error.
  std::vector<Field> items() const;
  // Entries of a map in document order; keys must be unique scalars. Absent: none.
  std::vector<std::pair<std::string, Field>> entries() const;
  // Rejects keys not in `accepted`, suggesting the closest accepted key.
  void check_keys(const std::vector<std::string>& accepted) const;
  // Errors unless this is a map (`what` names it in the message: "a section").
  void expect_map(std::string_view what) const;

  // --- scalar values (absent or null: "missing required key" / "no value") --------------
  double real(const RealRange& range) const;
  double real_or(double fallback, const RealRange& range) const;
  std::int64_t integer(const IntRange& range) const;
  std::int64_t integer_or(std::int64_t fallback, const IntRange& range) const;
  std::string text() const;  // a non-empty scalar
  std::string text_or(const std::string& fallback) const;
  bool boolean_or(bool fallback) const;  // true | false
  // [x, y, z], each component in `component`.
  Vec3 vec3(const RealRange& component) const;
  Vec3 vec3_or(const Vec3& fallback, const RealRange& component) const;
  // A scalar s (meaning [s, s, s]) or [x, y, z].
  Vec3 scalar_or_vec3(const RealRange& component) const;

  // The value as written, compact and truncated, for messages ("abc", "[1, 2]", "a map").
  std::string value_text() const;

 private:
  Field(const SceneSource* source, YAML::Node node, std::string path, int line);
  Field indexed(std::size_t i, const YAML::Node& item) const;
  // Errors if absent or null; `expected` says what would have been accepted.
  void require_value(const std::string& expected) const;
  std::string scalar_for_number(const std::string& expected) const;
  std::string override_note() const;
  bool set_by_override() const;

  const SceneSource* source_;
  YAML::Node node_;
  std::string path_;
  int line_;  // 1-based, 0 = unknown
};

// Not collective. Parses a YAML plain scalar as a real number: decimal or exponent
// notation, an optional sign, and YAML's .inf/.nan spellings (returned as such, so the
// caller can say "not finite"). Empty optional if it is not a number.
std::optional<double> parse_real(std::string_view text);
// Not collective. Parses an optionally signed decimal integer that fits in int64.
std::optional<std::int64_t> parse_integer(std::string_view text);

// Not collective. "a.b" / "a[3]" path arithmetic shared with the --set parser.
std::string join_key(const std::string& parent, std::string_view key);
std::string join_index(const std::string& parent, std::size_t index);

}  // namespace catena::model::detail
