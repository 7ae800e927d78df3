// A program using the installed Catena libraries: a scene parsed from text (model), the
// zero-phase Butterworth filter and the EN 50318 statistics (post) on a synthetic contact
// force. Exit 0 when every check holds, 1 otherwise (each failure named on stderr).
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <exception>
#include <vector>

#include "catena/core/version.hpp"
#include "catena/model/scene_reader.hpp"
#include "catena/post/butterworth.hpp"
#include "catena/post/contact_statistics.hpp"

namespace {

const char* const scene = R"(name: a wire between two pins
sections:
  cw: {type: cable, EA: 1.8e7, EI: 195, mass_per_length: 1.35}
nodes:
  - {id: 1, position: [0, 0, 0]}
  - {id: 2, position: [50, 0, 0]}
lines:
  - {name: cw, from: 1, to: 2, elements: 10, section: cw, tension: 20000}
supports:
  - {node: 1, fix: pinned}
  - {node: 2, fix: pinned}
output:
  file: out.h5
)";

int failures = 0;

void check(bool holds, const char* what) {
  if (holds) return;
  std::fprintf(stderr, "catena_consumer: FAILED: %s\n", what);
  ++failures;
}

}  // namespace

int main() try {
  namespace post = catena::post;
  check(std::strcmp(catena::version(), CATENA_EXPECTED_VERSION) == 0,
        "the library's version is the package's");

  // 10 elements generated along the line: 11 nodes.
  const catena::model::Model model = catena::model::parse_scene(scene, "consumer.yaml");
  check(model.elements.size() == 10 && model.nodes.size() == 11, "the scene's 10 elements");

  // A constant force of 120 N, sampled every 1 ms for 2 s at 20 m/s (0 to 39.98 m).
  const double dt = 1e-3, force = 120.0, speed = 20.0;
  post::PantographRecord record{"leading", speed, std::vector<double>(2000, force), {}};
  for (std::size_t k = 0; k < record.force.size(); ++k)
    record.position.push_back(speed * dt * static_cast<double>(k));

  // The zero-phase filter passes a constant unchanged.
  const std::vector<double> filtered = post::butterworth_lowpass_zero_phase(record.force, dt, 20.0);
  double worst = 0.0;
  for (double f : filtered) worst = std::fmax(worst, std::fabs(f - force));
  check(filtered.size() == record.force.size() && worst < 1e-9, "a constant passes unchanged");

  // Its statistics over [5, 35] m (samples 250 to 1750): the force, no spread, no loss.
  post::ContactStatisticsOptions options;
  options.dt = dt;
  options.section = {5.0, 35.0};
  const post::ContactStatistics s = post::contact_statistics(record, {}, options);
  check(s.n_samples == 1501, "1501 samples in the section");
  check(std::fabs(s.mean - force) < 1e-9 && s.standard_deviation < 1e-9, "mean 120 N, sigma 0");
  check(s.contact_loss_percent == 0.0 && !s.max_uplift_at_support, "no loss, no support");

  std::printf("catena_consumer: Catena %s (%s): %s\n", catena::version(), catena::git_version(),
              failures == 0 ? "every check holds" : "FAILED");
  return failures == 0 ? 0 : 1;
} catch (const std::exception& e) {
  std::fprintf(stderr, "catena_consumer: %s\n", e.what());
  return 1;
}
