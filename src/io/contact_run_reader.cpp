#include "catena/io/contact_run_reader.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <type_traits>
#include <utility>

#include "catena/core/error.hpp"
#include "hdf5_attributes.hpp"
#include "hdf5_error.hpp"
#include "hdf5_handles.hpp"
#include "static_result_layout.hpp"
#include "time_series_file.hpp"
#include "transient_layout.hpp"

namespace catena::io {
namespace {

namespace layout = transient_layout;
constexpr const char* time_name = layout::time.path;
constexpr const char* contact_force_name = layout::contact_force.path;
constexpr const char* contact_position_name = layout::contact_position.path;
constexpr const char* positions_name = layout::positions.path;
constexpr const char* pantographs_name = layout::pantographs_group;
constexpr const char* node_positions_name = layout::node_positions.path;
constexpr const char* registration_nodes_name = layout::registration_nodes.path;
constexpr const char* step_time_name = layout::step_time.path;
constexpr const char* step_contact_force_name = layout::step_contact_force.path;
constexpr const char* step_registration_height_name = layout::step_registration_height.path;
namespace root_attribute = layout::root_attribute;
namespace pantograph_attribute = layout::pantograph_attribute;

// Relative tolerance on the spacing of /time (dense output at k × output.interval).
constexpr double sampling_tolerance = 1e-6;

using Reader = TimeSeriesFile;

double uniform_interval(const Reader& r, const std::vector<double>& t,
                        const char* name = time_name) {
  if (t.size() < 2) r.fail(name, "fewer than 2 samples: no sampling interval");
  for (std::size_t k = 0; k < t.size(); ++k)
    if (!std::isfinite(t[k]))
      r.fail(name, "the time of sample " + std::to_string(k) + " is not a finite number");
  const double dt = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  if (!(dt > 0.0)) r.fail(name, "the sample times do not increase");
  for (std::size_t k = 0; k + 1 < t.size(); ++k) {
    const double step = t[k + 1] - t[k];
    if (!(std::abs(step - dt) <= sampling_tolerance * dt)) {
      std::ostringstream os;
      os << "not uniformly sampled: samples " << k << " and " << k + 1 << " are " << step
         << " s apart, the mean interval is " << dt << " s";
      r.fail(name, os.str());
    }
  }
  return dt;
}

std::optional<post::EvaluationSection> evaluation_section(const Reader& r) {
  post::EvaluationSection s;
  const char* start_name = root_attribute::evaluation_start;
  const char* end_name = root_attribute::evaluation_end;
  if (r.has_attribute(r.root(), start_name))
    s.x_start = r.number_attribute<double>(r.root(), start_name, start_name);
  if (r.has_attribute(r.root(), end_name))
    s.x_end = r.number_attribute<double>(r.root(), end_name, end_name);
  if (s.x_start == 0.0 && s.x_end == 0.0) return std::nullopt;
  if (!(s.x_end > s.x_start)) {
    std::ostringstream os;
    os << "evaluation_start " << s.x_start << " m, evaluation_end " << s.x_end
       << " m: the end must lie beyond the start (give --section X0 X1 instead)";
    r.fail(end_name, os.str());
  }
  return s;
}

// The groups under /pantographs, placed at their column (attribute index).
std::vector<post::PantographRecord> pantograph_list(const Reader& r, hsize_t n_columns) {
  if (!r.has_link(pantographs_name))
    r.fail(pantographs_name, "missing: the run had no pantographs");
  const GroupHandle group = r.open_group(pantographs_name);
  H5G_info_t info;
  if (H5Gget_info(group.get(), &info) < 0) r.fail(pantographs_name, "cannot list the group");
  if (info.nlinks == 0) r.fail(pantographs_name, "empty: the run had no pantographs");
  if (info.nlinks != n_columns) {
    std::ostringstream os;
    os << info.nlinks << " pantographs but " << n_columns << " columns in " << contact_force_name;
    r.fail(pantographs_name, os.str());
  }
  std::vector<post::PantographRecord> out(n_columns);
  std::vector<bool> seen(n_columns, false);
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t length = H5Lget_name_by_idx(group.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i,
                                              nullptr, 0, H5P_DEFAULT);
    if (length < 0) r.fail(pantographs_name, "cannot list the group");
    std::string name(static_cast<std::size_t>(length) + 1, '\0');
    H5Lget_name_by_idx(group.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(),
                       H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(length));
    const std::string where = std::string(pantographs_name) + "/" + name;
    const GroupHandle g = r.open_group(where.c_str());
    for (const char* attribute : {pantograph_attribute::index, pantograph_attribute::speed})
      if (!r.has_attribute(g.get(), attribute))
        r.fail(where, std::string("missing attribute ") + attribute);
    const auto index =
        r.number_attribute<std::int64_t>(g.get(), pantograph_attribute::index, where);
    if (index < 0 || static_cast<hsize_t>(index) >= n_columns ||
        seen[static_cast<std::size_t>(index)]) {
      std::ostringstream os;
      os << "attribute index = " << index << ": must be a distinct column in [0, " << n_columns
         << ")";
      r.fail(where, os.str());
    }
    const auto column = static_cast<std::size_t>(index);
    seen[column] = true;
    out[column].name = name;
    out[column].speed = r.number_attribute<double>(g.get(), pantograph_attribute::speed, where);
  }
  return out;
}

}  // namespace

