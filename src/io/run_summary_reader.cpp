#include "catena/io/run_summary_reader.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "catena/core/error.hpp"
#include "hdf5_error.hpp"
#include "time_series_file.hpp"
#include "transient_layout.hpp"

namespace catena::io {
namespace {

namespace layout = transient_layout;

// Samples read at once when scanning every node's positions: the memory is 256 × n_nodes × 3
// doubles (30 MB for 5000 nodes), whatever the record's length.
constexpr hsize_t samples_per_block = 256;

TimeSeriesFile open_complete(const std::string& path) {
  TimeSeriesFile r(path);
  layout::require_transient_format(r.root(), path);
  check_is_complete_dynamic_output(r);
  return r;
}

std::int64_t work_count(const TimeSeriesFile& r, const char* name) {
  if (!r.has_attribute(r.root(), name))
    r.fail(name, "missing: the run's work statistics were not written (an older Catena?)");
  return static_cast<std::int64_t>(std::llround(r.number_attribute<double>(r.root(), name, name)));
}

// (n_samples, n_nodes) of /samples/positions, checked against /time and /mesh/node_ids.
std::pair<hsize_t, hsize_t> positions_shape(const TimeSeriesFile& r) {
  const char* positions = layout::positions.path;
  const char* ids = layout::node_ids.path;
  const std::vector<hsize_t> n_samples = r.dims(layout::time.path);
  const std::vector<hsize_t> n_nodes = r.dims(ids);
  if (n_samples.size() != 1 || n_nodes.size() != 1) r.fail(ids, "not one-dimensional");
  if (r.dims(positions) != std::vector<hsize_t>{n_samples[0], n_nodes[0], 3})
    r.fail(positions, "not of shape (n_samples, n_nodes, 3)");
  return {n_samples[0], n_nodes[0]};
}

}  // namespace

RunWork read_run_work(const std::string& path) {
  const Hdf5ErrorPrintingSuppressed quiet;
  const TimeSeriesFile r = open_complete(path);
  RunWork w;
  w.t_reached = r.number_attribute<double>(r.root(), "t_reached", "t_reached");
  w.wall_seconds = r.number_attribute<double>(r.root(), "wall_seconds", "wall_seconds");
  w.stepping_seconds = w.wall_seconds;
  if (r.has_attribute(r.root(), "stepping_wall_seconds")) {
    w.stepping_seconds =
        r.number_attribute<double>(r.root(), "stepping_wall_seconds", "stepping_wall_seconds");
    w.t_started = r.number_attribute<double>(r.root(), "t_started", "t_started");
  }
  w.n_ranks = r.number_attribute<std::int64_t>(r.root(), layout::root_attribute::n_ranks,
                                               layout::root_attribute::n_ranks);
  w.n_dofs = r.number_attribute<std::int64_t>(r.root(), layout::root_attribute::n_dofs,
                                              layout::root_attribute::n_dofs);
  w.steps_accepted = work_count(r, "steps_accepted");
  w.steps_rejected = work_count(r, "steps_rejected");
  w.newton_iterations = work_count(r, "newton_iterations");
  w.residual_evaluations = work_count(r, "residual_evaluations");
  w.factorizations = work_count(r, "factorizations");
  w.linear_solves = work_count(r, "linear_solves");
  w.has_pantographs = r.has_link(layout::contact_force.path);
  return w;
}

NodeTrack read_node_track(const std::string& path, std::int64_t node_id) {
  const Hdf5ErrorPrintingSuppressed quiet;
  const TimeSeriesFile r = open_complete(path);
  const auto [n_samples, n_nodes] = positions_shape(r);
  const std::vector<std::int64_t> ids = r.integers(layout::node_ids.path, {n_nodes});
  const auto at = std::find(ids.begin(), ids.end(), node_id);
  if (at == ids.end()) {
    std::string some;
    for (std::size_t i = 0; i < std::min<std::size_t>(ids.size(), 5); ++i)
      some += (i ? ", " : "") + std::to_string(ids[i]);
    throw InputError({path, 0, "--probe"},
                     "no node with id " + std::to_string(node_id) + " (the run's " +
                         std::to_string(ids.size()) + " nodes have ids " + some +
                         (ids.size() > 5 ? ", ...; catena check --ids lists a catenary's)" : ")"));
  }
  NodeTrack track;
  track.node_id = node_id;
  track.time = r.doubles(layout::time.path, {n_samples});
  const hsize_t row = static_cast<hsize_t>(at - ids.begin());
  track.positions = r.block(layout::positions.path, {0, row, 0}, {n_samples, 1, 3});
  const std::vector<double> x = r.block(layout::node_positions.path, {row, 0}, {1, 3});
  track.reference_position = {x[0], x[1], x[2]};
  return track;
}

std::int64_t node_at(const std::string& path, const std::array<double, 3>& position,
                     double tolerance) {
  const Hdf5ErrorPrintingSuppressed quiet;
  const TimeSeriesFile r = open_complete(path);
  const auto [n_samples, n_nodes] = positions_shape(r);
  const std::vector<std::int64_t> ids = r.integers(layout::node_ids.path, {n_nodes});
  const std::vector<double> x = r.doubles(layout::node_positions.path, {n_nodes, 3});
  double nearest = HUGE_VAL;
  std::size_t found = 0;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    double d2 = 0.0;
    for (std::size_t c = 0; c < 3; ++c)
      d2 += (x[3 * i + c] - position[c]) * (x[3 * i + c] - position[c]);
    if (d2 < nearest) {
      nearest = d2;
      found = i;
    }
  }
  if (ids.empty() || std::sqrt(nearest) > tolerance) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "no node at the probe's point (%.9g, %.9g, %.9g) m (the nearest is %.3g m "
                  "away): a mesh that does not hold the reference's probe node",
                  position[0], position[1], position[2], std::sqrt(nearest));
    throw InputError({path, 0, "--probe"}, text);
  }
  return ids[found];
}

std::int64_t most_displaced_node(const std::string& path) {
  const Hdf5ErrorPrintingSuppressed quiet;
  const TimeSeriesFile r = open_complete(path);
  const auto [n_samples, n_nodes] = positions_shape(r);
  const std::vector<std::int64_t> ids = r.integers(layout::node_ids.path, {n_nodes});
  if (n_nodes == 0 || n_samples == 0) r.fail(layout::positions.path, "no nodes or no samples");
  const std::vector<double> first = r.block(layout::positions.path, {0, 0, 0}, {1, n_nodes, 3});
  std::vector<double> farthest(n_nodes, 0.0);
  for (hsize_t k0 = 0; k0 < n_samples; k0 += samples_per_block) {
    const hsize_t count = std::min(samples_per_block, n_samples - k0);
    const std::vector<double> block =
        r.block(layout::positions.path, {k0, 0, 0}, {count, n_nodes, 3});
    for (hsize_t k = 0; k < count; ++k)
      for (hsize_t i = 0; i < n_nodes; ++i) {
        double d2 = 0.0;
        for (hsize_t c = 0; c < 3; ++c) {
          const double e = block[(k * n_nodes + i) * 3 + c] - first[i * 3 + c];
          d2 += e * e;
        }
        farthest[i] = std::max(farthest[i], d2);
      }
  }
  const auto most = std::max_element(farthest.begin(), farthest.end());
  return ids[static_cast<std::size_t>(most - farthest.begin())];
}

}  // namespace catena::io
