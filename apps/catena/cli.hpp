#pragma once
// Command-line parsing for the catena app. Arguments we do not recognise and that start
// with '-' are left to PETSc's options database (e.g. -static_snes_monitor, -log_view).
#include <optional>
#include <string>
#include <vector>

namespace catena::app {

struct CommandLine {
  std::string command;                 // run | check | help
  std::string scene;                   // scene file path
  std::vector<std::string> overrides;  // --set key=value, in order
  std::optional<std::string> output;   // -o FILE (same as --set output.file=FILE)
  bool restart = false;                // --restart: continue from OUT.h5.chk
  std::string joined;                  // the whole command line, for the output file
};

// Throws catena::InputError for malformed arguments.
CommandLine parse_command_line(int argc, char** argv);

std::string usage();

}  // namespace catena::app
