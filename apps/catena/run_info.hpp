#pragma once
// Facts about a run stored in its output file.
#include "catena/assembly/second_order_system.hpp"
#include "catena/io/static_result.hpp"
#include "cli.hpp"

namespace catena::app {

// Not collective. "0.1.0 (<git describe>)", as stored in outputs and checkpoints.
std::string code_version();

// Collective (reads the PETSc options database).
io::RunInfo run_info(const CommandLine& cl, const assembly::SecondOrderSystem& system);

}  // namespace catena::app
