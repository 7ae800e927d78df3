// `catena elasticity SCENE [--set k=v ...] [--span N] [--step DX] [--force F] [--json]`:
// the static elasticity curve of one span of a catenary scene (docs/catenary.md,
// "Elasticity"). The scene's catenary is built and shaped as `catena run` does it
// (shape_catenary), its static equilibrium solved, and then, for points every DX along
// the span from support to support, the equilibrium with a static upward force F at the
// point (catenary::static_elasticity). Only the static structure counts: the scene's
// pantographs and moving loads are left out, its dynamic settings unused.
//
//   catena elasticity meshes/simple_catenary.yaml
//   mpirun -n 2 catena elasticity meshes/simple_catenary.yaml --span 6 --step 0.5 --json
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "catena/catenary/static_elasticity.hpp"
#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/core/version.hpp"
#include "catena/post/elasticity_summary.hpp"
#include "commands.hpp"
#include "elasticity_report.hpp"
#include "log_stage.hpp"
#include "scene_loading.hpp"
#include "shape_report.hpp"

namespace catena::app {
namespace {

// At most this many points per span (a guard against a mistyped --step).
constexpr std::size_t kMaxPoints = 100000;

// The scene as a static catenary, and what of it was left out.
struct StaticCatenary {
  model::Model model;
  std::size_t n_pantographs = 0, n_moving_loads = 0;
  bool dynamic = false;
};

// Collective. Pantographs are more than their contact (nodes, springs, masses, loads),
// so a scene with any is read again with `pantographs: []`: the structure without them,
// numbered as the reader numbers it.
StaticCatenary load_static_catenary(MPI_Comm comm, const CommandLine& cl) {
  StaticCatenary s{load_scene(comm, cl.scene, cl.overrides)};
  if (!s.model.catenary)
    throw InputError({cl.scene, 0, "catenary"},
                     "missing: catena elasticity needs a scene with a `catenary` key (a "
                     "contact wire on spans between supports; docs/scene.md \"catenary\")");
  s.n_pantographs = s.model.contacts.size();
  s.n_moving_loads = s.model.moving_loads.size();
  s.dynamic = s.model.analysis == model::AnalysisType::dynamic;
  if (s.n_pantographs > 0) {
    std::vector<std::string> overrides = cl.overrides;
    overrides.push_back("pantographs=[]");
    s.model = load_scene(comm, cl.scene, overrides);
  }
  s.model.moving_loads.clear();
  return s;
}

// The span asked for, or the first evaluation span, or the middle one (1-based).
int chosen_span(const CommandLine& cl, const model::Model& m,
                const std::vector<double>& support_arc) {
  const int n_spans = static_cast<int>(support_arc.size()) - 1;
  if (const auto& requested = cl.elasticity.span) {
    if (*requested > n_spans)
      throw InputError({"", 0, "--span"},
                       "span " + std::to_string(*requested) + " does not exist; accepted: 1 to " +
                           std::to_string(n_spans) + " (the catenary of " + cl.scene + " has " +
                           std::to_string(n_spans) + " spans)");
    return *requested;
  }
  if (m.evaluation_end > m.evaluation_start)
    for (int j = 0; j < n_spans; ++j)
      if (std::abs(support_arc[static_cast<std::size_t>(j)] - m.evaluation_start) < 1e-9)
        return j + 1;
  return (n_spans + 1) / 2;
}

std::string short_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// m along the span from its start support: every `step`, and the end support.
std::vector<double> span_points(double length, double step) {
  const double smallest = length / static_cast<double>(kMaxPoints - 1);
  const std::string accepted = "; accepted: " + short_number(smallest) + " m (" +
                               std::to_string(kMaxPoints) + " points) to " + short_number(length) +
                               " m (the span length)";
  if (step > length)
    throw InputError({"", 0, "--step"},
                     "a step of " + short_number(step) + " m is longer than the span" + accepted);
  const double n = std::floor(length / step * (1.0 + 1e-12));
  if (n + 1.0 > static_cast<double>(kMaxPoints))
    throw InputError({"", 0, "--step"},
                     "a step of " + short_number(step) + " m makes too many points" + accepted);
  std::vector<double> x;
  for (int k = 0; k <= static_cast<int>(n); ++k) x.push_back(std::min(k * step, length));
  if (length - x.back() > 1e-9 * length) x.push_back(length);
  return x;
}

}  // namespace

void command_elasticity(MPI_Comm comm, const CommandLine& cl) {
  const ElasticityArguments& args = cl.elasticity;
  const int rank = mpi_rank(comm);
  std::FILE* info = args.json ? stderr : stdout;  // stdout carries only the JSON
  StaticCatenary scene = load_static_catenary(comm, cl);
  model::Model& m = scene.model;
  const std::vector<int>& path = m.catenary->contact_wire.elements;
  std::vector<double> support_arc;  // m along the contact wire, at each support
  for (const int node : m.registration_nodes)
    support_arc.push_back(catenary::path_arc_length_at(m, path, node));
  const int span = chosen_span(cl, m, support_arc);
  const std::vector<double>& support_x = m.catenary->support_x;
  const auto j = static_cast<std::size_t>(span);
  // x runs along the track; a staggered wire runs straight but slightly longer in the span.
  const double length = support_x[j] - support_x[j - 1];
  const double wire_per_track = (support_arc[j] - support_arc[j - 1]) / length;
  const std::vector<double> x = span_points(length, args.step);

  if (rank == 0) {
    std::fprintf(info,
                 "catena %s (%s): elasticity of scene %s '%s', span %d of %zu (x = %g to %g m), "
                 "%zu points every %g m, static upward force %g N, %d ranks\n",
                 version(), git_version(), cl.scene.c_str(), m.name.c_str(), span,
                 support_x.size() - 1, support_x[j - 1], support_x[j], x.size(), args.step,
                 args.force, mpi_size(comm));
    std::fprintf(info,
                 "  the static catenary alone: the scene's pantographs (%zu) and moving loads "
                 "(%zu) are ignored%s\n",
                 scene.n_pantographs, scene.n_moving_loads,
                 scene.dynamic ? ", and so is its dynamic analysis" : "");
    std::fflush(info);
  }
  shape_catenary(comm, m, info,
                 cl.progress_seconds);  // as `catena run`: dropper lengths, preloads, prestrains

  const double t0 = MPI_Wtime();
  catenary::ElasticityProbe probe;
  probe.path = path;
  for (const double xi : x) probe.positions.push_back(support_arc[j - 1] + xi * wire_per_track);
  probe.force = Vec3(0.0, 0.0, args.force);  // up: a catenary's z axis (docs/catenary.md)
  const catenary::ElasticityReport report = [&] {
    const LogStage stage("Elasticity");
    return catenary::static_elasticity(comm, m, probe);
  }();

  ElasticityCurve curve;
  curve.span = span;
  curve.force = args.force;
  curve.x = x;
  for (const catenary::ElasticityPoint& p : report.points) {
    curve.uplift.push_back(1e3 * p.uplift);
    curve.elasticity.push_back(1e3 * p.elasticity);
    curve.linear.push_back(1e3 * p.linear_elasticity);
    curve.slack.push_back(p.slackened);
  }
  curve.summary = post::summarize_elasticity(curve.elasticity);
  curve.linear_summary = post::summarize_elasticity(curve.linear);
  if (rank != 0) return;
  std::fprintf(info,
               "static equilibrium: %d load steps, %d Newton iterations; %zu loaded equilibria: "
               "%ld Newton iterations, %ld factorisations, %.2f s\n",
               report.base.n_load_steps, report.base.n_newton_iterations, report.points.size(),
               report.newton_iterations, report.factorizations, MPI_Wtime() - t0);
  std::fflush(info);
  if (args.json)
    print_elasticity_json(stdout, curve);
  else
    print_elasticity_table(stdout, curve);
  warn_slack_droppers(curve);
}

}  // namespace catena::app
