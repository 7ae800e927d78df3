#pragma once
// What `catena stats`, `catena export` and `catena plot` compute from a dynamic run's
// output: per pantograph, the filtered contact force of the whole record, the EN 50318
// statistics over the evaluation section and, when the scene declares them (or --ranges),
// the acceptance ranges' checks. Each pantograph is evaluated over the part of the section
// its record covers: all of it for a complete run long enough, less for a run that did not
// complete (interrupted, failed, or crashed while running) or ended early, which the
// commands then say.
#include <optional>
#include <string>
#include <vector>

#include "catena/io/contact_run_reader.hpp"
#include "catena/post/contact_statistics.hpp"
#include "catena/post/en50318_ranges.hpp"
#include "cli.hpp"

namespace catena::app {

inline constexpr double kmh_per_ms = 3.6;  // a speed in m/s times this is in km/h

struct PantographEvaluation {
  const post::PantographRecord* pantograph = nullptr;  // in RunEvaluation::run
  // The section evaluated: the requested one cut to what the pantograph's record covers
  // (less the filter's end transient where the record ends inside it); empty (end before
  // start) when it covers none of it.
  post::EvaluationSection section;
  bool partial = false;  // the record covers less than the requested section
  // None: an unfinished run stopped before this pantograph reached the section.
  std::optional<post::ContactStatistics> statistics;
  // The acceptance ranges' checks at its speed; none without ranges or at another speed.
  std::optional<std::vector<post::AcceptanceCheck>> acceptance;
  std::vector<double> filtered_force;  // N, the whole record, low-pass filtered at the cutoff
};

struct RunEvaluation {
  io::ContactRun run;
  post::EvaluationSection section;  // requested: --section, else the run's
  bool section_given = false;       // by --section
  bool finished = true;             // status "complete"
  std::string ranges;               // the acceptance ranges applied ("en50318"), or empty
  // The series evaluated is every step's contact force (--series steps, or chosen because
  // the samples are too coarse for the cutoff: then `series_note` says so).
  bool steps = false;
  std::string series_note;
  std::vector<PantographEvaluation> pantographs;  // in column order
};

// What a pantograph's statistics are taken over.
enum class SectionCoverage {
  // The whole section of a complete run (`catena stats`: the statistics are the run's
  // answer), the part covered of an unfinished one.
  whole,
  // The part each pantograph covered, none where it covered nothing, and without a section
  // the whole record (`catena export` and `catena plot`: the series matter as much).
  covered,
};

// Not collective. Reads args.file and evaluates it. Throws catena::InputError naming the
// file and the dataset or option at fault (reader errors; a cutoff the sampling cannot
// carry; and with SectionCoverage::whole: no section, a finished run whose pantograph never
// lies in the section, an unfinished run none of whose pantographs reached it).
RunEvaluation evaluate_run(const StatsArguments& args,
                           SectionCoverage coverage = SectionCoverage::whole);

// Not collective. Throws catena::InputError naming OUT.part.h5 when `file` (OUT.h5) does
// not exist but the unfinished run's output does.
void refuse_unfinished_name(const std::string& file);

// Not collective. The zero-phase filter starts each pass from the record's end value: a
// record shorter than two periods of the cutoff is all start-up (a 0.2 s record at 0.001 Hz
// gave the first sample's force as mean, minimum and maximum, and σ = 0). Whether
// `cutoff_hz` is too low for a record of `record` s, and the lowest cutoff it takes (2/record
// rounded up to three significant digits: to nearest, 2/1.995 s printed 1 Hz, itself too low).
bool cutoff_too_low(double cutoff_hz, double record);
std::string lowest_cutoff_text(double record);

// Not collective. "8 of 8 in range" style count of `checks`.
std::size_t checks_passed(const std::vector<post::AcceptanceCheck>& checks);

}  // namespace catena::app
