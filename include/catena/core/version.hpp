#pragma once
// The code version recorded in every output file and printed by the apps. Defined in a
// source generated at configure time (src/core/version.cpp.in), so that a new commit
// recompiles one file, not every file that sees a compile definition.
namespace catena {

const char* version();      // the project version, e.g. "0.1.0"
const char* git_version();  // `git describe --always --dirty --tags` at configure time

}  // namespace catena
