#pragma once
// The plots of `catena study`, `catena sweep` and `catena plot` are drawn by Python scripts
// shipped in apps/ (Debian's python3 and matplotlib: what the users' own post-processing uses).
#include <string>
#include <vector>

namespace catena::app {

// Where SCRIPT is found: in share/catena beside the executable (an installed catena), else in
// the source tree's apps/ (a catena in its build tree).

// Not collective. Runs /usr/bin/python3 SCRIPT ARGS... without a shell (any path is one
// argument), its output discarded, and says on stdout that `png` was drawn, or the command
// that would draw it. A failure costs the picture, not the command: said, not thrown.
void draw_plot(const std::string& script, const std::vector<std::string>& args,
               const std::string& png);

// Not collective. Runs /usr/bin/python3 SCRIPT ARGS... without a shell, its output
// (the files it wrote, or its error) passed through; true when it exited 0.
bool draw_figures(const std::string& script, const std::vector<std::string>& args);

}  // namespace catena::app
