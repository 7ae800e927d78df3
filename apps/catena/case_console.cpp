#include "case_console.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>

#include "catena/core/error.hpp"

namespace catena::app {
namespace {

// Writes all of [data, data + n) to fd (retrying short writes); errors are ignored: a full
// disk costs the log, not the case.
void write_all(int fd, const char* data, std::size_t n) {
  while (n > 0) {
    const ssize_t written = ::write(fd, data, n);
    if (written <= 0) return;
    data += written;
    n -= static_cast<std::size_t>(written);
  }
}

}  // namespace

CaseConsole::CaseConsole(const std::filesystem::path& log, std::string case_name)
    : case_name_(std::move(case_name)) {
  log_ = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (log_ < 0) throw Error("cannot open the case log " + log.string());
  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0) {
    ::close(log_);
    throw Error("cannot open a pipe for the case log " + log.string());
  }
  std::fflush(stdout);
  std::fflush(stderr);
  saved_out_ = ::dup(STDOUT_FILENO);
  saved_err_ = ::dup(STDERR_FILENO);
  if (saved_out_ < 0 || saved_err_ < 0) {
    for (int fd : {saved_out_, saved_err_, pipe_fds[0], pipe_fds[1], log_})
      if (fd >= 0) ::close(fd);
    throw Error("cannot keep the console while writing the case log " + log.string());
  }
  const int read_end = pipe_fds[0];
  // The copier first, so that nothing is redirected into a pipe that no one reads.
  copier_ = std::thread([this, read_end] { copy_lines(read_end, log_, saved_out_); });
  ::dup2(pipe_fds[1], STDOUT_FILENO);
  ::dup2(pipe_fds[1], STDERR_FILENO);
  ::close(pipe_fds[1]);
}

CaseConsole::~CaseConsole() {
  std::fflush(stdout);
  std::fflush(stderr);
  // The pipe's last write ends close here: the copier reads to its end and stops.
  ::dup2(saved_out_, STDOUT_FILENO);
  ::dup2(saved_err_, STDERR_FILENO);
  copier_.join();
  ::close(saved_out_);
  ::close(saved_err_);
  ::close(log_);
}

// Every byte goes to the log; each whole line that starts with "progress:" also goes to
// the console, after "study: CASE ".
void CaseConsole::copy_lines(int from, int log, int console) const {
  static constexpr char progress[] = "progress:";
  std::string line;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(from, buffer, sizeof buffer);
    if (n <= 0) break;
    write_all(log, buffer, static_cast<std::size_t>(n));
    for (ssize_t i = 0; i < n; ++i) {
      line += buffer[i];
      if (buffer[i] != '\n') continue;
      if (line.rfind(progress, 0) == 0) {
        const std::string shown = "study: " + case_name_ + " " + line;
        write_all(console, shown.data(), shown.size());
      }
      line.clear();
    }
  }
  ::close(from);
}

}  // namespace catena::app