namespace {

// catenary.window: how often the window had moved by each row of `dataset` (samples or
// steps) and how far it moves each time (m along x); none for a run without a window.
struct WindowMoves {
  std::vector<std::int64_t> moves;
  double shift_x = 0.0;
};
std::optional<WindowMoves> window_moves(const Reader& r, const char* dataset, hsize_t rows) {
  if (!r.has_attribute(r.root(), root_attribute::window_shift_x)) return std::nullopt;
  WindowMoves w;
  w.shift_x = r.number_attribute<double>(r.root(), root_attribute::window_shift_x,
                                         root_attribute::window_shift_x);
  if (!(w.shift_x > 0.0)) r.fail(root_attribute::window_shift_x, "not a positive length");
  if (!r.has_link(dataset)) r.fail(dataset, "missing: a window's run records its moves");
  if (r.dims(dataset) != std::vector<hsize_t>{rows}) r.fail(dataset, "not one row per record");
  w.moves = r.integers(dataset, {rows});
  return w;
}

// A window's registration nodes stand, at each row, for the points of the line they are at:
// x = reference x + moves × shift. Per point of the line any node reached, its height where a
// node stood on it, else its static height (row 0 of a node one whole number of periods
// from it, the farthest from the pantographs' start `away_from`, whose static push does not
// reach it): the line ahead of the window is at rest; behind it the point's motion is not
// known, but the statistics use a point only while the pantograph is between its
// neighbouring points, which the window holds.
std::vector<post::RegistrationPoint> on_line(const std::vector<post::RegistrationPoint>& nodes,
                                             const WindowMoves& w, double away_from) {
  const auto key = [](double x) { return std::llround(x * 1e4); };  // 0.1 mm
  std::map<long long, post::RegistrationPoint> points;
  const std::size_t rows = w.moves.size();
  for (const post::RegistrationPoint& node : nodes)
    for (std::size_t k = 0; k < rows; ++k) {
      const double x = node.reference_x + static_cast<double>(w.moves[k]) * w.shift_x;
      points[key(x)].reference_x = x;
    }
  for (auto& [unused, point] : points) {
    const post::RegistrationPoint* same_phase = nullptr;
    for (const post::RegistrationPoint& node : nodes) {
      const double periods = (point.reference_x - node.reference_x) / w.shift_x;
      if (std::abs(periods - std::round(periods)) < 1e-6 &&
          (!same_phase ||
           std::abs(node.reference_x - away_from) > std::abs(same_phase->reference_x - away_from)))
        same_phase = &node;
    }
    point.z.assign(rows, same_phase ? same_phase->z.front() : 0.0);
  }
  for (const post::RegistrationPoint& node : nodes)
    for (std::size_t k = 0; k < rows; ++k)
      points[key(node.reference_x + static_cast<double>(w.moves[k]) * w.shift_x)].z[k] = node.z[k];
  std::vector<post::RegistrationPoint> out;
  for (auto& [unused, point] : points) out.push_back(std::move(point));
  return out;
}

// The run's records as written, with a window's registration nodes as they are.
ContactRun read_run(const std::string& path, UnfinishedRuns unfinished) {
  const Hdf5ErrorPrintingSuppressed quiet;
  const Reader r(path);
  layout::require_transient_format(r.root(), path);
  if (unfinished == UnfinishedRuns::refused) check_is_complete_dynamic_output(r);

  ContactRun run;
  run.status = dynamic_output_status(r);
  if (r.has_attribute(r.root(), root_attribute::acceptance))
    run.acceptance =
        r.text_attribute(r.root(), root_attribute::acceptance, root_attribute::acceptance);
  if (!r.has_link(time_name)) r.fail(time_name, "missing: not a Catena dynamic output");
  const std::vector<hsize_t> time_dims = r.dims(time_name);
  if (time_dims.size() != 1) r.fail(time_name, "not one-dimensional");
  const hsize_t n = time_dims[0];
  run.n_samples = static_cast<std::size_t>(n);
  const std::vector<double> times = r.doubles(time_name, {n});
  run.dt = uniform_interval(r, times);
  run.t_end = times.back();
  run.time = times;
  run.evaluation_section = evaluation_section(r);

  for (const char* name : {contact_force_name, contact_position_name})
    if (!r.has_link(name))
      r.fail(name, "missing: the run had no pantographs (no contact was modelled)");
  const std::vector<hsize_t> force_dims = r.dims(contact_force_name);
  if (force_dims.size() != 2 || force_dims[0] != n)
    r.fail(contact_force_name, "not of shape (n_samples, n_pantographs)");
  const hsize_t n_pantographs = force_dims[1];
  if (n_pantographs == 0) r.fail(contact_force_name, "no columns: the run had no pantographs");
  run.pantographs = pantograph_list(r, n_pantographs);
  const std::vector<double> force = r.doubles(contact_force_name, {n, n_pantographs});
  const std::vector<double> position = r.doubles(contact_position_name, {n, n_pantographs});
  for (std::size_t j = 0; j < run.pantographs.size(); ++j) {
    post::PantographRecord& p = run.pantographs[j];
    p.force.resize(run.n_samples);
    p.position.resize(run.n_samples);
    for (std::size_t k = 0; k < run.n_samples; ++k) {
      p.force[k] = force[k * n_pantographs + j];
      p.position[k] = position[k * n_pantographs + j];
    }
  }

  run.has_registration_nodes = r.has_link(registration_nodes_name);
  if (!run.has_registration_nodes) return run;
  const std::vector<hsize_t> registration_dims = r.dims(registration_nodes_name);
  if (registration_dims.size() != 1) r.fail(registration_nodes_name, "not one-dimensional");
  const std::vector<std::int64_t> registration =
      r.integers(registration_nodes_name, registration_dims);
  if (registration.empty()) return run;
  const std::vector<hsize_t> mesh_dims = r.dims(node_positions_name);
  if (mesh_dims.size() != 2 || mesh_dims[1] != 3)
    r.fail(node_positions_name, "not of shape (n_nodes, 3)");
  const hsize_t n_nodes = mesh_dims[0];
  const std::vector<double> reference = r.doubles(node_positions_name, mesh_dims);
  if (r.dims(positions_name) != std::vector<hsize_t>{n, n_nodes, 3})
    r.fail(positions_name, "not of shape (n_samples, n_nodes, 3)");
  std::set<hsize_t> unique;
  for (std::int64_t node : registration) {
    if (node < 0 || static_cast<hsize_t>(node) >= n_nodes) {
      std::ostringstream os;
      os << "node index " << node << " outside [0, " << n_nodes << ")";
      r.fail(registration_nodes_name, os.str());
    }
    unique.insert(static_cast<hsize_t>(node));
  }
  const std::vector<hsize_t> nodes(unique.begin(), unique.end());
  const std::vector<double> z = r.node_heights(nodes, n);
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    post::RegistrationPoint p;
    p.reference_x = reference[3 * nodes[j]];
    p.z.resize(run.n_samples);
    for (std::size_t k = 0; k < run.n_samples; ++k) p.z[k] = z[k * nodes.size() + j];
    run.registration_points.push_back(std::move(p));
  }
  return run;
}

}  // namespace

