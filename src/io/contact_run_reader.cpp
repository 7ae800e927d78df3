#include "catena/io/contact_run_reader.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>
#include <sstream>
#include <type_traits>
#include <utility>

#include "catena/core/error.hpp"
#include "hdf5_attributes.hpp"
#include "hdf5_error.hpp"
#include "hdf5_handles.hpp"
#include "transient_layout.hpp"

namespace catena::io {
namespace {

namespace layout = transient_layout;
constexpr const char* time_name = layout::time.path;
constexpr const char* contact_force_name = layout::contact_force.path;
constexpr const char* contact_position_name = layout::contact_position.path;
constexpr const char* positions_name = layout::positions.path;
constexpr const char* pantographs_name = layout::pantographs_group;
constexpr const char* node_positions_name = layout::node_positions.path;
constexpr const char* registration_nodes_name = layout::registration_nodes.path;
constexpr const char* step_time_name = layout::step_time.path;
constexpr const char* step_contact_force_name = layout::step_contact_force.path;
constexpr const char* step_registration_height_name = layout::step_registration_height.path;
namespace root_attribute = layout::root_attribute;
namespace pantograph_attribute = layout::pantograph_attribute;

// Relative tolerance on the spacing of /time (dense output at k × output.interval).
constexpr double sampling_tolerance = 1e-6;

class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)), file_(open(path_)) {}

  [[noreturn]] void fail(const std::string& object, const std::string& message) const {
    throw InputError({path_, 0, object}, message);
  }

  bool has_link(const char* name) const {
    // Checks each level, so "/a/b" is false (not an error) when "/a" is missing.
    std::string partial;
    std::string rest = name;
    while (!rest.empty()) {
      const auto slash = rest.find('/', 1);
      partial += rest.substr(0, slash);
      rest = slash == std::string::npos ? "" : rest.substr(slash);
      if (H5Lexists(file_.get(), partial.c_str(), H5P_DEFAULT) <= 0) return false;
    }
    return true;
  }
  bool has_attribute(hid_t object, const char* name) const { return H5Aexists(object, name) > 0; }
  hid_t root() const { return file_.get(); }

  std::string text_attribute(hid_t object, const char* name, const std::string& where) const {
    std::optional<std::string> value;
    try {
      value = read_string_attribute({object, path_}, name);
    } catch (const Error& e) {
      fail(where, e.what());
    }
    if (!value) fail(where, std::string("cannot open attribute ") + name);
    return *value;
  }

  template <class T>
  T number_attribute(hid_t object, const char* name, const std::string& where) const {
    const AttributeHandle a(H5Aopen(object, name, H5P_DEFAULT));
    if (a.get() < 0) fail(where, std::string("cannot open attribute ") + name);
    const DataspaceHandle space(H5Aget_space(a.get()));
    const DatatypeHandle type(H5Aget_type(a.get()));
    const H5T_class_t cls = H5Tget_class(type.get());
    if (H5Sget_simple_extent_npoints(space.get()) != 1 || (cls != H5T_INTEGER && cls != H5T_FLOAT))
      fail(where, std::string("attribute ") + name + " is not a single number");
    T value{};
    const hid_t memory = std::is_same_v<T, double> ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT64;
    if (H5Aread(a.get(), memory, &value) < 0)
      fail(where, std::string("cannot read attribute ") + name);
    return value;
  }

  std::vector<hsize_t> dims(const char* name) const {
    const DatasetHandle d = open_dataset(name);
    const DataspaceHandle space(H5Dget_space(d.get()));
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank < 0) fail(name, "cannot read the dataset's shape");
    std::vector<hsize_t> out(static_cast<std::size_t>(rank));
    H5Sget_simple_extent_dims(space.get(), out.data(), nullptr);
    return out;
  }

  // The whole dataset as doubles (float or integer in the file), checked against `shape`.
  std::vector<double> doubles(const char* name, const std::vector<hsize_t>& shape) const {
    return read<double>(name, shape, H5T_FLOAT, H5T_NATIVE_DOUBLE);
  }
  std::vector<std::int64_t> integers(const char* name, const std::vector<hsize_t>& shape) const {
    return read<std::int64_t>(name, shape, H5T_INTEGER, H5T_NATIVE_INT64);
  }

  // z of the given nodes (sorted, unique) at every sample of /samples/positions, one read:
  // out[k * nodes.size() + j] is z of nodes[j] at sample k (HDF5 maps a union selection in
  // the file's row-major order).
  std::vector<double> node_heights(const std::vector<hsize_t>& nodes, hsize_t n_samples) const {
    const DatasetHandle d = open_dataset(positions_name);
    const DataspaceHandle file_space(H5Dget_space(d.get()));
    H5Sselect_none(file_space.get());
    for (hsize_t node : nodes) {
      const hsize_t start[3] = {0, node, 2};
      const hsize_t count[3] = {n_samples, 1, 1};
      if (H5Sselect_hyperslab(file_space.get(), H5S_SELECT_OR, start, nullptr, count, nullptr) < 0)
        fail(positions_name, "cannot select the registration nodes");
    }
    const hsize_t memory_dims[2] = {n_samples, nodes.size()};
    const DataspaceHandle memory_space(H5Screate_simple(2, memory_dims, nullptr));
    std::vector<double> out(n_samples * nodes.size());
    if (!out.empty() && H5Dread(d.get(), H5T_NATIVE_DOUBLE, memory_space.get(), file_space.get(),
                                H5P_DEFAULT, out.data()) < 0)
      fail(positions_name, "cannot read the registration nodes' positions");
    return out;
  }

  GroupHandle open_group(const char* name) const {
    GroupHandle g(H5Gopen2(file_.get(), name, H5P_DEFAULT));
    if (g.get() < 0) fail(name, "not a group");
    return g;
  }

 private:
  static hid_t open(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(path, ec)) throw InputError({path, 0, ""}, "no such file");
    if (fs::is_directory(path, ec)) throw InputError({path, 0, ""}, "is a directory");
    if (H5Fis_hdf5(path.c_str()) <= 0)
      throw InputError({path, 0, ""}, "not an HDF5 file (or not readable)");
    const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (id < 0) throw InputError({path, 0, ""}, "cannot open the HDF5 file for reading");
    return id;
  }

  DatasetHandle open_dataset(const char* name) const {
    DatasetHandle d(H5Dopen2(file_.get(), name, H5P_DEFAULT));
    if (d.get() < 0) fail(name, "cannot open the dataset");
    return d;
  }

  template <class T>
  std::vector<T> read(const char* name, const std::vector<hsize_t>& shape, H5T_class_t kind,
                      hid_t memory_type) const {
    const DatasetHandle d = open_dataset(name);
    const DatatypeHandle type(H5Dget_type(d.get()));
    const H5T_class_t cls = H5Tget_class(type.get());
    if (cls != kind && !(kind == H5T_FLOAT && cls == H5T_INTEGER))
      fail(name, kind == H5T_FLOAT ? "not a numeric dataset" : "not an integer dataset");
    const std::vector<hsize_t> found = dims(name);
    if (found != shape) {
      auto text = [](const std::vector<hsize_t>& s) {
        std::ostringstream os;
        os << "(";
        for (std::size_t i = 0; i < s.size(); ++i) os << (i ? ", " : "") << s[i];
        os << (s.size() == 1 ? ",)" : ")");
        return os.str();
      };
      fail(name, "shape " + text(found) + ", expected " + text(shape));
    }
    std::size_t n = 1;
    for (hsize_t s : shape) n *= static_cast<std::size_t>(s);
    std::vector<T> out(n);
    if (n > 0 && H5Dread(d.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
      fail(name, "cannot read the dataset");
    return out;
  }

  std::string path_;
  FileHandle file_;
};

// After the format check (a time series of this format), which analysis and status.
void check_is_complete_dynamic_output(const Reader& r) {
  const std::string not_dynamic = "not a Catena dynamic output";
  const char* analysis_name = root_attribute::analysis;
  if (!r.has_attribute(r.root(), analysis_name))
    r.fail("", not_dynamic + " (no root attribute analysis = \"dynamic\")");
  const std::string analysis = r.text_attribute(r.root(), analysis_name, analysis_name);
  if (analysis != layout::analysis_dynamic)
    r.fail(analysis_name, not_dynamic + " (analysis = '" + analysis + "')");
  const char* status_name = root_attribute::status;
  if (!r.has_attribute(r.root(), status_name))
    r.fail(status_name, "missing: the file was not written by a complete dynamic run");
  const std::string status = r.text_attribute(r.root(), status_name, status_name);
  if (status != "complete")
    r.fail(status_name,
           "the run's status is '" + status + "', not 'complete': statistics need a finished run");
}

double uniform_interval(const Reader& r, const std::vector<double>& t,
                        const char* name = time_name) {
  if (t.size() < 2) r.fail(name, "fewer than 2 samples: no sampling interval");
  const double dt = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  if (!(dt > 0.0)) r.fail(name, "the sample times do not increase");
  for (std::size_t k = 0; k + 1 < t.size(); ++k) {
    const double step = t[k + 1] - t[k];
    if (std::abs(step - dt) > sampling_tolerance * dt) {
      std::ostringstream os;
      os << "not uniformly sampled: samples " << k << " and " << k + 1 << " are " << step
         << " s apart, the mean interval is " << dt << " s";
      r.fail(name, os.str());
    }
  }
  return dt;
}

std::optional<post::EvaluationSection> evaluation_section(const Reader& r) {
  post::EvaluationSection s;
  const char* start_name = root_attribute::evaluation_start;
  const char* end_name = root_attribute::evaluation_end;
  if (r.has_attribute(r.root(), start_name))
    s.x_start = r.number_attribute<double>(r.root(), start_name, start_name);
  if (r.has_attribute(r.root(), end_name))
    s.x_end = r.number_attribute<double>(r.root(), end_name, end_name);
  if (s.x_start == 0.0 && s.x_end == 0.0) return std::nullopt;
  if (!(s.x_end > s.x_start)) {
    std::ostringstream os;
    os << "evaluation_start " << s.x_start << " m, evaluation_end " << s.x_end
       << " m: the end must lie beyond the start (give --section X0 X1 instead)";
    r.fail(end_name, os.str());
  }
  return s;
}

// The groups under /pantographs, placed at their column (attribute index).
std::vector<post::PantographRecord> pantograph_list(const Reader& r, hsize_t n_columns) {
  if (!r.has_link(pantographs_name))
    r.fail(pantographs_name, "missing: the run had no pantographs");
  const GroupHandle group = r.open_group(pantographs_name);
  H5G_info_t info;
  if (H5Gget_info(group.get(), &info) < 0) r.fail(pantographs_name, "cannot list the group");
  if (info.nlinks == 0) r.fail(pantographs_name, "empty: the run had no pantographs");
  if (info.nlinks != n_columns) {
    std::ostringstream os;
    os << info.nlinks << " pantographs but " << n_columns << " columns in " << contact_force_name;
    r.fail(pantographs_name, os.str());
  }
  std::vector<post::PantographRecord> out(n_columns);
  std::vector<bool> seen(n_columns, false);
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t length = H5Lget_name_by_idx(group.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i,
                                              nullptr, 0, H5P_DEFAULT);
    if (length < 0) r.fail(pantographs_name, "cannot list the group");
    std::string name(static_cast<std::size_t>(length) + 1, '\0');
    H5Lget_name_by_idx(group.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(),
                       H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(length));
    const std::string where = std::string(pantographs_name) + "/" + name;
    const GroupHandle g = r.open_group(where.c_str());
    for (const char* attribute : {pantograph_attribute::index, pantograph_attribute::speed})
      if (!r.has_attribute(g.get(), attribute))
        r.fail(where, std::string("missing attribute ") + attribute);
    const auto index =
        r.number_attribute<std::int64_t>(g.get(), pantograph_attribute::index, where);
    if (index < 0 || static_cast<hsize_t>(index) >= n_columns ||
        seen[static_cast<std::size_t>(index)]) {
      std::ostringstream os;
      os << "attribute index = " << index << ": must be a distinct column in [0, " << n_columns
         << ")";
      r.fail(where, os.str());
    }
    const auto column = static_cast<std::size_t>(index);
    seen[column] = true;
    out[column].name = name;
    out[column].speed = r.number_attribute<double>(g.get(), pantograph_attribute::speed, where);
  }
  return out;
}

}  // namespace

