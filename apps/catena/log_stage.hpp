#pragma once
// A -log_view stage for the duration of a scope, so that -log_view reports each phase of a
// command (shape finding, statics, dynamics, output, elasticity) in its own section instead
// of one "Main Stage". Stages nest (output inside dynamics is output's).
namespace catena::app {

class LogStage {
 public:
  // Not collective, but every rank must open the same stages in the same order (PETSc
  // numbers stages by registration): the phases of a command are the same on every rank.
  explicit LogStage(const char* name);
  ~LogStage();
  LogStage(const LogStage&) = delete;
  LogStage& operator=(const LogStage&) = delete;
};

}  // namespace catena::app
