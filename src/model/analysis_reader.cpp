#include "analysis_reader.hpp"

#include "did_you_mean.hpp"

namespace catena::model::detail {
namespace {

// Generous caps that still catch a misplaced exponent ("max: 2e9").
constexpr std::int64_t max_load_steps_cap = 1'000'000;
constexpr std::int64_t max_newton_iterations_cap = 10'000;

AnalysisType read_analysis_type(const Field& type) {
  static const std::vector<std::string> accepted{"static", "dynamic"};
  const std::string name = type.text_or("static");
  if (name == "static") return AnalysisType::static_equilibrium;
  if (name == "dynamic") return AnalysisType::dynamic;
  type.fail("unknown analysis type '" + name + "';" + did_you_mean(name, accepted) +
            " accepted: static, dynamic");
}

void read_load_steps(const Field& steps, StaticOptions& options) {
  if (!steps.present()) return;
  steps.expect_map("load stepping settings {initial, min, max}");
  steps.check_keys({"initial", "min", "max"});
  const RealRange fraction = RealRange::between(0.0, false, 1.0, true, "");
  const Field initial = steps.child("initial");
  const Field min = steps.child("min");
  options.initial_load_step = initial.real_or(options.initial_load_step, fraction);
  options.min_load_step = min.real_or(options.min_load_step, fraction);
  options.max_load_steps = static_cast<int>(steps.child("max").integer_or(
      options.max_load_steps, IntRange::between(1, max_load_steps_cap)));
  if (options.min_load_step > options.initial_load_step)
    (min.present() ? min : initial)
        .fail("the smallest load step (min = " + format_number(options.min_load_step) +
              ") exceeds the first one (initial = " + format_number(options.initial_load_step) +
              "); expected 0 < min <= initial <= 1");
}

void read_newton(const Field& newton, StaticOptions& options) {
  if (!newton.present()) return;
  newton.expect_map("Newton settings {rtol, atol, max_iterations}");
  newton.check_keys({"rtol", "atol", "max_iterations"});
  options.rtol =
      newton.child("rtol").real_or(options.rtol, RealRange::between(0.0, false, 1e-3, true, ""));
  options.atol = newton.child("atol").real_or(options.atol, RealRange::positive("N"));
  options.max_newton_iterations =
      static_cast<int>(newton.child("max_iterations")
                           .integer_or(options.max_newton_iterations,
                                       IntRange::between(1, max_newton_iterations_cap)));
}

}  // namespace

AnalysisType read_analysis(const Field& analysis, StaticOptions& options) {
  if (!analysis.present()) return AnalysisType::static_equilibrium;
  analysis.expect_map("analysis settings {type, duration, initial, load_steps, newton}");
  analysis.check_keys({"type", "duration", "initial", "load_steps", "newton",
                       "elastic_catenary_guess", "structure", "modal_cutoff", "modal_basis"});
  const AnalysisType type = read_analysis_type(analysis.child("type"));
  options.elastic_catenary_guess =
      analysis.child("elastic_catenary_guess").boolean_or(options.elastic_catenary_guess);
  read_load_steps(analysis.child("load_steps"), options);
  read_newton(analysis.child("newton"), options);
  return type;
}

void read_output(const Field& output, OutputOptions& options) {
  if (!output.present()) return;
  output.expect_map(
      "output settings {file, interval, flush_wall_seconds, checkpoint_wall_seconds}");
  output.check_keys({"file", "interval", "flush_wall_seconds", "checkpoint_wall_seconds"});
  options.file = output.child("file").text_or(options.file);
  options.interval =
      output.child("interval").real_or(options.interval, RealRange::non_negative("s"));
  options.flush_wall_seconds = output.child("flush_wall_seconds")
                                   .real_or(options.flush_wall_seconds, RealRange::positive("s"));
  options.checkpoint_wall_seconds =
      output.child("checkpoint_wall_seconds")
          .real_or(options.checkpoint_wall_seconds, RealRange::non_negative("s"));
}

}  // namespace catena::model::detail
