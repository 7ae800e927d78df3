#include "catena/io/hdf5_library.hpp"

#include <hdf5.h>

namespace catena::io {

void start_hdf5_before_mpi() {
  H5dont_atexit();
  H5open();
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

}  // namespace catena::io