ContactRun read_contact_run(const std::string& path, UnfinishedRuns unfinished) {
  ContactRun run = read_run(path, unfinished);
  const Hdf5ErrorPrintingSuppressed quiet;
  const Reader r(path);
  if (const auto w = window_moves(r, layout::window_moves.path, run.n_samples))
    run.registration_points =
        on_line(run.registration_points, *w, run.pantographs.front().position.front());
  return run;
}

namespace {

// y (sampled at the ascending times t) at time x: linear between samples, extended by the
// nearest pair beyond them.
double interpolate(const std::vector<double>& t, const std::vector<double>& y, double x) {
  const auto upper = std::upper_bound(t.begin(), t.end(), x);
  std::size_t k = static_cast<std::size_t>(upper - t.begin());
  k = std::clamp<std::size_t>(k, 1, t.size() - 1);
  const double w = (x - t[k - 1]) / (t[k] - t[k - 1]);
  return (1.0 - w) * y[k - 1] + w * y[k];
}

}  // namespace

ContactRun read_contact_run_steps(const std::string& path, UnfinishedRuns unfinished) {
  ContactRun run = read_run(path, unfinished);
  const Hdf5ErrorPrintingSuppressed quiet;
  const Reader r(path);
  const std::vector<double> sample_times = r.doubles(time_name, {run.n_samples});
  for (const char* name : {step_time_name, step_contact_force_name})
    if (!r.has_link(name)) r.fail(name, "missing: the run wrote no step records");
  const std::vector<hsize_t> dims = r.dims(step_time_name);
  if (dims.size() != 1) r.fail(step_time_name, "not one-dimensional");
  const hsize_t n_steps = dims[0];
  const auto n_pantographs = static_cast<hsize_t>(run.pantographs.size());
  if (r.dims(step_contact_force_name) != std::vector<hsize_t>{n_steps, n_pantographs})
    r.fail(step_contact_force_name, "not of shape (n_steps, n_pantographs)");
  const std::vector<double> step_time = r.doubles(step_time_name, {n_steps});
  const std::vector<double> step_force =
      r.doubles(step_contact_force_name, {n_steps, n_pantographs});
  // The series: the first sample (the start), then every step after it.
  std::vector<double> t{sample_times.front()};
  std::vector<std::size_t> rows{0};
  // An unfinished run may have flushed steps beyond its last sample: no positions there.
  const double t_last = run.status == "complete" ? std::numeric_limits<double>::infinity()
                                                 : sample_times.back() + 1e-6 * run.dt;
  for (std::size_t k = 0; k < step_time.size() && step_time[k] <= t_last; ++k)
    if (step_time[k] > t.front()) {
      t.push_back(step_time[k]);
      rows.push_back(k + 1);  // 0: the sample; k + 1: step k
    }
  // A last step cut short to land on the duration.
  if (t.size() > 2) {
    const double dt = t[1] - t[0], last = t.back() - t[t.size() - 2];
    if (last < dt * (1.0 - 1e-6)) {
      t.pop_back();
      rows.pop_back();
    }
  }
  run.dt = uniform_interval(r, t, step_time_name);
  const std::size_t n = t.size();
  for (std::size_t j = 0; j < run.pantographs.size(); ++j) {
    post::PantographRecord& p = run.pantographs[j];
    std::vector<double> force(n), position(n);
    for (std::size_t k = 0; k < n; ++k) {
      force[k] = rows[k] == 0 ? p.force[0] : step_force[(rows[k] - 1) * n_pantographs + j];
      position[k] = interpolate(sample_times, p.position, t[k]);
    }
    p.force = std::move(force);
    p.position = std::move(position);
  }
  // The registration points' heights of every step where the run wrote them; a file
  // without them (an older Catena) gives them interpolated from the samples.
  // Its columns follow /mesh/registration_nodes; the points are that list's distinct nodes,
  // ascending (read_contact_run): point j reads the column of its node's first entry.
  std::vector<double> step_heights;
  std::vector<std::size_t> column(run.registration_points.size());
  hsize_t n_columns = 0;
  if (!run.registration_points.empty() && r.has_link(step_registration_height_name)) {
    const std::vector<std::int64_t> listed =
        r.integers(registration_nodes_name, r.dims(registration_nodes_name));
    std::vector<std::int64_t> distinct(listed);
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    for (std::size_t j = 0; j < column.size(); ++j)
      column[j] = static_cast<std::size_t>(std::find(listed.begin(), listed.end(), distinct[j]) -
                                           listed.begin());
    n_columns = static_cast<hsize_t>(listed.size());
    if (r.dims(step_registration_height_name) != std::vector<hsize_t>{n_steps, n_columns})
      r.fail(step_registration_height_name, "not of shape (n_steps, n_registration_nodes)");
    step_heights = r.doubles(step_registration_height_name, {n_steps, n_columns});
  }
  for (std::size_t j = 0; j < run.registration_points.size(); ++j) {
    post::RegistrationPoint& point = run.registration_points[j];
    std::vector<double> z(n);
    for (std::size_t k = 0; k < n; ++k)
      z[k] = rows[k] == 0 || step_heights.empty()
                 ? interpolate(sample_times, point.z, t[k])
                 : step_heights[(rows[k] - 1) * n_columns + column[j]];
    point.z = std::move(z);
  }
  // A window's moves at each row: the first sample's, then each step's.
  if (auto w = window_moves(r, layout::window_moves.path, run.n_samples)) {
    const std::int64_t first = w->moves.front();
    const std::vector<std::int64_t> steps =
        window_moves(r, layout::step_window_moves.path, n_steps)->moves;
    w->moves.assign(n, first);
    for (std::size_t k = 1; k < n; ++k) w->moves[k] = steps[rows[k] - 1];
    run.registration_points =
        on_line(run.registration_points, *w, run.pantographs.front().position.front());
  }
  run.n_samples = n;
  run.time = std::move(t);
  return run;
}

const char* contact_run_times_dataset() { return time_name; }

bool has_contact_forces(const std::string& path) {
  const Hdf5ErrorPrintingSuppressed quiet;
  return Reader(path).has_link(contact_force_name);
}

void require_run_or_static_result(const std::string& path) {
  const Hdf5ErrorPrintingSuppressed quiet;
  const Reader r(path);
  const std::string format = r.has_attribute(r.root(), "format")
                                 ? r.text_attribute(r.root(), "format", "format")
                                 : std::string("none");
  if (format != layout::format && format != static_layout::format)
    r.fail("format", "the file's format is '" + format + "', not a Catena result; accepted: a " +
                         "dynamic run's output (" + layout::format + ") or a static result (" +
                         static_layout::format + ")");
}

post::EvaluationSection evaluation_section_or_record(const ContactRun& run) {
  if (run.evaluation_section) return *run.evaluation_section;
  const auto& x = run.pantographs.front().position;  // the reader refuses a run without any
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  return {*lo, *hi};
}

}  // namespace catena::io
