#include "log_stage.hpp"

#include <petsclog.h>

#include <map>
#include <string>

#include "catena/assembly/petsc_call.hpp"

namespace catena::app {

LogStage::LogStage(const char* name) {
  static std::map<std::string, PetscLogStage> stages;  // registered once each
  auto it = stages.find(name);
  if (it == stages.end()) {
    PetscLogStage stage = 0;
    CATENA_PETSC(PetscLogStageRegister(name, &stage));
    it = stages.emplace(name, stage).first;
  }
  CATENA_PETSC(PetscLogStagePush(it->second));
}

// Errors cannot be reported from a destructor (it may run while an exception unwinds).
LogStage::~LogStage() { (void)PetscLogStagePop(); }

}  // namespace catena::app
