#include "catena/io/run_files.hpp"

#include <hdf5.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <random>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "hdf5_attributes.hpp"
#include "hdf5_error.hpp"
#include "hdf5_handles.hpp"
#include "transient_layout.hpp"

namespace catena::io {
namespace fs = std::filesystem;

std::string partial_output_path(const std::string& output_path) {
  const fs::path p(output_path);
  fs::path partial = p.parent_path() / p.stem();
  partial += ".part";
  partial += p.extension();
  return partial.string();
}

std::string new_run_id(MPI_Comm comm) {
  std::string id;
  if (mpi_rank(comm) == 0) {
    std::random_device entropy;
    std::uniform_int_distribution<std::uint32_t> word;
    char text[40];
    std::snprintf(text, sizeof text, "%08x%08x%08x%08x", word(entropy), word(entropy),
                  word(entropy), word(entropy));
    id = text;
  }
  broadcast_string(comm, id, 0);
  return id;
}

std::string read_run_id(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return "";
  const Hdf5ErrorPrintingSuppressed quiet;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) return "";
  const FileHandle owned(file);
  try {
    return read_string_attribute({file, path}, transient_layout::root_attribute::run_id)
        .value_or("");
  } catch (const Error&) {
    return "";  // not a string: no Catena time series
  }
}

int remove_abandoned_checkpoint_temporaries(const std::string& output_path) {
  const fs::path checkpoint(checkpoint_path(output_path));
  const fs::path dir = checkpoint.has_parent_path() ? checkpoint.parent_path() : fs::path(".");
  const std::string prefix = checkpoint.filename().string() + ".tmp-";
  int removed = 0;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) == 0 && entry.is_regular_file(ec) && fs::remove(entry.path(), ec))
      ++removed;
  }
  return removed;
}

}  // namespace catena::io
