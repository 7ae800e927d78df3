#include "plot_script.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <system_error>

namespace catena::app {

namespace {

// The script SCRIPT: installed beside the executable (CATENA_INSTALLED_SCRIPTS, relative
// to the directory of /proc/self/exe, or absolute), else in the source tree's apps/ (a
// catena run from its build tree). Neither readable: the installed path if this catena is
// installed (its scripts' directory exists), else the source tree's, for the message.
std::string script_path(const std::string& script) {
  namespace fs = std::filesystem;
  const fs::path source = fs::path(CATENA_SOURCE_DIR) / "apps" / script;
  std::error_code error;
  const fs::path exe = fs::read_symlink("/proc/self/exe", error);
  if (error) return source.string();
  const fs::path dir = (exe.parent_path() / CATENA_INSTALLED_SCRIPTS).lexically_normal();
  const fs::path installed = dir / script;
  if (access(installed.c_str(), R_OK) == 0) return installed.string();
  if (access(source.c_str(), R_OK) != 0 && fs::is_directory(dir, error)) return installed.string();
  return source.string();
}

constexpr const char* python = "/usr/bin/python3";

// Runs `python SCRIPT ARGS...` without a shell and waits for it: its exit status (-1 when
// the script is not readable or the interpreter cannot start). `quiet`: its output goes to
// /dev/null.
int run_script(const std::string& path, const std::vector<std::string>& args, bool quiet) {
  if (access(path.c_str(), R_OK) != 0) return -1;
  std::vector<std::string> words = {python, path};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (quiet) {
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  }
  std::fflush(stdout);  // the script's lines follow ours
  pid_t pid = 0;
  int status = -1;
  if (posix_spawn(&pid, python, &actions, nullptr, argv.data(), environ) == 0)
    waitpid(pid, &status, 0);
  posix_spawn_file_actions_destroy(&actions);
  return status;
}

}  // namespace

void draw_plot(const std::string& script, const std::vector<std::string>& args,
               const std::string& png) {
  const std::string path = script_path(script);
  if (run_script(path, args, true) == 0) {
    std::printf("plot: %s\n", png.c_str());
    return;
  }
  std::string command = std::string(python) + " " + path;
  for (const std::string& a : args) command += " " + a;
  std::printf("plot: not drawn (needs %s with matplotlib): %s\n", python, command.c_str());
}

bool draw_figures(const std::string& script, const std::vector<std::string>& args) {
  const std::string path = script_path(script);
  if (access(path.c_str(), R_OK) != 0) {
    std::fprintf(stderr, "catena: the plot script %s is missing\n", path.c_str());
    return false;
  }
  const int status = run_script(path, args, false);
  if (status == -1)
    std::fprintf(stderr,
                 "catena: cannot start %s (install Debian's python3-matplotlib and "
                 "python3-h5py)\n",
                 python);
  return status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace catena::app