ContactRun read_contact_run(const std::string& path) {
  const Hdf5ErrorPrintingSuppressed quiet;
  const Reader r(path);
  layout::require_transient_format(r.root(), path);
  check_is_complete_dynamic_output(r);

  ContactRun run;
  if (!r.has_link(time_name)) r.fail(time_name, "missing: not a Catena dynamic output");
  const std::vector<hsize_t> time_dims = r.dims(time_name);
  if (time_dims.size() != 1) r.fail(time_name, "not one-dimensional");
  const hsize_t n = time_dims[0];
  run.n_samples = static_cast<std::size_t>(n);
  run.dt = uniform_interval(r, r.doubles(time_name, {n}));
  run.evaluation_section = evaluation_section(r);

  for (const char* name : {contact_force_name, contact_position_name})
    if (!r.has_link(name))
      r.fail(name, "missing: the run had no pantographs (no contact was modelled)");
  const std::vector<hsize_t> force_dims = r.dims(contact_force_name);
  if (force_dims.size() != 2 || force_dims[0] != n)
    r.fail(contact_force_name, "not of shape (n_samples, n_pantographs)");
  const hsize_t n_pantographs = force_dims[1];
  if (n_pantographs == 0) r.fail(contact_force_name, "no columns: the run had no pantographs");
  run.pantographs = pantograph_list(r, n_pantographs);
  const std::vector<double> force = r.doubles(contact_force_name, {n, n_pantographs});
  const std::vector<double> position = r.doubles(contact_position_name, {n, n_pantographs});
  for (std::size_t j = 0; j < run.pantographs.size(); ++j) {
    post::PantographRecord& p = run.pantographs[j];
    p.force.resize(run.n_samples);
    p.position.resize(run.n_samples);
    for (std::size_t k = 0; k < run.n_samples; ++k) {
      p.force[k] = force[k * n_pantographs + j];
      p.position[k] = position[k * n_pantographs + j];
    }
  }

  run.has_registration_nodes = r.has_link(registration_nodes_name);
  if (!run.has_registration_nodes) return run;
  const std::vector<hsize_t> registration_dims = r.dims(registration_nodes_name);
  if (registration_dims.size() != 1) r.fail(registration_nodes_name, "not one-dimensional");
  const std::vector<std::int64_t> registration =
      r.integers(registration_nodes_name, registration_dims);
  if (registration.empty()) return run;
  const std::vector<hsize_t> mesh_dims = r.dims(node_positions_name);
  if (mesh_dims.size() != 2 || mesh_dims[1] != 3)
    r.fail(node_positions_name, "not of shape (n_nodes, 3)");
  const hsize_t n_nodes = mesh_dims[0];
  const std::vector<double> reference = r.doubles(node_positions_name, mesh_dims);
  if (r.dims(positions_name) != std::vector<hsize_t>{n, n_nodes, 3})
    r.fail(positions_name, "not of shape (n_samples, n_nodes, 3)");
  std::set<hsize_t> unique;
  for (std::int64_t node : registration) {
    if (node < 0 || static_cast<hsize_t>(node) >= n_nodes) {
      std::ostringstream os;
      os << "node index " << node << " outside [0, " << n_nodes << ")";
      r.fail(registration_nodes_name, os.str());
    }
    unique.insert(static_cast<hsize_t>(node));
  }
  const std::vector<hsize_t> nodes(unique.begin(), unique.end());
  const std::vector<double> z = r.node_heights(nodes, n);
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    post::RegistrationPoint p;
    p.reference_x = reference[3 * nodes[j]];
    p.z.resize(run.n_samples);
    for (std::size_t k = 0; k < run.n_samples; ++k) p.z[k] = z[k * nodes.size() + j];
    run.registration_points.push_back(std::move(p));
  }
  return run;
}

