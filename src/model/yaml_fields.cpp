#include "yaml_fields.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <map>

#include "did_you_mean.hpp"
#include "physical_bounds.hpp"

namespace catena::model::detail {
namespace {

constexpr std::size_t max_value_text = 60;  // characters of a value quoted in a message

std::string truncated(std::string s) {
  if (s.size() > max_value_text) s = s.substr(0, max_value_text - 3) + "...";
  return s;
}

// yaml-cpp tags quoted scalars "!" (non-plain); plain scalars get "?" or an explicit tag.
bool is_quoted(const YAML::Node& node) { return node.IsScalar() && node.Tag() == "!"; }

// True if `path` is `ancestor` or lies below it ("a.b" is below "a", "a[0]" too).
bool is_at_or_under(std::string_view path, std::string_view ancestor) {
  if (!path.starts_with(ancestor)) return false;
  if (path.size() == ancestor.size()) return true;
  const char next = path[ancestor.size()];
  return next == '.' || next == '[';
}

std::string with_unit(std::string text, const std::string& unit) {
  return unit.empty() ? text : text + " [" + unit + "]";
}

int line_of(const YAML::Mark& mark, int fallback) {
  return mark.is_null() ? fallback : mark.line + 1;
}

}  // namespace

// --- ranges ------------------------------------------------------------------------------

RealRange RealRange::any(std::string unit) {
  RealRange r;
  r.max_magnitude = physical_magnitude_bound(unit);
  r.unit = std::move(unit);
  return r;
}

RealRange RealRange::positive(std::string unit) { return greater_than(0.0, std::move(unit)); }

RealRange RealRange::non_negative(std::string unit) {
  RealRange r;
  r.min = 0.0;
  r.max_magnitude = physical_magnitude_bound(unit);
  r.unit = std::move(unit);
  return r;
}

RealRange RealRange::greater_than(double min, std::string unit) {
  RealRange r;
  r.min = min;
  r.min_inclusive = false;
  r.max_magnitude = physical_magnitude_bound(unit);
  r.unit = std::move(unit);
  return r;
}

RealRange RealRange::between(double min, bool min_inclusive, double max, bool max_inclusive,
                             std::string unit) {
  RealRange r;
  r.min = min;
  r.max = max;
  r.min_inclusive = min_inclusive;
  r.max_inclusive = max_inclusive;
  r.unit = std::move(unit);
  return r;
}

bool RealRange::contains(double x) const {
  if (!std::isfinite(x)) return false;
  const bool above = min_inclusive ? x >= min : x > min;
  const bool below = max_inclusive ? x <= max : x < max;
  return above && below && std::abs(x) <= max_magnitude;
}

std::string RealRange::describe() const {
  const bool has_min = std::isfinite(min);
  const bool has_max = std::isfinite(max);
  std::string text = "a finite number";
  if (has_min && has_max) {
    text += std::string(" in ") + (min_inclusive ? "[" : "(") + format_number(min) + ", " +
            format_number(max) + (max_inclusive ? "]" : ")");
  } else if (has_min) {
    text += (min_inclusive ? " >= " : " > ") + format_number(min);
  } else if (has_max) {
    text += (max_inclusive ? " <= " : " < ") + format_number(max);
  }
  text = with_unit(text, unit);
  // Kept apart from the interval, whose wording messages and tests rely on.
  if (std::isfinite(max_magnitude))
    text += std::string(has_min && min >= 0.0 ? " (at most " : " (magnitude at most ") +
            format_number(max_magnitude) + ", a physical bound)";
  return text;
}

IntRange IntRange::any(std::string meaning) {
  IntRange r;
  r.meaning = std::move(meaning);
  return r;
}

IntRange IntRange::between(std::int64_t min, std::int64_t max) {
  IntRange r;
  r.min = min;
  r.max = max;
  return r;
}

std::string IntRange::describe() const {
  constexpr auto lowest = std::numeric_limits<std::int64_t>::min();
  constexpr auto highest = std::numeric_limits<std::int64_t>::max();
  std::string text = "an integer";
  if (min != lowest && max != highest)
    text += " in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  else if (min != lowest)
    text += " >= " + std::to_string(min);
  else if (max != highest)
    text += " <= " + std::to_string(max);
  return meaning.empty() ? text : meaning + " (" + text + ")";
}

// --- free helpers ------------------------------------------------------------------------

std::optional<double> parse_real(std::string_view text) {
  std::string_view body = text;
  bool negative = false;
  if (!body.empty() && (body.front() == '+' || body.front() == '-')) {
    negative = body.front() == '-';
    body.remove_prefix(1);
  }
  // YAML 1.2 core-schema spellings; returned so that the caller can say "not finite".
  for (std::string_view inf : {".inf", ".Inf", ".INF"})
    if (body == inf) return negative ? -HUGE_VAL : HUGE_VAL;
  for (std::string_view nan : {".nan", ".NaN", ".NAN"})
    if (body == nan) return std::nan("");
  // from_chars would also take "inf" and "nan", which YAML reads as strings.
  if (body.empty() ||
      !(std::isdigit(static_cast<unsigned char>(body.front())) || body.front() == '.'))
    return std::nullopt;
  double value = 0.0;
  const auto [end, ec] =
      std::from_chars(body.data(), body.data() + body.size(), value, std::chars_format::general);
  if (end != body.data() + body.size()) return std::nullopt;
  if (ec == std::errc::result_out_of_range) {
    // Saturate as strtod does (±HUGE_VAL on overflow, 0 on underflow); the body is a
    // validated decimal, so the C locale's decimal point is not an issue.
    value = std::strtod(std::string(body).c_str(), nullptr);
  } else if (ec != std::errc()) {
    return std::nullopt;
  }
  return negative ? -value : value;
}

std::optional<std::int64_t> parse_integer(std::string_view text) {
  std::string_view body = text;
  if (body.size() > 1 && body.front() == '+') body.remove_prefix(1);
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(body.data(), body.data() + body.size(), value);
  if (ec != std::errc() || end != body.data() + body.size()) return std::nullopt;
  return value;
}

std::string join_key(const std::string& parent, std::string_view key) {
  return parent.empty() ? std::string(key) : parent + "." + std::string(key);
}

std::string join_index(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

// --- Field -------------------------------------------------------------------------------

Field::Field(const SceneSource* source, YAML::Node node, std::string path, int line)
    : source_(source), node_(std::move(node)), path_(std::move(path)), line_(line) {}

Field Field::root(const SceneSource& source, const YAML::Node& node) {
  return Field(&source, node, "", line_of(node.Mark(), 1));
}

bool Field::set_by_override() const {
  for (const AppliedOverride& o : source_->overrides)
    if (is_at_or_under(path_, o.path)) return true;
  return false;
}

std::string Field::override_note() const {
  std::string involved;
  for (const AppliedOverride& o : source_->overrides) {
    const bool related =
        is_at_or_under(path_, o.path) || (!path_.empty() && is_at_or_under(o.path, path_));
    if (!related) continue;
    involved += involved.empty() ? "" : ", ";
    involved += "--set '" + o.text + "'";
  }
  return involved.empty() ? std::string() : " (value given on the command line: " + involved + ")";
}

InputLocation Field::location() const {
  // A value that came from --set has no line in the file: its yaml-cpp mark points into
  // the override text, so report no line and name the override in the message instead.
  return InputLocation{source_->file_label, set_by_override() ? 0 : line_, path_};
}

void Field::fail(const std::string& message) const {
  throw InputError(location(), message + override_note());
}

Field Field::indexed(std::size_t i, const YAML::Node& item) const {
  return Field(source_, item, join_index(path_, i), line_of(item.Mark(), line_));
}

Field Field::child(std::string_view key) const {
  const std::string child_path = join_key(path_, key);
  if (!present()) return Field(source_, YAML::Node(YAML::NodeType::Undefined), child_path, line_);
  if (!node_.IsMap())
    fail("expected a map with key '" + std::string(key) + "', got " + value_text());
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    if (it->first.IsScalar() && it->first.Scalar() == key)
      return Field(source_, it->second, child_path, line_of(it->first.Mark(), line_));
  }
  return Field(source_, YAML::Node(YAML::NodeType::Undefined), child_path, line_);
}

std::vector<Field> Field::items() const {
  std::vector<Field> out;
  if (!present()) return out;
  if (!node_.IsSequence()) fail("expected a list (write [] for none), got " + value_text());
  out.reserve(node_.size());
  std::size_t i = 0;
  for (const YAML::Node& item : node_) out.push_back(indexed(i++, item));
  return out;
}

std::vector<std::pair<std::string, Field>> Field::entries() const {
  std::vector<std::pair<std::string, Field>> out;
  if (!present()) return out;
  if (!node_.IsMap()) fail("expected a map of keys, got " + value_text());
  std::map<std::string, int> first_line;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const int key_line = line_of(it->first.Mark(), line_);
    if (!it->first.IsScalar() || it->first.Scalar().empty()) {
      const Field key_field(source_, it->first, path_, key_line);
      key_field.fail("keys must be plain names, got " + key_field.value_text());
    }
    const std::string& key = it->first.Scalar();
    Field value(source_, it->second, join_key(path_, key), key_line);
    const auto [previous, inserted] = first_line.emplace(key, key_line);
    if (!inserted)
      value.fail("duplicate key '" + key + "' (first given at line " +
                 std::to_string(previous->second) + ")");
    out.emplace_back(key, std::move(value));
  }
  return out;
}

