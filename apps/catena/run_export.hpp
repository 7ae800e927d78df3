#pragma once
// The CSV files of `catena export` (docs/output.md, "Exports"): a run's contact-force series
// per pantograph and its statistics. `catena plot` draws from the same files.
#include <filesystem>
#include <string>

#include "run_statistics.hpp"

namespace catena::app {

// Not collective. PREFIX_contact.csv: one row per sample (per step with --series steps):
// t_s, then per pantograph NAME_position_m, NAME_force_N, NAME_force_filtered_N. Written
// atomically; throws catena::Error naming the file when it cannot be.
void write_contact_csv(const RunEvaluation& ev, const std::filesystem::path& path);

// Not collective. PREFIX_statistics.csv: one row per pantograph: the EN 50318 statistics
// over its section (empty cells where it did not reach it) and, with acceptance ranges,
// the ranges' name, the count in range and a 1/0 per statistic. Written atomically.
void write_statistics_csv(const RunEvaluation& ev, const std::filesystem::path& path);

// Not collective. Creates the directory `file` is to be written in, if missing. Throws
// catena::OutputError naming it when it cannot be created.
void create_parent_directory(const std::filesystem::path& file);

// Not collective. The default prefix of a run's derived files: OUT.h5 less its extension.
std::string default_prefix(const std::string& output_file);

}  // namespace catena::app
