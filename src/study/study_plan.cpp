#include "catena/study/study_plan.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <regex>
#include <set>

#include "catena/core/error.hpp"
#include "catena/model/integrator_catalogue.hpp"

namespace catena::study {
namespace {

[[noreturn]] void fail(const std::string& argument, const std::string& message) {
  throw InputError({"", 0, "--vary"}, "'" + argument + "': " + message);
}

// Splits at commas outside brackets, braces and quotes.
std::vector<std::string> split_top_level(const std::string& text) {
  std::vector<std::string> parts(1);
  int depth = 0;
  char quote = 0;
  for (char c : text) {
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    } else if (c == ',' && depth == 0) {
      parts.emplace_back();
      continue;
    }
    parts.back() += c;
  }
  return parts;
}

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

std::optional<double> number(const std::string& text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::string joined(const std::vector<std::pair<std::string, std::string>>& values,
                   bool resolution) {
  std::string out;
  for (const auto& [key, value] : values) {
    if (resolution_key(key).has_value() != resolution) continue;
    out += (out.empty() ? "" : " ") + key + "=" + value;
  }
  return out;
}

}  // namespace

std::vector<std::string> keys_not_taken_by(const std::string& type) {
  const model::IntegratorType* t = model::find_integrator_type(type);
  if (!t) return {};  // an unknown type: the scene reader names it
  std::vector<std::string> keys;
  if (!t->takes_alpha) keys.emplace_back("integrator.alpha");
  if (t->method != model::IntegratorMethod::irk) {
    keys.emplace_back("integrator.stages");
    keys.emplace_back("integrator.linear_algebra");
  }
  if (!t->takes_newton) {
    keys.emplace_back("integrator.newton");
    keys.emplace_back("integrator.tangent_every");
  }
  if (!t->takes_local_newton) keys.emplace_back("integrator.local_newton");
  if (t->max_order == 0) keys.emplace_back("integrator.order");
  return keys;
}

Variation parse_variation(const std::string& argument) {
  const auto eq = argument.find('=');
  if (eq == std::string::npos)
    fail(argument, "expected KEY=V1,V2,... (a scene key and its values, comma-separated)");
  Variation v;
  v.key = trimmed(argument.substr(0, eq));
  if (v.key.empty()) fail(argument, "the key before '=' is empty");
  std::set<std::string> seen;
  for (const std::string& part : split_top_level(argument.substr(eq + 1))) {
    const std::string value = trimmed(part);
    if (value.empty()) fail(argument, "an empty value (two commas, or one at an end)");
    if (!seen.insert(value).second) fail(argument, "the value '" + value + "' is given twice");
    v.values.push_back(value);
  }
  return v;
}

std::optional<Refinement> resolution_key(const std::string& key) {
  if (key == "integrator.dt" || key == "integrator.dt_max" || key == "catenary.element_length")
    return Refinement{true, 0.5};
  if (key == "integrator.rtol" || key == "integrator.atol") return Refinement{true, 0.1};
  static const std::regex element_count(R"(lines\[[0-9]+\]\.elements)");
  if (std::regex_match(key, element_count)) return Refinement{false, 2.0};
  return std::nullopt;
}

std::vector<std::string> Setting::overrides() const {
  std::vector<std::string> out;
  for (const auto& [key, value] : preset) out.push_back(key + "=" + value);
  for (const auto& [key, value] : values) out.push_back(key + "=" + value);
  for (const auto* list : {&preset, &values})
    for (const auto& [key, value] : *list)
      if (key == "integrator.type")
        for (const std::string& removed : keys_not_taken_by(value)) out.push_back(removed + "=~");
  return out;
}

std::string Setting::method() const {
  const std::string varied = joined(values, false);
  return label.empty() ? varied : varied.empty() ? label : label + " " + varied;
}
std::string Setting::resolution() const { return joined(values, true); }

std::vector<Setting> expand(const std::vector<Variation>& variations) {
  std::set<std::string> keys;
  for (const Variation& v : variations)
    if (!keys.insert(v.key).second)
      throw InputError({"", 0, "--vary"},
                       "the key '" + v.key + "' is varied twice; give its values in one --vary");
  std::vector<Setting> settings(1);
  for (const Variation& v : variations) {
    std::vector<Setting> next;
    for (const Setting& s : settings)
      for (const std::string& value : v.values) {
        Setting grown = s;
        grown.values.emplace_back(v.key, value);
        next.push_back(std::move(grown));
      }
    settings = std::move(next);
  }
  return variations.empty() ? std::vector<Setting>{} : settings;
}

std::vector<MethodPreset> method_presets() {
  return {
      {"hht",
       "HHT-alpha (the scene's alpha), nonlinear structure, at 1x the scene's step",
       1.0,
       true,
       {"integrator.type=hht", nullptr}},
      {"radau",
       "Radau IIA with 3 stages (order 5, L-stable), nonlinear, at 4x the scene's step",
       4.0,
       true,
       {"integrator.type=radau_iia", "integrator.stages=3", nullptr}},
      {"park",
       "Park's method (linear multistep, order 2, A-stable), nonlinear, at 1x",
       1.0,
       true,
       {"integrator.type=park", nullptr}},
      {"bdf",
       "variable-step BDF of order 2, nonlinear, at 1x",
       1.0,
       true,
       {"integrator.type=bdf", "integrator.order=2", nullptr}},
      {"linear",
       "the linear structure, HHT with one linearly implicit step per time step, at 1x",
       1.0,
       false,
       {"analysis.structure=linear", "integrator.type=hht", "integrator.newton=linearly_implicit",
        nullptr}},
      {"modal",
       "the modal model (the scene's or the default cut-off), at 1x",
       1.0,
       false,
       {"analysis.structure=modal", "integrator.type=hht", nullptr}},
  };
}

std::vector<Setting> expand_methods(const std::vector<std::string>& names,
                                    const std::vector<std::string>& steps,
                                    const std::vector<Variation>& variations,
                                    const MethodContext& context) {
  const std::vector<MethodPreset> presets = method_presets();
  std::vector<std::string> wanted;
  for (const std::string& name : names) {
    if (name == "all") {
      for (const MethodPreset& p : presets) wanted.emplace_back(p.name);
      continue;
    }
    if (std::none_of(presets.begin(), presets.end(),
                     [&](const MethodPreset& p) { return name == p.name; })) {
      std::string accepted;
      for (const MethodPreset& p : presets) accepted += std::string(p.name) + ", ";
      throw InputError({"", 0, "--methods"},
                       "unknown method '" + name + "'; accepted: " + accepted + "all");
    }
    if (std::find(wanted.begin(), wanted.end(), name) != wanted.end())
      throw InputError({"", 0, "--methods"}, "the method '" + name + "' is given twice");
    wanted.push_back(name);
  }
  for (const Variation& v : variations)
    if (v.key == "integrator.dt")
      throw InputError({"", 0, "--vary"},
                       "--methods runs each method at its own steps (--steps, multiples of "
                       "its base step): do not also --vary integrator.dt");
  std::vector<double> factors;
  for (const std::string& text : steps) {
    const std::optional<double> f = number(text);
    if (!f || !(*f > 0.0))
      throw InputError({"", 0, "--steps"}, "'" + text +
                                               "': a step factor must be a positive number "
                                               "(e.g. --steps 2,1,0.5)");
    if (std::find(factors.begin(), factors.end(), *f) != factors.end())
      throw InputError({"", 0, "--steps"}, "the step factor '" + text + "' is given twice");
    factors.push_back(*f);
  }
  std::vector<Setting> settings;
  const std::vector<Setting> others =
      variations.empty() ? std::vector<Setting>(1) : expand(variations);
  for (const std::string& name : wanted) {
    const MethodPreset& p = *std::find_if(presets.begin(), presets.end(),
                                          [&](const MethodPreset& q) { return name == q.name; });
    for (double f : factors)
      for (const Setting& other : others) {
        Setting s;
        s.label = p.name;
        for (const char* const* k = p.keys; *k; ++k) {
          const std::string kv = *k;
          const auto eq = kv.find('=');
          s.preset.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
        }
        if (!context.scene_nonlinear && name != "modal") {  // a linear or modal scene
          if (p.nonlinear) s.preset.emplace_back("analysis.structure", "nonlinear");
          s.preset.emplace_back("analysis.modal_cutoff", "~");
          s.preset.emplace_back("analysis.modal_basis", "~");
        }
        if (name == "modal" && !context.modal_basis.empty())
          s.preset.emplace_back("analysis.modal_basis", context.modal_basis);
        s.values.emplace_back("integrator.dt", number_text(context.scene_dt * p.step_factor * f));
        s.values.insert(s.values.end(), other.values.begin(), other.values.end());
        settings.push_back(std::move(s));
      }
  }
  return settings;
}

ReferencePlan default_reference(const std::vector<Variation>& variations, double scene_dt) {
  ReferencePlan plan;
  bool dt_varied = false;
  std::string refined_text;
  for (const Variation& v : variations) {
    const std::optional<Refinement> rule = resolution_key(v.key);
    if (!rule) continue;
    dt_varied = dt_varied || v.key == "integrator.dt";
    std::optional<double> tightest;
    std::string tightest_text;
    for (const std::string& text : v.values) {
      const std::optional<double> x = number(text);
      if (!x || !(*x > 0.0))
        fail(v.key + "=" + text, "a resolution key's values must be positive numbers");
      if (!tightest || (rule->finer_is_smaller ? *x < *tightest : *x > *tightest)) {
        tightest = x;
        tightest_text = text;
      }
    }
    const std::string refined = number_text(*tightest * rule->factor);
    plan.overrides.push_back(v.key + "=" + refined);
    plan.check_overrides.push_back(v.key + "=" + tightest_text);
    refined_text +=
        (refined_text.empty() ? "" : ", ") + v.key + " " + tightest_text + " -> " + refined;
  }
  if (!dt_varied) {
    const std::string refined = number_text(0.5 * scene_dt);
    plan.overrides.push_back("integrator.dt=" + refined);
    plan.check_overrides.push_back("integrator.dt=" + number_text(scene_dt));
    refined_text += (refined_text.empty() ? "" : ", ") + std::string("integrator.dt ") +
                    number_text(scene_dt) + " (the scene's) -> " + refined;
  }
  plan.description = "the scene's method at the study's tightest resolution, refined once (" +
                     refined_text + "); checked against the same unrefined";
  return plan;
}

ReferencePlan given_reference(const std::vector<std::string>& overrides) {
  ReferencePlan plan;
  plan.overrides = overrides;
  for (const std::string& o : overrides)
    if (o.rfind("integrator.type=", 0) == 0)
      for (const std::string& removed : keys_not_taken_by(o.substr(16)))
        plan.overrides.push_back(removed + "=~");
  std::string list;
  for (const std::string& o : overrides) list += (list.empty() ? "" : " ") + o;
  plan.description = overrides.empty() ? "the scene as it is (--reference with no keys)"
                                       : "given by --reference: " + list;
  return plan;
}

std::string case_stem(const std::string& method, const std::string& resolution) {
  std::string text = method.empty()       ? resolution
                     : resolution.empty() ? method
                                          : method + " " + resolution;
  for (const char* prefix : {"integrator.", "analysis.", "catenary."})
    for (std::size_t at; (at = text.find(prefix)) != std::string::npos;)
      text.erase(at, std::char_traits<char>::length(prefix));
  std::string stem;
  for (char c : text) {
    const bool kept = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' ||
                      c == '=' || c == '+' || c == '-';
    stem += kept ? c : '_';
  }
  if (stem.size() > 96) stem.resize(96);
  return stem.empty() ? "setting" : stem;
}

std::string number_text(double value) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return ec == std::errc() ? std::string(buffer, end) : std::to_string(value);
}

}  // namespace catena::study
