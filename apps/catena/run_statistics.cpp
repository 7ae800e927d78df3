#include "run_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "catena/core/error.hpp"
#include "catena/io/run_files.hpp"
#include "catena/post/butterworth.hpp"

namespace catena::app {
namespace {

// The library's keys name its arguments; the user knows the file's datasets and the options.
[[noreturn]] void rethrow_naming_file(const InputError& e, const std::string& file) {
  const std::string& k = e.where().key;
  const std::string key = k == "cutoff" ? "--cutoff"
                          : k == "dt"   ? io::contact_run_times_dataset()
                                        : k;
  throw InputError({file, 0, key}, e.message());
}

// The part of `section` the pantograph's record covers. Where the record ends inside the
// section (a run stopped, or too short), the last 2/cutoff seconds of travel are left out:
// the zero-phase filter's backward pass starts there from the last value, and its start-up
// transient (on a contact-force-like test signal: 0.07 N one cutoff period before the end)
// is 0.0015 N two periods before it (tests/unit/test_post_contact_statistics.cpp).
// A record that reaches an end of the section but for round-off (240.0 is stored as
// 239.99999999998892 by some step sequences) covers it: the ends are widened as the
// statistics widen them (contact_statistics.hpp).
post::EvaluationSection covered_part_of(const post::EvaluationSection& section,
                                        const post::PantographRecord& p, double dt,
                                        double cutoff_hz) {
  auto [lo, hi] = std::minmax_element(p.position.begin(), p.position.end());
  double low = *lo, high = *hi;
  const double edge = std::abs(p.speed) * 2.0 / cutoff_hz;
  const auto round_off = [&](double x) {
    return std::max(1e-6 * std::abs(p.speed) * dt, 1e-9 * std::abs(x));
  };
  const bool forward = p.position.back() >= p.position.front();
  // Snapped to the section's ends where the record reaches them; else cut, the record's
  // last end by the filter's edge.
  if (high >= section.x_end - round_off(section.x_end))
    high = section.x_end;
  else if (forward)
    high -= edge;
  if (low <= section.x_start + round_off(section.x_start))
    low = section.x_start;
  else if (!forward)
    low += edge;
  return {std::max(section.x_start, low), std::min(section.x_end, high)};
}

post::EvaluationSection requested_section(const StatsArguments& args, const io::ContactRun& run) {
  if (args.section) return {(*args.section)[0], (*args.section)[1]};
  if (run.evaluation_section) return *run.evaluation_section;
  throw InputError({args.file, 0, "evaluation_start"},
                   "the run sets no evaluation section (root attributes evaluation_start, "
                   "evaluation_end absent or 0): give one with --section X0 X1 (m along "
                   "the path)");
}

std::string ranges_to_apply(const StatsArguments& args, const io::ContactRun& run) {
  if (args.ranges) return *args.ranges == "none" ? "" : *args.ranges;
  if (run.acceptance.empty() || run.acceptance == "en50318") return run.acceptance;
  throw InputError({args.file, 0, "acceptance"},
                   "unknown acceptance ranges '" + run.acceptance +
                       "' (root attribute acceptance); accepted: en50318. Override with "
                       "--ranges en50318|none");
}

}  // namespace

void refuse_unfinished_name(const std::string& file) {
  // A run still going (or stopped) writes OUT.part.h5: point there from OUT.h5.
  const std::string partial = io::partial_output_path(file);
  if (!std::filesystem::exists(file) && std::filesystem::exists(partial))
    throw InputError({file, 0, ""},
                     "no such file; the run has not finished: its output so far is " + partial +
                         " (give that file, or continue the run with catena run --restart)");
}

RunEvaluation evaluate_run(const StatsArguments& args, SectionCoverage coverage) {
  refuse_unfinished_name(args.file);
  RunEvaluation out;
  const auto unfinished = io::UnfinishedRuns::accepted;
  out.steps = args.steps;
  out.run = args.steps ? io::read_contact_run_steps(args.file, unfinished)
                       : io::read_contact_run(args.file, unfinished);
  const double coarsest = 1.0 / (post::min_sampling_rate_per_cutoff * args.cutoff_hz);
  if (!args.series_given && out.run.dt > coarsest * (1.0 + 1e-9)) {
    // Fields written seldom (output.interval): the contact force of every step, if the
    // steps are uniform; else the samples, which the statistics then refuse by name.
    try {
      io::ContactRun steps = io::read_contact_run_steps(args.file, unfinished);
      std::ostringstream note;
      note << "the samples are " << out.run.dt << " s apart, too coarse for the " << args.cutoff_hz
           << " Hz cutoff (at most " << coarsest
           << " s): the contact force of every step is evaluated (as --series steps)";
      out.series_note = note.str();
      out.run = std::move(steps);
      out.steps = true;
    } catch (const InputError&) {
    }
  }
  // A cutoff the user chose is refused when the record is too short for it (cutoff_too_low);
  // EN 50318's 20 Hz on a short run (a test's 0.05 s) is left as it was.
  const double record = out.run.time.size() > 1 ? out.run.time.back() - out.run.time.front() : 0.0;
  if (args.cutoff_given && record > 0.0 && cutoff_too_low(args.cutoff_hz, record)) {
    std::ostringstream os;
    os << "--cutoff " << args.cutoff_hz << " Hz: the record lasts " << record
       << " s, shorter than two periods of the cutoff (" << 2.0 / args.cutoff_hz
       << " s), so the filtered force would be its start-up transient; accepted: at least "
       << lowest_cutoff_text(record) << " Hz for this record (EN 50318: 20 Hz)";
    throw InputError({args.file, 0, "--cutoff"}, os.str());
  }
  out.finished = out.run.status == "complete";
  out.section = coverage == SectionCoverage::covered && !args.section
                    ? io::evaluation_section_or_record(out.run)
                    : requested_section(args, out.run);
  out.section_given = args.section.has_value();
  out.ranges = ranges_to_apply(args, out.run);

  post::ContactStatisticsOptions options;
  options.dt = out.run.dt;
  options.cutoff_hz = args.cutoff_hz;
  for (const post::PantographRecord& p : out.run.pantographs) {
    for (std::size_t k = 0; k < p.force.size(); ++k)
      if (!std::isfinite(p.force[k]) || !std::isfinite(p.position[k])) {
        std::ostringstream os;
        os << "pantograph '" << p.name << "': the contact "
           << (std::isfinite(p.force[k]) ? "position" : "force") << " of sample " << k
           << " (t = " << out.run.time[k]
           << " s) is not a number: the run diverged there; no statistics";
        throw InputError(
            {args.file, 0, out.steps ? "/steps/contact_force" : "/samples/contact_force"},
            os.str());
      }
    PantographEvaluation e;
    e.pantograph = &p;
    // Without an evaluation section (the scene's or --section) each pantograph is evaluated
    // over its own record: on a long line with several trains no two share a stretch.
    const post::EvaluationSection whole =
        !args.section && !out.run.evaluation_section && !p.position.empty()
            ? post::EvaluationSection{*std::min_element(p.position.begin(), p.position.end()),
                                      *std::max_element(p.position.begin(), p.position.end())}
            : out.section;
    e.section = covered_part_of(whole, p, out.run.dt, args.cutoff_hz);
    e.partial = e.section.x_end - e.section.x_start <
                (whole.x_end - whole.x_start) - std::abs(p.speed) * out.run.dt;
    options.section = e.section;
    try {
      e.filtered_force = post::butterworth_lowpass_zero_phase(p.force, out.run.dt, args.cutoff_hz);
      if (e.section.x_end > e.section.x_start) {
        e.statistics =
            post::contact_statistics(p, e.filtered_force, out.run.registration_points, options);
      } else if (coverage == SectionCoverage::whole && out.finished) {
        options.section = out.section;  // names the part the record covers
        post::contact_statistics(p, out.run.registration_points, options);
      }
    } catch (const InputError& error) {
      rethrow_naming_file(error, args.file);
    }
    if (e.statistics && out.ranges == "en50318")
      e.acceptance = post::check_en50318(*e.statistics, std::abs(p.speed) * kmh_per_ms);
    out.pantographs.push_back(std::move(e));
  }
  const bool any = std::any_of(out.pantographs.begin(), out.pantographs.end(),
                               [](const PantographEvaluation& e) { return e.statistics; });
  if (!any && coverage == SectionCoverage::whole) {
    std::ostringstream os;
    os << "the run stopped (status '" << out.run.status << "') at t = " << out.run.t_end
       << " s, before any pantograph reached the evaluation section [" << out.section.x_start
       << ", " << out.section.x_end << "] m: no statistics (continue it with catena run "
       << "--restart, or give --section X0 X1 within the part run)";
    throw InputError({args.file, 0, "status"}, os.str());
  }
  return out;
}

std::size_t checks_passed(const std::vector<post::AcceptanceCheck>& checks) {
  return static_cast<std::size_t>(std::count_if(
      checks.begin(), checks.end(), [](const post::AcceptanceCheck& c) { return c.pass; }));
}

bool cutoff_too_low(double cutoff_hz, double record) { return record * cutoff_hz < 2.0; }

std::string lowest_cutoff_text(double record) {
  const double lowest = 2.0 / record;
  const double unit = std::pow(10.0, std::floor(std::log10(lowest)) - 2.0);
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", std::ceil(lowest / unit * (1.0 - 1e-12)) * unit);
  return text;
}

}  // namespace catena::app
