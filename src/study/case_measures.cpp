#include "catena/study/case_measures.hpp"

#include <algorithm>
#include <cmath>

#include "catena/core/error.hpp"
#include "catena/post/run_difference.hpp"

namespace catena::study {
namespace {

// m: how near a run's node must be to the reference's probe point to be the same point.
constexpr double probe_tolerance = 1e-6;

// Keeps in `worst` the value of larger magnitude (a NaN `worst` takes any value).
void keep_worst(double& worst, double value) {
  if (!std::isfinite(worst) || std::abs(value) > std::abs(worst)) worst = value;
}

std::vector<double> sample_times(std::size_t n, double dt) {
  std::vector<double> t(n);
  for (std::size_t k = 0; k < n; ++k) t[k] = static_cast<double>(k) * dt;
  return t;
}

// Percent of the reference's statistic; a statistic near zero (a minimum of 0 N) is
// compared relative to 1 N, or 1 mm for the uplift.
double percent(double value, double reference, double floor) {
  return 100.0 * post::relative_error(value, reference, floor);
}

// Rethrows an error of the statistics library naming `path`.
[[noreturn]] void rethrow_for(const std::string& path, const InputError& e) {
  throw InputError({path, 0, e.where().key}, e.message());
}

}  // namespace

ReferenceRun::ReferenceRun(const std::string& path, std::vector<std::int64_t> probes,
                           double cutoff_hz)
    : path_(path), cutoff_hz_(cutoff_hz), probes_(std::move(probes)) {
  has_pantographs_ = io::read_run_work(path).has_pantographs;
  if (has_pantographs_) {
    contact_ = io::read_contact_run(path);
    section_ = io::evaluation_section_or_record(contact_);
    try {
      for (const post::PantographRecord& p : contact_.pantographs)
        statistics_.push_back(post::contact_statistics(p, contact_.registration_points,
                                                       {contact_.dt, cutoff_hz_, section_}));
    } catch (const InputError& e) {
      rethrow_for(path, e);
    }
  }
  if (probes_.empty() && !has_pantographs_) probes_.push_back(io::most_displaced_node(path));
  for (std::int64_t id : probes_) tracks_.push_back(io::read_node_track(path, id));
}

std::vector<PartErrors> ReferenceRun::errors_by_part(const std::string& path) const {
  std::vector<PartErrors> parts;
  if (has_pantographs_) {
    const io::ContactRun run = io::read_contact_run(path);
    const std::vector<double> reference_times = sample_times(contact_.n_samples, contact_.dt);
    const std::vector<double> run_times = sample_times(run.n_samples, run.dt);
    for (std::size_t j = 0; j < contact_.pantographs.size(); ++j) {
      const post::PantographRecord& ref = contact_.pantographs[j];
      const auto match = std::find_if(run.pantographs.begin(), run.pantographs.end(),
                                      [&](const auto& p) { return p.name == ref.name; });
      if (match == run.pantographs.end())
        throw InputError({path, 0, "/pantographs"},
                         "no pantograph '" + ref.name + "' as in the reference " + path_);
      CaseErrors& e = parts.emplace_back(PartErrors{ref.name, {}}).errors;
      try {
        post::PantographRecord on_reference_times = ref;
        on_reference_times.force = post::resample_linear(run_times, match->force, reference_times);
        const post::ForceDifference d =
            post::force_difference(on_reference_times, ref, {contact_.dt, cutoff_hz_, section_});
        keep_worst(e.force_rms, d.rms_raw);
        keep_worst(e.force_max, d.max_raw);
        keep_worst(e.force_rms_filtered, d.rms_filtered);
        keep_worst(e.force_max_filtered, d.max_filtered);
        const post::ContactStatistics s = post::contact_statistics(*match, run.registration_points,
                                                                   {run.dt, cutoff_hz_, section_});
        const post::ContactStatistics& r = statistics_[j];
        keep_worst(e.mean, percent(s.mean, r.mean, 1.0));
        keep_worst(e.std, percent(s.standard_deviation, r.standard_deviation, 1.0));
        keep_worst(e.stat_max, percent(s.statistical_max, r.statistical_max, 1.0));
        keep_worst(e.stat_min, percent(s.statistical_min, r.statistical_min, 1.0));
        keep_worst(e.max, percent(s.max, r.max, 1.0));
        keep_worst(e.min, percent(s.min, r.min, 1.0));
        keep_worst(e.loss, s.contact_loss_percent - r.contact_loss_percent);
        if (s.max_uplift_at_support && r.max_uplift_at_support)
          keep_worst(e.uplift, percent(*s.max_uplift_at_support, *r.max_uplift_at_support, 1e-3));
      } catch (const InputError& error) {
        rethrow_for(path, error);
      }
    }
  }
  for (const io::NodeTrack& ref : tracks_) {
    // By its point, not its id: a run on another mesh numbers its nodes otherwise.
    const io::NodeTrack run =
        io::read_node_track(path, io::node_at(path, ref.reference_position, probe_tolerance));
    std::vector<double> on_reference_times(ref.positions.size());
    for (int c = 0; c < 3; ++c) {
      std::vector<double> coordinate;
      for (std::size_t k = 0; k < run.time.size(); ++k)
        coordinate.push_back(run.positions[3 * k + static_cast<std::size_t>(c)]);
      std::vector<double> resampled;
      try {
        resampled = post::resample_linear(run.time, coordinate, ref.time);
      } catch (const InputError& error) {
        rethrow_for(path, error);
      }
      for (std::size_t k = 0; k < ref.time.size(); ++k)
        on_reference_times[3 * k + static_cast<std::size_t>(c)] = resampled[k];
    }
    const post::TrackDifference d = post::track_difference(on_reference_times, ref.positions);
    CaseErrors& e =
        parts.emplace_back(PartErrors{"node " + std::to_string(ref.node_id), {}}).errors;
    e.probe_rms = d.rms;
    e.probe_max = d.max;
  }
  return parts;
}

CaseErrors worst_of(const std::vector<PartErrors>& parts) {
  CaseErrors worst;
  for (const auto field : error_fields())
    for (const PartErrors& p : parts)
      if (std::isfinite(p.errors.*field)) keep_worst(worst.*field, p.errors.*field);
  return worst;
}

CaseErrors ReferenceRun::errors_of(const std::string& path) const {
  return worst_of(errors_by_part(path));
}

}  // namespace catena::study
