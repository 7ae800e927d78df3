#pragma once
// What `catena study` leaves and prints once every case has run: DIR/study.csv, the table,
// the reference's check, the recommendation for the --target accuracy, DIR/study.png.
#include <filesystem>
#include <string>
#include <vector>

#include "catena/study/case_measures.hpp"
#include "catena/study/study_table.hpp"
#include "cli.hpp"

namespace catena::app {

// Not collective (rank 0). Throws catena::Error if study.csv cannot be written.
void write_study_report(const CommandLine& cl, const std::vector<study::StudyRow>& rows,
                        const study::ReferenceRun& reference,
                        const std::filesystem::path& directory,
                        const std::string& reference_description);

}  // namespace catena::app
