#pragma once
// The last lines of a pantograph run: its contact-force statistics per pantograph (and the
// acceptance count when the scene declares ranges), so that a user sees the answer without
// a second command; `catena stats` has the whole table.
#include <string>

namespace catena::app {

// Not collective (rank 0). Evaluates the run's output `file` as `catena stats` does at the
// default cutoff (over the part of the section each pantograph covered; the whole record
// without a section) and prints one line per pantograph. Never throws: what cannot be
// evaluated (a sampling too coarse for the cutoff) is said in a note instead.
void print_contact_summary(const std::string& file);

}  // namespace catena::app
