#pragma once
// The io layer's side of the write-fault testing hook (catena/io/write_fault_injection.hpp).
#include <string_view>

#include "catena/io/write_fault_injection.hpp"

namespace catena::io {

// Not collective. Counts a write call (`call`: "H5Dwrite", "H5Fflush" or "H5Fclose") on
// this rank and says whether it must report failure. Other calls are not counted.
bool write_fault_injected(std::string_view call, std::string_view file, std::string_view object);

}  // namespace catena::io
