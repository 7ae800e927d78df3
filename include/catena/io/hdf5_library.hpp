#pragma once
// How an application starts the HDF5 library.
#include <string>

namespace catena::io {

// Not collective. Call once, first thing in main(), before MPI_Init (PetscInitialize).
//
// Starts HDF5 so that it never shuts itself down. HDF5 1.10 releases a file whose H5Fclose
// fails (a full disk: the last metadata cannot be written) but keeps its id; shutting the
// library down later closes that id again and crashes (a segfault in H5F__close_cb). HDF5
// shuts down at MPI_Finalize, through an attribute it puts on MPI_COMM_SELF when it starts
// after MPI_Init, and at exit unless told not to: started here, it does neither. Files are
// closed by their owners (RAII handles) as before; what the library holds goes with the
// process.
//
// Also turns off HDF5's printing of its error stack to stderr: the io layer reports every
// failure once, as an exception naming the call, the file and the cause.
void start_hdf5_before_mpi();

// Not collective. The HDF5 library's version, e.g. "1.10.8".
std::string hdf5_version();

}  // namespace catena::io
