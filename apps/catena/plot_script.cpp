#include "plot_script.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>

namespace catena::app {

void draw_plot(const std::string& script, const std::vector<std::string>& args,
               const std::string& png) {
  const std::string python = "/usr/bin/python3";
  const std::string path = std::string(CATENA_SOURCE_DIR) + "/apps/" + script;
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

}  // namespace catena::app