namespace {

// y (sampled at the ascending times t) at time x: linear between samples, extended by the
// nearest pair beyond them.
double interpolate(const std::vector<double>& t, const std::vector<double>& y, double x) {
  const auto upper = std::upper_bound(t.begin(), t.end(), x);
  std::size_t k = static_cast<std::size_t>(upper - t.begin());
  k = std::clamp<std::size_t>(k, 1, t.size() - 1);
  const double w = (x - t[k - 1]) / (t[k] - t[k - 1]);
  return (1.0 - w) * y[k - 1] + w * y[k];
}

}  // namespace

ContactRun read_contact_run_steps(const std::string& path) {
  ContactRun run = read_contact_run(path);
  const Hdf5ErrorPrintingSuppressed quiet;
  const Reader r(path);
  const std::vector<double> sample_times = r.doubles(time_name, {run.n_samples});
  for (const char* name : {step_time_name, step_contact_force_name})
    if (!r.has_link(name)) r.fail(name, "missing: the run wrote no step records");
  const std::vector<hsize_t> dims = r.dims(step_time_name);
  if (dims.size() != 1) r.fail(step_time_name, "not one-dimensional");
  const hsize_t n_steps = dims[0];
  const auto n_pantographs = static_cast<hsize_t>(run.pantographs.size());
  if (r.dims(step_contact_force_name) != std::vector<hsize_t>{n_steps, n_pantographs})
    r.fail(step_contact_force_name, "not of shape (n_steps, n_pantographs)");
  const std::vector<double> step_time = r.doubles(step_time_name, {n_steps});
  const std::vector<double> step_force =
      r.doubles(step_contact_force_name, {n_steps, n_pantographs});
  // The series: the first sample (the start), then every step after it.
  std::vector<double> t{sample_times.front()};
  std::vector<std::size_t> rows{0};
  for (std::size_t k = 0; k < step_time.size(); ++k)
    if (step_time[k] > t.front()) {
      t.push_back(step_time[k]);
      rows.push_back(k + 1);  // 0: the sample; k + 1: step k
    }
  // A last step cut short to land on the duration.
  if (t.size() > 2) {
    const double dt = t[1] - t[0], last = t.back() - t[t.size() - 2];
    if (last < dt * (1.0 - 1e-6)) {
      t.pop_back();
      rows.pop_back();
    }
  }
  run.dt = uniform_interval(r, t, step_time_name);
  const std::size_t n = t.size();
  for (std::size_t j = 0; j < run.pantographs.size(); ++j) {
    post::PantographRecord& p = run.pantographs[j];
    std::vector<double> force(n), position(n);
    for (std::size_t k = 0; k < n; ++k) {
      force[k] = rows[k] == 0 ? p.force[0] : step_force[(rows[k] - 1) * n_pantographs + j];
      position[k] = interpolate(sample_times, p.position, t[k]);
    }
    p.force = std::move(force);
    p.position = std::move(position);
  }
  // The registration points' heights of every step where the run wrote them; a file
  // without them (an older Catena) gives them interpolated from the samples.
  // Its columns follow /mesh/registration_nodes; the points are that list's distinct nodes,
  // ascending (read_contact_run): point j reads the column of its node's first entry.
  std::vector<double> step_heights;
  std::vector<std::size_t> column(run.registration_points.size());
  hsize_t n_columns = 0;
  if (!run.registration_points.empty() && r.has_link(step_registration_height_name)) {
    const std::vector<std::int64_t> listed =
        r.integers(registration_nodes_name, r.dims(registration_nodes_name));
    std::vector<std::int64_t> distinct(listed);
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    for (std::size_t j = 0; j < column.size(); ++j)
      column[j] = static_cast<std::size_t>(std::find(listed.begin(), listed.end(), distinct[j]) -
                                           listed.begin());
    n_columns = static_cast<hsize_t>(listed.size());
    if (r.dims(step_registration_height_name) != std::vector<hsize_t>{n_steps, n_columns})
      r.fail(step_registration_height_name, "not of shape (n_steps, n_registration_nodes)");
    step_heights = r.doubles(step_registration_height_name, {n_steps, n_columns});
  }
  for (std::size_t j = 0; j < run.registration_points.size(); ++j) {
    post::RegistrationPoint& point = run.registration_points[j];
    std::vector<double> z(n);
    for (std::size_t k = 0; k < n; ++k)
      z[k] = rows[k] == 0 || step_heights.empty()
                 ? interpolate(sample_times, point.z, t[k])
                 : step_heights[(rows[k] - 1) * n_columns + column[j]];
    point.z = std::move(z);
  }
  run.n_samples = n;
  return run;
}

const char* contact_run_times_dataset() { return time_name; }

}  // namespace catena::io
