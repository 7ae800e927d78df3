#include "catena/io/error_bar_record.hpp"

#include <hdf5.h>

#include "catena/core/error.hpp"
#include "catena/io/output_error.hpp"
#include "hdf5_attributes.hpp"
#include "hdf5_error.hpp"
#include "hdf5_handles.hpp"

namespace catena::io {
namespace {

// The measures in the order they are written and shown.
constexpr const char* kMeasures[] = {"mean", "std",    "stat_max",           "stat_min", "max",
                                     "min",  "uplift", "force_rms_filtered", "probe_rms"};

double read_double(hid_t object, const char* name, const std::string& path,
                   const std::string& where) {
  const Hdf5Handle<&H5Aclose> attribute(
      checked_hdf5_id(H5Aopen(object, name, H5P_DEFAULT), "H5Aopen", path, where + "@" + name));
  double value = 0.0;
  check_hdf5_status(H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value), "H5Aread", path,
                    where + "@" + name);
  return value;
}

herr_t collect_name(hid_t, const char* name, const H5L_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->emplace_back(name);
  return 0;
}

}  // namespace

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

std::optional<ErrorBarRecord> read_error_bar(const std::string& path) {
  const Hdf5ErrorPrintingSuppressed quiet;
  const FileHandle file(
      checked_hdf5_id(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "H5Fopen", path));
  if (H5Lexists(file.get(), "error_bar", H5P_DEFAULT) <= 0) return std::nullopt;
  const GroupHandle group(checked_hdf5_id(H5Gopen2(file.get(), "error_bar", H5P_DEFAULT), "H5Gopen",
                                          path, "/error_bar"));
  ErrorBarRecord r;
  r.dt = read_double(group.get(), "dt", path, "/error_bar");
  for (const char* name : {"coarse_dt_1", "coarse_dt_2"})
    if (H5Aexists(group.get(), name) > 0)
      r.coarse_dt.push_back(read_double(group.get(), name, path, "/error_bar"));
  std::vector<std::string> parts;
  check_hdf5_status(
      H5Literate(group.get(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_name, &parts),
      "H5Literate", path, "/error_bar");
  for (const std::string& name : parts) {
    const std::string where = "/error_bar/" + name;
    const GroupHandle part(
        checked_hdf5_id(H5Gopen2(group.get(), name.c_str(), H5P_DEFAULT), "H5Gopen", path, where));
    const AttributeTarget on{part.get(), path};
    for (const char* measure : kMeasures) {
      if (H5Aexists(part.get(), measure) <= 0) continue;
      ErrorBarEntry e;
      e.part = name;
      e.measure = measure;
      e.estimate = read_double(part.get(), measure, path, where);
      e.order = read_double(part.get(), (std::string(measure) + "_order").c_str(), path, where);
      e.unit = read_string_attribute(on, (std::string(measure) + "_unit").c_str()).value_or("");
      r.entries.push_back(e);
    }
  }
  return r;
}

}  // namespace catena::io
