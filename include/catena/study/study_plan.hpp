#pragma once
// What `catena study` runs (docs/study.md): the settings — the Cartesian product of the
// `--vary KEY=V1,V2,...` lists, each a set of scene overrides on top of the study's `--set`
// ones — and the reference they are measured against.
//
// The default reference refines the study's tightest setting: every varied resolution key
// (a key whose value sets how fine the run is: the step, tolerances, the element length or
// count) at its tightest value in the study, refined once, and the time step halved even if
// it was not varied; every other key (the method, the structure model) as the scene has it.
// The same settings unrefined are the reference check: the difference between the two
// estimates the reference's own error, which the study reports beside the errors it
// measures. Pure: no files, no MPI.
#include <optional>
#include <string>
#include <vector>

namespace catena::study {

// One `--vary KEY=V1,V2,...`.
struct Variation {
  std::string key;
  std::vector<std::string> values;
};

// Not collective. Parses "KEY=V1,V2,...": values split at top-level commas (a comma inside
// [], {} or quotes belongs to its value: "catenary.presag=0.01,0.02",
// "gravity=[0,0,-9.81],[0,0,-9.8]"). Throws catena::InputError (key "--vary") naming the
// argument when there is no '=', the key or a value is empty, or a value repeats.
Variation parse_variation(const std::string& argument);

// How a resolution key makes a run finer, and by how much the reference refines it.
struct Refinement {
  bool finer_is_smaller = true;  // the step, tolerances, the element length
  double factor = 0.5;           // the reference's value: the tightest times this
};

// Not collective. The refinement of `key` if it is a resolution key: integrator.dt and
// integrator.dt_max (× 1/2), integrator.rtol and integrator.atol (× 1/10),
// catenary.element_length (× 1/2), lines[i].elements (× 2); else none.
std::optional<Refinement> resolution_key(const std::string& key);

// One setting: a value for every varied key, in the order of the --vary arguments, after
// the keys of its method preset (--methods), if any.
struct Setting {
  std::string label;  // the method preset's name ("" without --methods)
  std::vector<std::pair<std::string, std::string>> preset;  // its keys
  std::vector<std::pair<std::string, std::string>> values;

  // "key=value" for each varied key; where integrator.type is varied, then "key=~" (remove)
  // for each integrator key the type does not take (keys_not_taken_by), so that a scene
  // written for one method serves every method of the study.
  std::vector<std::string> overrides() const;
  // The preset's name and the values of the varied keys that are not resolution keys
  // ("radau", "integrator.type=radau integrator.stages=3"): the method, one line of the
  // work–precision plot; "" if none.
  std::string method() const;
  // The values of the varied resolution keys ("integrator.dt=0.0005"); "" if none.
  std::string resolution() const;
};

// Not collective. The integrator keys (dotted paths) a scene may hold that integrator type
// `type` does not take: alpha (but for hht and petsc), stages and linear_algebra (but for
// the implicit Runge–Kutta types), newton and tangent_every, local_newton (but for hht);
// none for an unknown type.
std::vector<std::string> keys_not_taken_by(const std::string& type);

// Not collective. A file stem for the case of `setting` labelled `method`, made from its
// content so that it names the same case when a study's list of settings changes (and a
// resumed study finds what it ran): "radau_dt=0.004", "type=hht_dt=0.04" — the common key
// prefixes (integrator., analysis., catenary.) dropped, characters other than letters,
// digits and ._=+- made '_', at most 96 characters. Two settings may still share a stem
// (values that differ only in the dropped characters): the caller makes them unique.
std::string case_stem(const std::string& method, const std::string& resolution);

// Not collective. Every combination of the variations' values, the first variation
// varying slowest. Throws catena::InputError (key "--vary") when a key is varied twice.
std::vector<Setting> expand(const std::vector<Variation>& variations);

// A method of `--methods`: scene keys and the step it is run at, the scene's integrator.dt
// times step_factor times each of `--steps`: the factor puts each method's steps where they
// compete (Radau IIA s = 3: 4 × 0.5 ms on EN 50318 agrees with HHT at 0.5 ms, and at 8 ms
// half its steps fail Newton through the contact: docs/study.md).
struct MethodPreset {
  const char* name;
  const char* what;     // one line for the help and the docs
  double step_factor;   // its base step in scene steps
  bool nonlinear;       // runs the nonlinear structure (else the structure keys below)
  const char* keys[4];  // "key=value" overrides (nullptr-terminated)
};

// Not collective. hht, radau, park, bdf, linear, modal (`all` is every one).
std::vector<MethodPreset> method_presets();

// What --methods expands to, besides the presets' keys.
struct MethodContext {
  double scene_dt = 0.0;        // s, the scene's integrator.dt after --set
  bool scene_nonlinear = true;  // the scene's analysis.structure is nonlinear
  std::string modal_basis;      // the file the modal settings share (their modes)
};

// Not collective. The settings of `--methods NAMES --steps FACTORS`: every preset (in
// order) at every step, then combined with `variations` (which must not vary
// integrator.dt: --steps sets it). Throws catena::InputError (key "--methods") for an
// unknown name, naming the accepted ones; (key "--steps") for a factor that is not a
// positive number or with integrator.dt varied.
std::vector<Setting> expand_methods(const std::vector<std::string>& names,
                                    const std::vector<std::string>& steps,
                                    const std::vector<Variation>& variations,
                                    const MethodContext& context);

// The reference's settings (overrides on top of the study's --set ones) and those of its
// check, and a sentence that says how they were chosen.
struct ReferencePlan {
  std::vector<std::string> overrides;
  std::vector<std::string> check_overrides;  // empty with a given reference: no check
  std::string description;
};

// Not collective. The default reference of `variations` (see above); `scene_dt` is the
// time step the scene has after the study's --set overrides (used when integrator.dt is
// not varied). Throws catena::InputError (key "--vary") when a resolution key's values are
// not all positive numbers.
ReferencePlan default_reference(const std::vector<Variation>& variations, double scene_dt);

// Not collective. A reference given by `--reference KEY=V` arguments (no check run); with
// integrator.type among them, the keys that type does not take are removed as in a setting.
ReferencePlan given_reference(const std::vector<std::string>& overrides);

// Not collective. The shortest decimal text of `value` that reads back as the same double.
std::string number_text(double value);

}  // namespace catena::study
