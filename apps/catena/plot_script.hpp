#pragma once
// The plots of `catena study` and `catena sweep` are drawn by Python scripts shipped in
// apps/ (Debian's python3 and matplotlib: what the users' own post-processing uses).
#include <string>
#include <vector>

namespace catena::app {

// Not collective. Runs /usr/bin/python3 apps/SCRIPT ARGS... without a shell (any path is one
// argument), its output discarded, and says on stdout that `png` was drawn, or the command
// that would draw it. A failure costs the picture, not the command: said, not thrown.
void draw_plot(const std::string& script, const std::vector<std::string>& args,
               const std::string& png);

}  // namespace catena::app
