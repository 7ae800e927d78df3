#include "catena/io/error_bar_record.hpp"

#include <hdf5.h>

#include "catena/core/error.hpp"
#include "catena/io/output_error.hpp"
#include "hdf5_attributes.hpp"
#include "hdf5_error.hpp"
#include "hdf5_handles.hpp"

namespace catena::io {

void write_error_bar(const std::string& path, const ErrorBarRecord& record) {
  try {
    const Hdf5ErrorPrintingSuppressed quiet;
    const FileHandle file(
        checked_hdf5_id(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), "H5Fopen", path));
    if (H5Lexists(file.get(), "error_bar", H5P_DEFAULT) > 0)
      check_hdf5_status(H5Ldelete(file.get(), "error_bar", H5P_DEFAULT), "H5Ldelete", path,
                        "/error_bar");
    const GroupHandle group(
        checked_hdf5_id(H5Gcreate2(file.get(), "error_bar", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                        "H5Gcreate", path, "/error_bar"));
    const AttributeTarget at{group.get(), path};
    write_string_attribute(at, "method", "richardson");
    write_double_attribute(at, "dt", record.dt);
    for (std::size_t i = 0; i < record.coarse_dt.size(); ++i)
      write_double_attribute(at, ("coarse_dt_" + std::to_string(i + 1)).c_str(),
                             record.coarse_dt[i]);
    write_string_list_attribute(at, "coarse_files", record.coarse_files);
    for (const ErrorBarEntry& e : record.entries) {
      std::string name = e.part;
      for (char& c : name)
        if (c == '/') c = '_';
      const std::string object = "/error_bar/" + name;
      if (H5Lexists(group.get(), name.c_str(), H5P_DEFAULT) <= 0)
        GroupHandle(checked_hdf5_id(
            H5Gcreate2(group.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
            "H5Gcreate", path, object));
      const GroupHandle part(checked_hdf5_id(H5Gopen2(group.get(), name.c_str(), H5P_DEFAULT),
                                             "H5Gopen", path, object));
      const AttributeTarget on{part.get(), path};
      write_double_attribute(on, e.measure.c_str(), e.estimate);
      write_double_attribute(on, (e.measure + "_order").c_str(), e.order);
      write_string_attribute(on, (e.measure + "_unit").c_str(), e.unit);
    }
  } catch (const OutputError&) {
    throw;
  } catch (const Error& e) {
    throw OutputError(std::string("cannot store the error bar in ") + path + ": " + e.what());
  }
}

}  // namespace catena::io
