# Writes the code version into OUTPUT from INPUT (src/core/version.cpp.in) at build time, so
# that every build records the commit it was built from, not the one of the last configure.
# configure_file rewrites OUTPUT only when its text changes: an unchanged version rebuilds
# nothing. Arguments: SOURCE_DIR, INPUT, OUTPUT, PROJECT_VERSION.
execute_process(COMMAND git describe --always --dirty --tags
                WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE CATENA_GIT_VERSION OUTPUT_STRIP_TRAILING_WHITESPACE
                ERROR_QUIET)
if(NOT CATENA_GIT_VERSION)
  set(CATENA_GIT_VERSION "unknown")
endif()
configure_file(${INPUT} ${OUTPUT} @ONLY)