void Field::check_keys(const std::vector<std::string>& accepted) const {
  for (const auto& [key, value] : entries()) {
    if (std::find(accepted.begin(), accepted.end(), key) != accepted.end()) continue;
    std::string list;
    for (const std::string& a : accepted) list += (list.empty() ? "" : ", ") + a;
    value.fail("unknown key '" + key + "';" + did_you_mean(key, accepted) +
               " accepted keys: " + list);
  }
}

void Field::expect_map(std::string_view what) const {
  const std::string expected = std::string(what) + " (a map of keys)";
  require_value(expected);
  if (!node_.IsMap()) fail("expected " + expected + ", got " + value_text());
}

void Field::require_value(const std::string& expected) const {
  if (!present()) fail("missing required key; expected " + expected);
  if (node_.IsNull()) fail("no value given; expected " + expected);
}

std::string Field::scalar_for_number(const std::string& expected) const {
  require_value(expected);
  if (!node_.IsScalar()) fail("expected " + expected + ", got " + value_text());
  if (is_quoted(node_))
    fail("expected " + expected + ", got the quoted string " + value_text() +
         " (write numbers without quotes)");
  return node_.Scalar();
}

double Field::real(const RealRange& range) const {
  const std::string expected = range.describe();
  const std::string text = scalar_for_number(expected);
  const std::optional<double> value = parse_real(text);
  if (!value) fail("invalid value '" + truncated(text) + "'; expected " + expected);
  if (!std::isfinite(*value))
    fail("value " + truncated(text) + " is not finite; expected " + expected);
  if (!range.contains(*value))
    fail("value " + truncated(text) + " is out of range; expected " + expected);
  return *value;
}

