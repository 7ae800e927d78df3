# FindMETIS: METIS (libmetis-dev on Debian ships neither a CMake package nor a pkg-config
# file). Defines the imported target METIS::METIS and METIS_FOUND; the cache variables
# METIS_INCLUDE_DIR and METIS_LIBRARY point it elsewhere.
#
# Used by Catena's build and by the installed CatenaConfig.cmake: the exported catena_assembly
# links METIS::METIS, which each machine finds anew, rather than the absolute path of the
# library on the machine that built Catena.
find_path(METIS_INCLUDE_DIR metis.h)
find_library(METIS_LIBRARY metis)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(METIS REQUIRED_VARS METIS_LIBRARY METIS_INCLUDE_DIR)
mark_as_advanced(METIS_INCLUDE_DIR METIS_LIBRARY)
if(METIS_FOUND AND NOT TARGET METIS::METIS)
  add_library(METIS::METIS UNKNOWN IMPORTED)
  set_target_properties(METIS::METIS PROPERTIES IMPORTED_LOCATION "${METIS_LIBRARY}"
                                                INTERFACE_INCLUDE_DIRECTORIES "${METIS_INCLUDE_DIR}")
endif()
