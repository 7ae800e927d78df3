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

}  // namespace

void draw_plot(const std::string& script, const std::vector<std::string>& args,
               const std::string& png) {
  const std::string python = "/usr/bin/python3";
  const std::string path = script_path(script);
  std::vector<std::string> words = {python, path};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  std::string command;
  for (std::string& w : words) {
    argv.push_back(w.data());
    command += (command.empty() ? "" : " ") + w;
  }
  argv.push_back(nullptr);
  posix_spawn_file_actions_t quiet;
  posix_spawn_file_actions_init(&quiet);
  posix_spawn_file_actions_addopen(&quiet, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&quiet, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  int status = -1;
  if (access(path.c_str(), R_OK) == 0 &&
      posix_spawn(&pid, python.c_str(), &quiet, nullptr, argv.data(), environ) == 0)
    waitpid(pid, &status, 0);
  posix_spawn_file_actions_destroy(&quiet);
  if (status == 0)
    std::printf("plot: %s\n", png.c_str());
  else
    std::printf("plot: not drawn (needs %s with matplotlib): %s\n", python.c_str(),
                command.c_str());
}

bool draw_figures(const std::string& script, const std::vector<std::string>& args) {
  const std::string python = "/usr/bin/python3";
  const std::string path = script_path(script);
  std::vector<std::string> words = {python, path};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  std::fflush(stdout);  // the script's lines follow ours
  pid_t pid = 0;
  int status = -1;
  if (access(path.c_str(), R_OK) != 0) {
    std::fprintf(stderr, "catena: the plot script %s is missing\n", path.c_str());
    return false;
  }
  if (posix_spawn(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ) != 0) {
    std::fprintf(stderr,
                 "catena: cannot start %s (install Debian's python3-matplotlib and "
                 "python3-h5py)\n",
                 python.c_str());
    return false;
  }
  waitpid(pid, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace catena::app