double Field::real_or(double fallback, const RealRange& range) const {
  return present() ? real(range) : fallback;
}

std::int64_t Field::integer(const IntRange& range) const {
  const std::string expected = range.describe();
  const std::string text = scalar_for_number(expected);
  const std::optional<std::int64_t> value = parse_integer(text);
  if (!value) {
    const bool is_number = parse_real(text).has_value();
    fail((is_number ? "value " + truncated(text) + " is not an integer"
                    : "invalid value '" + truncated(text) + "'") +
         "; expected " + expected);
  }
  if (!range.contains(*value))
    fail("value " + truncated(text) + " is out of range; expected " + expected);
  return *value;
}

std::int64_t Field::integer_or(std::int64_t fallback, const IntRange& range) const {
  return present() ? integer(range) : fallback;
}

std::string Field::text() const {
  const std::string expected = "a non-empty string";
  require_value(expected);
  if (!node_.IsScalar()) fail("expected " + expected + ", got " + value_text());
  if (node_.Scalar().empty()) fail("expected " + expected + ", got an empty string");
  return node_.Scalar();
}

std::string Field::text_or(const std::string& fallback) const {
  return present() ? text() : fallback;
}

bool Field::boolean_or(bool fallback) const {
  if (!present()) return fallback;
  const std::string expected = "true or false";
  require_value(expected);
  if (node_.IsScalar() && !is_quoted(node_)) {
    std::string lowered = node_.Scalar();
    for (char& c : lowered) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lowered == "true") return true;
    if (lowered == "false") return false;
  }
  fail("invalid value " + value_text() + "; expected " + expected);
}

Vec3 Field::vec3(const RealRange& component) const {
  const std::string expected = "a list of 3 numbers [x, y, z], each " + component.describe();
  require_value(expected);
  if (!node_.IsSequence() || node_.size() != 3) {
    const std::string count =
        node_.IsSequence() ? " (" + std::to_string(node_.size()) + " items)" : "";
    fail("expected " + expected + ", got " + value_text() + count);
  }
  Vec3 v;
  for (std::size_t i = 0; i < 3; ++i)
    v[static_cast<Eigen::Index>(i)] = indexed(i, node_[i]).real(component);
  return v;
}

Vec3 Field::vec3_or(const Vec3& fallback, const RealRange& component) const {
  return present() ? vec3(component) : fallback;
}

Vec3 Field::scalar_or_vec3(const RealRange& component) const {
  require_value("a number or a list of 3 numbers [x, y, z], each " + component.describe());
  if (node_.IsScalar()) return Vec3::Constant(real(component));
  return vec3(component);
}

std::string Field::value_text() const {
  if (!present()) return "nothing";
  if (node_.IsNull()) return "no value";
  if (node_.IsScalar())
    return is_quoted(node_) ? "\"" + truncated(node_.Scalar()) + "\"" : truncated(node_.Scalar());
  YAML::Emitter flow;
  flow.SetMapFormat(YAML::Flow);
  flow.SetSeqFormat(YAML::Flow);
  flow << node_;
  return truncated(flow.c_str());
}

}  // namespace catena::model::detail
