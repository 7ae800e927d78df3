#pragma once
// While a `catena study` case runs, this process's console output goes to the case's log;
// its progress lines ("progress: ...", docs/output.md) are also shown on the study's
// console, prefixed with the case's name, so that a long case is seen to advance. Each
// process belongs to one group, so two cases' outputs never mix in one log.
#include <filesystem>
#include <string>
#include <thread>

namespace catena::app {

class CaseConsole {
 public:
  // Not collective. Throws catena::Error if the log or the pipe cannot be opened.
  CaseConsole(const std::filesystem::path& log, std::string case_name);
  // Restores stdout and stderr and waits until everything written is in the log.
  ~CaseConsole();
  CaseConsole(const CaseConsole&) = delete;
  CaseConsole& operator=(const CaseConsole&) = delete;

 private:
  void copy_lines(int from, int log, int console) const;

  std::string case_name_;
  int saved_out_ = -1;
  int saved_err_ = -1;
  int log_ = -1;
  std::thread copier_;
};

}  // namespace catena::app
