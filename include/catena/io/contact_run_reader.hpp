#pragma once
// Reading what `catena stats` needs from a dynamic run's time-series file (docs/output.md,
// "Contact forces and pantographs"; the names: src/io/transient_layout.hpp): the sampling,
// the pantographs' contact force and position, the evaluation section and the registration
// points' heights. Serial HDF5 (default file access), for one rank.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "catena/post/contact_statistics.hpp"

namespace catena::io {

struct ContactRun {
  // The root attribute status: "complete", or for an unfinished run read with
  // UnfinishedRuns::accepted "running" (still running, or it crashed: the record holds the
  // data up to its last flush), "interrupted" or "failed: <why>".
  std::string status;
  double t_end = 0.0;        // s, the time of the record's last sample
  std::vector<double> time;  // s, of every sample (of every step with the steps' series)
  // The acceptance ranges the scene declared (catenary.acceptance, root attribute
  // acceptance): "en50318", or empty.
  std::string acceptance;
  std::size_t n_samples = 0;
  double dt = 0.0;  // s, the (uniform) sampling interval of /time
  // The root attributes evaluation_start/evaluation_end; none if absent or both 0.
  std::optional<post::EvaluationSection> evaluation_section;
  std::vector<post::PantographRecord> pantographs;  // in column order (attribute index)
  bool has_registration_nodes = false;              // the file has /mesh/registration_nodes
  std::vector<post::RegistrationPoint> registration_points;  // one per registration node
};

// Not collective. The run's evaluation section, or, when it sets none, the range of contact
// positions its first pantograph covers (the whole record): what `catena study` and
// `catena sweep` evaluate over.
post::EvaluationSection evaluation_section_or_record(const ContactRun& run);

// Whether a run that did not complete is read (its record so far) or refused.
enum class UnfinishedRuns { refused, accepted };

// Not collective. Reads `path`; throws catena::InputError naming the file (and the object)
// if it is missing, not HDF5, not a Catena time series of this format (root attribute
// `format`: the one found and the one expected), not complete (status; unless `unfinished`
// is accepted), has no pantographs, is not uniformly sampled or its datasets' shapes
// disagree.
ContactRun read_contact_run(const std::string& path,
                            UnfinishedRuns unfinished = UnfinishedRuns::refused);

// Not collective. As read_contact_run, on the time base of the accepted steps instead of the
// samples (`catena stats --series steps`): the contact force of every step (/steps/
// contact_force: a fixed-step run has it at every dt, whatever output.interval), the
// sample at t = 0 first; the contact positions (linear in time) interpolated from the
// samples; the registration points' heights of every step (/steps/registration_height), or
// interpolated from the samples in a file without them (an older Catena), whose uplift is
// then only as fine as its output interval. A last step cut short to reach the duration is
// left out, and so are the steps of an unfinished run beyond its last sample (flushed
// before it). Throws InputError as above, and if the steps are not uniform (an adaptive run).
ContactRun read_contact_run_steps(const std::string& path,
                                  UnfinishedRuns unfinished = UnfinishedRuns::refused);

// Not collective. Whether the HDF5 file at `path` holds contact forces (/samples/
// contact_force: a dynamic run with pantographs). Throws catena::InputError naming the file
// when it is missing or not HDF5.
bool has_contact_forces(const std::string& path);

// Not collective. Throws catena::InputError naming `path` and its `format` unless it is a
// dynamic run's output or a static result (what `catena plot` draws): a modes file, a
// checkpoint or a file of another program is refused before the plot script reads it.
void require_run_or_static_result(const std::string& path);

// Not collective. The dataset ContactRun::dt comes from ("/time"), for messages naming it.
const char* contact_run_times_dataset();

}  // namespace catena::io
