#include "cli.hpp"

#include "catena/core/error.hpp"

namespace catena::app {

std::string usage() {
  return R"(catena — parallel solver for cables, beams and overhead contact lines

Usage:
  catena run   SCENE.yaml [-o OUT.h5] [--set KEY=VALUE ...] [--restart] [PETSc options]
  catena check SCENE.yaml [--set KEY=VALUE ...]
  catena --help

Commands:
  run     solve the scene (static equilibrium) and write OUT.h5 (+ OUT.xmf for ParaView)
  check   validate the scene and print what would be modelled, without solving

Options:
  -o, --output FILE     output file (default: the scene's output.file, else catena.h5)
  --set KEY=VALUE       override a scene value, e.g. --set lines[0].elements=400
                        --set sections.cw.EA=2e7 (validated like the file; repeatable)
  --restart             dynamics: continue from the checkpoint OUT.h5.chk, appending to
                        OUT.h5 (same scene; analysis.duration may be raised)
  -h, --help            this text

PETSc options (prefix -static_ for the static solver), e.g.:
  -static_snes_monitor -static_ksp_view -log_view -static_mat_mumps_icntl_4 2

Examples:
  catena check meshes/default.yaml
  mpirun -n 2 catena run meshes/default.yaml -o default.h5
  mpirun -n 4 catena run meshes/default.yaml --set lines[0].elements=2000 -log_view
)";
}

namespace {
bool is_scene_path(const std::string& token) {
  auto ends_with = [&](const std::string& suffix) {
    return token.size() >= suffix.size() &&
           token.compare(token.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  return ends_with(".yaml") || ends_with(".yml");
}
}  // namespace

CommandLine parse_command_line(int argc, char** argv) {
  CommandLine cl;
  for (int i = 0; i < argc; ++i) {
    if (i > 0) cl.joined += ' ';
    cl.joined += argv[i];
  }
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    // No arguments: run the shipped default scene (style.md: every app runs with none).
    cl.command = "run";
    cl.scene = "meshes/default.yaml";
    return cl;
  }
  size_t i = 0;
  if (args[0] == "-h" || args[0] == "--help" || args[0] == "help") {
    cl.command = "help";
    return cl;
  }
  cl.command = args[i++];
  if (cl.command != "run" && cl.command != "check")
    throw InputError({"", 0, "command"}, "unknown command '" + cl.command +
                                             "'; accepted: run, check, --help");
  for (; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](const char* flag) -> std::string {
      if (i + 1 >= args.size())
        throw InputError({"", 0, flag}, std::string("missing value after ") + flag);
      return args[++i];
    };
    if (a == "-h" || a == "--help") {
      cl.command = "help";
      return cl;
    } else if (a == "--set") {
      cl.overrides.push_back(value("--set"));
    } else if (a.rfind("--set=", 0) == 0) {
      cl.overrides.push_back(a.substr(6));
    } else if (a == "--restart") {
      cl.restart = true;
    } else if (a == "-o" || a == "--output") {
      cl.output = value("-o");
    } else if (!a.empty() && a[0] == '-') {
      // A PETSc option; skip its value if it has one: the next token, unless it starts
      // with '-' or names the scene file (a .yaml/.yml path).
      if (i + 1 < args.size() && !args[i + 1].empty() && args[i + 1][0] != '-' &&
          !(cl.scene.empty() && is_scene_path(args[i + 1])))
        ++i;
    } else if (cl.scene.empty()) {
      cl.scene = a;
    } else {
      throw InputError({"", 0, "arguments"}, "unexpected argument '" + a +
                                                 "': one scene file is accepted (got '" +
                                                 cl.scene + "' already)");
    }
  }
  if (cl.scene.empty())
    throw InputError({"", 0, "SCENE"}, "no scene file given; usage: catena " + cl.command +
                                           " SCENE.yaml");
  if (cl.output) cl.overrides.push_back("output.file=" + *cl.output);
  return cl;
}

}  // namespace catena::app
