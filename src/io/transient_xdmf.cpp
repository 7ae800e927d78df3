// write_transient_xdmf: the XDMF descriptions of a time-series file. Dataset names:
// transient_layout.hpp; what ParaView shows: docs/output.md ("Time series", ParaView).
//
// One Uniform grid per sample inside a temporal collection. Every grid repeats the HDF
// references to the mesh datasets (one line each) and selects row k of the sampled
// datasets: start (k, 0, 0), stride 1, count (1, n_nodes, 3), so that a reader reads only
// that sample from the file. ParaView has two families of XDMF readers, which accept
// different ways of selecting (checked with ParaView 5.11's pvpython on a run's files):
//   - the Xdmf3 readers (Xdmf3 Reader S and T, the default for .xmf) take the selection
//     inside the HDF reference, "file:/dataset|start:stride:count:dimensions", and show a
//     grid of 0 points for a HyperSlab item; they drop Function items (computed fields);
//   - the XDMF Reader (the one ParaView picks for .xmf2) takes XDMF's HyperSlab items and
//     Function items, and fails on the "|" syntax.
// So each run gets NAME.xmf for the first and NAME.xmf2 for the second, which also carries
// the displacements (Functions of the samples and the mesh).
//
// Rigid bodies and sliders are nodes outside every element, which a polyline grid does not
// draw: scenes with them get a temporal collection each beside the mesh's ("bodies",
// "sliders"), whose grids are vertices at those nodes (/mesh/body_nodes, /mesh/slider_nodes
// index the same sampled positions) carrying the per-body and per-slider series as cell
// values; joints get one ("joints") of segments from each body's node to the joint's point,
// which draws a mechanism as a stick figure.
#include "catena/io/transient_xdmf.hpp"

#include <hdf5.h>
#include <unistd.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/atomic_file.hpp"
#include "hdf5_error.hpp"
#include "hdf5_handles.hpp"
#include "transient_layout.hpp"
#include "xdmf_writer.hpp"

namespace catena::io {
namespace {

namespace layout = transient_layout;
namespace fs = std::filesystem;

// The sizes the XDMF announces; every one is checked against the file before writing.
struct SeriesShape {
  std::int64_t n_samples = 0;
  std::int64_t n_nodes = 0;
  std::int64_t n_elements = 0;
  std::int64_t n_bodies = 0;   // rows of /mesh/body_nodes (0: no rigid bodies)
  std::int64_t n_sliders = 0;  // rows of /mesh/slider_nodes (0: no sliders)
  std::int64_t n_joints = 0;   // joints of /samples/joint_links (0: no joints)
};

// How a dataset is stored, in XDMF's terms (NumberType + Precision in bytes) and HDF5's.
struct StoredNumber {
  const char* xdmf_type;
  int precision;
  H5T_class_t hdf5_class;
};
constexpr StoredNumber float64{"Float", 8, H5T_FLOAT};
constexpr StoredNumber int64{"Int", 8, H5T_INTEGER};
constexpr StoredNumber int32{"Int", 4, H5T_INTEGER};
// /mesh/element_kind is stored as int8 and announced as int32, as in the static result's
// XDMF: the readers let HDF5 convert on reading.
constexpr StoredNumber int8{"Int", 1, H5T_INTEGER};

std::string dimensions_text(const std::vector<std::int64_t>& dimensions) {
  std::string text;
  for (const std::int64_t n : dimensions) {
    if (!text.empty()) text += ' ';
    text += std::to_string(n);
  }
  return text;
}

// Shortest decimal text that reads back as the same double (the readers use strtod/atof).
std::string time_text(double t) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, t);
  CATENA_ASSERT(error == std::errc(), "32 characters hold any double");
  return std::string(buffer, end);
}

// Writes the XML of the grids, all pointing into one HDF5 file.
class TransientXdmfText {
 public:
  TransientXdmfText(const std::string& hdf5_file_name, const SeriesShape& shape,
                    XdmfReaders readers)
      : file_name_(xml_escaped(hdf5_file_name)), shape_(shape), readers_(readers) {}

  std::string document(const std::vector<double>& times) {
    xml_ << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
         << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
         << "<!-- Catena time series (dynamic run): " << shape_.n_samples
         << " samples; layout in Catena's docs/output.md. "
         << (readers_ == XdmfReaders::xdmf3
                 ? "For ParaView's Xdmf3 readers (the default); the .xmf2 beside it, with the "
                   "displacements, for its XDMF Reader."
                 : "For ParaView's XDMF Reader (with the displacements); the .xmf beside it for "
                   "the Xdmf3 readers.")
         << " -->\n"
         << "<Xdmf Version=\"3.0\">\n"
         << "  <Domain>\n";
    collection("samples", times, &TransientXdmfText::sample_grid);
    if (shape_.n_bodies > 0) collection("bodies", times, &TransientXdmfText::body_grid);
    if (shape_.n_joints > 0) collection("joints", times, &TransientXdmfText::joint_grid);
    if (shape_.n_sliders > 0) collection("sliders", times, &TransientXdmfText::slider_grid);
    xml_ << "  </Domain>\n"
         << "</Xdmf>\n";
    return xml_.str();
  }

 private:
  void sample_grid(std::int64_t k, double t) {
    const std::int64_t n_nodes = shape_.n_nodes, n_elements = shape_.n_elements;
    xml_ << "      <Grid Name=\"sample_" << k << "\" GridType=\"Uniform\">\n"
         << "        <Time Value=\"" << time_text(t) << "\"/>\n"
         << "        <Topology TopologyType=\"Polyline\" NodesPerElement=\""
         << layout::nodes_per_element << "\" NumberOfElements=\"" << n_elements << "\">\n";
    data_item(10, layout::element_nodes.path, {n_elements, layout::nodes_per_element}, int64);
    xml_ << "        </Topology>\n"
         << "        <Geometry GeometryType=\"XYZ\">\n";
    // ParaView's XDMF Reader keys its geometry cache on the content of the first child node
    // of the Geometry's first DataItem: here the comment. With no content there (an
    // element) it logs an error at every time step; with the same content in every grid it
    // could reuse sample 0's points at every time. "sample k" differs per grid.
    sample_slab(10, layout::positions.path, {n_nodes, 3}, k, "sample " + std::to_string(k));
    xml_ << "        </Geometry>\n";

    if (readers_ == XdmfReaders::xdmf2) displacements(k);
    sampled_attribute("velocities", "Vector", "Node", layout::velocities.path, {n_nodes, 3}, k);
    sampled_attribute("slopes", "Vector", "Node", layout::slopes.path, {n_nodes, 3}, k);
    sampled_attribute("axial_force", "Scalar", "Cell", layout::axial_force.path, {n_elements}, k);
    begin_attribute("node_ids", "Scalar", "Node");
    data_item(10, layout::node_ids.path, {n_nodes}, int64);
    end_attribute();
    begin_attribute("element_ids", "Scalar", "Cell");
    data_item(10, layout::element_ids.path, {n_elements}, int64);
    end_attribute();
    begin_attribute("element_kind", "Scalar", "Cell");
    data_item(10, layout::element_kind.path, {n_elements}, int32);
    end_attribute();
    begin_attribute("element_set", "Scalar", "Cell");
    data_item(10, layout::element_set.path, {n_elements}, int32);
    end_attribute();
    xml_ << "      </Grid>\n";
  }

  // A temporal collection beside the mesh's: `grid` of each sample.
  void collection(const char* name, const std::vector<double>& times,
                  void (TransientXdmfText::*grid)(std::int64_t, double)) {
    xml_ << "    <Grid Name=\"" << name
         << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (std::size_t k = 0; k < times.size(); ++k)
      (this->*grid)(static_cast<std::int64_t>(k), times[k]);
    xml_ << "    </Grid>\n";
  }

  // Sample k of the rigid bodies: a vertex at each body's node, its orientation (the unit
  // quaternion w, x, y, z) and angular velocity per cell; the node's velocity and its axis
  // e1 (the slopes) per point.
  void body_grid(std::int64_t k, double t) {
    const std::int64_t n_nodes = shape_.n_nodes, n = shape_.n_bodies;
    vertex_grid_begin("bodies_" + std::to_string(k), t, layout::body_nodes.path, n, k,
                      "bodies sample " + std::to_string(k));
    sampled_attribute("velocities", "Vector", "Node", layout::velocities.path, {n_nodes, 3}, k);
    sampled_attribute("slopes", "Vector", "Node", layout::slopes.path, {n_nodes, 3}, k);
    sampled_attribute("orientation", "Matrix", "Cell", layout::body_orientation.path, {n, 4}, k);
    sampled_attribute("angular_velocity", "Vector", "Cell", layout::body_angular_velocity.path,
                      {n, 3}, k);
    xml_ << "      </Grid>\n";
  }

  // Sample k of the sliders: a vertex at each slider's node, its arc length s along its path
  // and its rate per cell.
  void slider_grid(std::int64_t k, double t) {
    const std::int64_t n_nodes = shape_.n_nodes, n = shape_.n_sliders;
    vertex_grid_begin("sliders_" + std::to_string(k), t, layout::slider_nodes.path, n, k,
                      "sliders sample " + std::to_string(k));
    sampled_attribute("velocities", "Vector", "Node", layout::velocities.path, {n_nodes, 3}, k);
    sampled_attribute("slider_position", "Scalar", "Cell", layout::slider_position.path, {n}, k);
    sampled_attribute("slider_speed", "Scalar", "Cell", layout::slider_speed.path, {n}, k);
    xml_ << "      </Grid>\n";
  }

  // Sample k of the joints: two segments per joint (A's node to the joint's point on A, the
  // joint's point on B to B's node), whose points are row k of /samples/joint_links read in
  // order; the segments' ends and the joint each belongs to are fixed, so they are written
  // here (a mechanism has few joints).
  void joint_grid(std::int64_t k, double t) {
    const std::int64_t n = shape_.n_joints;
    xml_ << "      <Grid Name=\"joints_" << k << "\" GridType=\"Uniform\">\n"
         << "        <Time Value=\"" << time_text(t) << "\"/>\n"
         << "        <Topology TopologyType=\"Polyline\" NodesPerElement=\"2\" NumberOfElements=\""
         << 2 * n << "\">\n"
         << indent(10) << "<DataItem Dimensions=\"" << 2 * n
         << " 2\" NumberType=\"Int\" Precision=\"8\" Format=\"XML\">";
    for (std::int64_t p = 0; p < 4 * n; ++p) xml_ << (p > 0 ? " " : "") << p;
    xml_ << "</DataItem>\n"
         << "        </Topology>\n"
         << "        <Geometry GeometryType=\"XYZ\">\n";
    sample_slab(10, layout::joint_links.path, {n, 4, 3}, k, "joints sample " + std::to_string(k));
    xml_ << "        </Geometry>\n";
    begin_attribute("joint", "Scalar", "Cell");
    xml_ << indent(10) << "<DataItem Dimensions=\"" << 2 * n
         << "\" NumberType=\"Int\" Precision=\"8\" Format=\"XML\">";
    for (std::int64_t c = 0; c < 2 * n; ++c) xml_ << (c > 0 ? " " : "") << c / 2;
    xml_ << "</DataItem>\n";
    end_attribute();
    xml_ << "      </Grid>\n";
  }

  // A grid's opening, time, topology (a vertex at each of the `n` nodes listed in `nodes`) and
  // geometry (every node's sampled position, as the mesh grid's; the comment keeps the XDMF
  // Reader's geometry cache apart from the mesh grid's, as there).
  void vertex_grid_begin(const std::string& name, double t, const char* nodes, std::int64_t n,
                         std::int64_t k, const std::string& comment) {
    xml_
        << "      <Grid Name=\"" << name << "\" GridType=\"Uniform\">\n"
        << "        <Time Value=\"" << time_text(t) << "\"/>\n"
        << "        <Topology TopologyType=\"Polyvertex\" NodesPerElement=\"1\" NumberOfElements=\""
        << n << "\">\n";
    data_item(10, nodes, {n}, int64);
    xml_ << "        </Topology>\n"
         << "        <Geometry GeometryType=\"XYZ\">\n";
    sample_slab(10, layout::positions.path, {shape_.n_nodes, 3}, k, comment);
    xml_ << "        </Geometry>\n";
  }

  // The displacement from the mesh and from the static equilibrium (sample 0): Functions
  // of the samples and the mesh, which only the XDMF Reader evaluates.
  void displacements(std::int64_t k) {
    const std::int64_t n_nodes = shape_.n_nodes;
    begin_attribute("displacement", "Vector", "Node");
    xml_ << indent(10) << "<DataItem ItemType=\"Function\" Function=\"$0 - $1\" Dimensions=\""
         << dimensions_text({n_nodes, 3}) << "\">\n";
    sample_slab(12, layout::positions.path, {n_nodes, 3}, k);
    data_item(12, layout::node_positions.path, {n_nodes, 3}, float64);
    xml_ << indent(10) << "</DataItem>\n";
    end_attribute();
    // From the static equilibrium the run starts from (sample 0): the motion itself, which a
    // magnified Warp By Vector shows without the static sag.
    begin_attribute("displacement_from_static", "Vector", "Node");
    xml_ << indent(10) << "<DataItem ItemType=\"Function\" Function=\"$0 - $1\" Dimensions=\""
         << dimensions_text({n_nodes, 3}) << "\">\n";
    sample_slab(12, layout::positions.path, {n_nodes, 3}, k);
    sample_slab(12, layout::positions.path, {n_nodes, 3}, 0);
    xml_ << indent(10) << "</DataItem>\n";
    end_attribute();
  }

  static std::string indent(int n_spaces) {
    return std::string(static_cast<std::size_t>(n_spaces), ' ');
  }

  // A whole dataset: "<file>:<dataset>".
  void data_item(int n_spaces, const char* dataset, const std::vector<std::int64_t>& dimensions,
                 StoredNumber number) {
    xml_ << indent(n_spaces) << "<DataItem Dimensions=\"" << dimensions_text(dimensions)
         << "\" NumberType=\"" << number.xdmf_type << "\" Precision=\"" << number.precision
         << "\" Format=\"HDF\">" << file_name_ << ':' << dataset << "</DataItem>\n";
  }

  // Row k of a float64 dataset of shape (n_samples, row_shape...). Its Dimensions are the
  // selection's count, (1, row_shape...): readers take the values in order, so the leading
  // 1 does not matter to them.
  void sample_slab(int n_spaces, const char* dataset, const std::vector<std::int64_t>& row_shape,
                   std::int64_t k, const std::string& comment = {}) {
    std::vector<std::int64_t> count{1}, full{shape_.n_samples};
    count.insert(count.end(), row_shape.begin(), row_shape.end());
    full.insert(full.end(), row_shape.begin(), row_shape.end());
    const std::int64_t rank = static_cast<std::int64_t>(full.size());
    std::vector<std::int64_t> start(full.size(), 0), stride(full.size(), 1);
    start[0] = k;

    if (readers_ == XdmfReaders::xdmf3) {
      // The selection inside the HDF reference: start:stride:count:dimensions.
      xml_ << indent(n_spaces) << "<DataItem Dimensions=\"" << dimensions_text(count)
           << "\" NumberType=\"" << float64.xdmf_type << "\" Precision=\"" << float64.precision
           << "\" Format=\"HDF\">";
      if (!comment.empty()) xml_ << "<!-- " << comment << " -->";
      xml_ << file_name_ << ':' << dataset << '|' << dimensions_text(start) << ':'
           << dimensions_text(stride) << ':' << dimensions_text(count) << ':'
           << dimensions_text(full) << "</DataItem>\n";
      return;
    }
    const std::string inner = indent(n_spaces + 2);
    xml_ << indent(n_spaces) << "<DataItem ItemType=\"HyperSlab\" Dimensions=\""
         << dimensions_text(count) << "\" NumberType=\"" << float64.xdmf_type << "\" Precision=\""
         << float64.precision << "\">";
    if (!comment.empty()) xml_ << "<!-- " << comment << " -->";
    xml_ << '\n'
         << inner << "<DataItem Dimensions=\"3 " << rank << "\" NumberType=\"Int\" Format=\"XML\">"
         << dimensions_text(start) << ' ' << dimensions_text(stride) << ' '
         << dimensions_text(count) << "</DataItem>\n";
    data_item(n_spaces + 2, dataset, full, float64);
    xml_ << indent(n_spaces) << "</DataItem>\n";
  }

  void begin_attribute(const char* name, const char* type, const char* center) {
    xml_ << "        <Attribute Name=\"" << name << "\" AttributeType=\"" << type << "\" Center=\""
         << center << "\">\n";
  }
  void end_attribute() { xml_ << "        </Attribute>\n"; }

  void sampled_attribute(const char* name, const char* type, const char* center,
                         const char* dataset, const std::vector<std::int64_t>& row_shape,
                         std::int64_t k) {
    begin_attribute(name, type, center);
    sample_slab(10, dataset, row_shape, k);
    end_attribute();
  }

  std::ostringstream xml_;
  std::string file_name_;
  SeriesShape shape_;
  XdmfReaders readers_;
};

// A dataset the XDMF refers to, with the shape and storage it announces.
struct ExpectedDataset {
  const char* name;
  std::vector<std::int64_t> dimensions;
  StoredNumber number;
};

// Opens the time series for reading; throws unless it has this layout's format.
FileHandle open_time_series(const std::string& path) {
  FileHandle file(
      checked_hdf5_id(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "H5Fopen", path));
  layout::require_transient_format(file.get(), path);
  return file;
}

std::vector<std::int64_t> dataset_dimensions(hid_t dataset, const std::string& path,
                                             const char* name) {
  const DataspaceHandle space(checked_hdf5_id(H5Dget_space(dataset), "H5Dget_space", path, name));
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) throw_hdf5_error("H5Sget_simple_extent_ndims", path, name);
  std::vector<hsize_t> dimensions(static_cast<std::size_t>(rank));
  if (H5Sget_simple_extent_dims(space.get(), dimensions.data(), nullptr) < 0)
    throw_hdf5_error("H5Sget_simple_extent_dims", path, name);
  return {dimensions.begin(), dimensions.end()};
}

// Throws unless every dataset the XDMF refers to exists with the announced shape and type.
void check_datasets(const std::string& path, const SeriesShape& shape) {
  const FileHandle file = open_time_series(path);
  const std::int64_t s = shape.n_samples, n = shape.n_nodes, e = shape.n_elements;
  std::vector<ExpectedDataset> expected{
      {layout::time.path, {s}, float64},
      {layout::node_ids.path, {n}, int64},
      {layout::node_positions.path, {n, 3}, float64},
      {layout::element_ids.path, {e}, int64},
      {layout::element_nodes.path, {e, layout::nodes_per_element}, int64},
      {layout::element_kind.path, {e}, int8},
      {layout::element_set.path, {e}, int32},
      {layout::positions.path, {s, n, 3}, float64},
      {layout::velocities.path, {s, n, 3}, float64},
      {layout::slopes.path, {s, n, 3}, float64},
      {layout::axial_force.path, {s, e}, float64},
  };
  if (shape.n_bodies > 0) {
    const std::int64_t b = shape.n_bodies;
    expected.push_back({layout::body_nodes.path, {b}, int64});
    expected.push_back({layout::body_orientation.path, {s, b, 4}, float64});
    expected.push_back({layout::body_angular_velocity.path, {s, b, 3}, float64});
  }
  if (shape.n_joints > 0)
    expected.push_back({layout::joint_links.path, {s, shape.n_joints, 4, 3}, float64});
  if (shape.n_sliders > 0) {
    const std::int64_t b = shape.n_sliders;
    expected.push_back({layout::slider_nodes.path, {b}, int64});
    expected.push_back({layout::slider_position.path, {s, b}, float64});
    expected.push_back({layout::slider_speed.path, {s, b}, float64});
  }
  for (const ExpectedDataset& dataset : expected) {
    const DatasetHandle handle(checked_hdf5_id(H5Dopen2(file.get(), dataset.name, H5P_DEFAULT),
                                               "H5Dopen2", path, dataset.name));
    const std::vector<std::int64_t> found = dataset_dimensions(handle.get(), path, dataset.name);
    if (found != dataset.dimensions)
      throw Error("'" + path + "' at " + dataset.name + ": shape (" + dimensions_text(found) +
                  "), expected (" + dimensions_text(dataset.dimensions) + ") for " +
                  std::to_string(s) + " samples, " + std::to_string(n) + " nodes, " +
                  std::to_string(e) + " elements");
    const DatatypeHandle type(
        checked_hdf5_id(H5Dget_type(handle.get()), "H5Dget_type", path, dataset.name));
    if (H5Tget_class(type.get()) != dataset.number.hdf5_class ||
        H5Tget_size(type.get()) != static_cast<std::size_t>(dataset.number.precision))
      throw Error("'" + path + "' at " + dataset.name + ": stored type is not " +
                  (dataset.number.hdf5_class == H5T_FLOAT ? "float" : "int") +
                  std::to_string(8 * dataset.number.precision));
  }
}

// The rows of an index dataset of nodes (/mesh/body_nodes, /mesh/slider_nodes): 0 if the file
// has none (a scene without bodies or sliders). Throws unless it is one-dimensional int64 with
// every value a node of the mesh (0 ≤ value < n_nodes), so that the vertices the XDMF draws
// exist.
std::int64_t node_index_rows(const std::string& path, const char* name, std::int64_t n_nodes) {
  const FileHandle file = open_time_series(path);
  const htri_t exists = H5Lexists(file.get(), name, H5P_DEFAULT);
  if (exists < 0) throw_hdf5_error("H5Lexists", path, name);
  if (exists == 0) return 0;
  const DatasetHandle dataset(
      checked_hdf5_id(H5Dopen2(file.get(), name, H5P_DEFAULT), "H5Dopen2", path, name));
  const std::vector<std::int64_t> dimensions = dataset_dimensions(dataset.get(), path, name);
  if (dimensions.size() != 1)
    throw Error("'" + path + "' at " + name + ": shape (" + dimensions_text(dimensions) +
                "), expected one dimension");
  std::vector<std::int64_t> nodes(static_cast<std::size_t>(dimensions[0]));
  if (!nodes.empty())
    check_hdf5_status(
        H5Dread(dataset.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, nodes.data()),
        "H5Dread", path, name);
  for (const std::int64_t node : nodes)
    if (node < 0 || node >= n_nodes)
      throw Error("'" + path + "' at " + name + ": node index " + std::to_string(node) +
                  " is not one of the mesh's " + std::to_string(n_nodes) + " nodes");
  return dimensions[0];
}

// The joints of /samples/joint_links (its second dimension): 0 if the file has none.
std::int64_t joint_rows(const std::string& path) {
  const FileHandle file = open_time_series(path);
  const char* name = layout::joint_links.path;
  const htri_t exists = H5Lexists(file.get(), name, H5P_DEFAULT);
  if (exists < 0) throw_hdf5_error("H5Lexists", path, name);
  if (exists == 0) return 0;
  const DatasetHandle dataset(
      checked_hdf5_id(H5Dopen2(file.get(), name, H5P_DEFAULT), "H5Dopen2", path, name));
  const std::vector<std::int64_t> dimensions = dataset_dimensions(dataset.get(), path, name);
  if (dimensions.size() != 4)
    throw Error("'" + path + "' at " + name + ": shape (" + dimensions_text(dimensions) +
                "), expected (samples, joints, 4, 3)");
  return dimensions[1];
}

// Both names in one directory: the XDMF refers to the HDF5 file by its base name.
void check_paths(const fs::path& hdf5_path, const fs::path& xdmf_path) {
  const fs::path hdf5_absolute = fs::absolute(hdf5_path).lexically_normal();
  const fs::path xdmf_absolute = fs::absolute(xdmf_path).lexically_normal();
  if (hdf5_absolute == xdmf_absolute)
    throw Error("the XDMF file would replace the HDF5 file it describes");
  if (hdf5_absolute.parent_path() != xdmf_absolute.parent_path())
    throw Error("the XDMF file must be in the directory of '" + hdf5_path.string() +
                "': it refers to it by its base name");
}

}  // namespace

std::string transient_xdmf_path(const std::string& hdf5_path) {
  return xdmf_path_for(fs::path(hdf5_path)).string();
}

std::string transient_xdmf2_path(const std::string& hdf5_path) {
  return transient_xdmf_path(hdf5_path) + "2";
}

std::vector<double> read_sample_times(const std::string& hdf5_path) {
  const Hdf5ErrorPrintingSuppressed quiet_hdf5;
  const FileHandle file = open_time_series(hdf5_path);
  const char* time = layout::time.path;
  const DatasetHandle dataset(
      checked_hdf5_id(H5Dopen2(file.get(), time, H5P_DEFAULT), "H5Dopen2", hdf5_path, time));
  const std::vector<std::int64_t> dimensions = dataset_dimensions(dataset.get(), hdf5_path, time);
  if (dimensions.size() != 1)
    throw Error("'" + hdf5_path + "' at " + time + ": shape (" + dimensions_text(dimensions) +
                "), expected one dimension");
  std::vector<double> times(static_cast<std::size_t>(dimensions[0]));
  if (!times.empty())
    check_hdf5_status(
        H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, times.data()),
        "H5Dread", hdf5_path, time);
  return times;
}

void write_transient_xdmf(const std::string& hdf5_path, const std::string& xdmf_path,
                          std::int64_t n_nodes, std::int64_t n_elements,
                          const std::vector<double>& times, XdmfReaders readers) {
  const Hdf5ErrorPrintingSuppressed quiet_hdf5;
  try {
    check_paths(hdf5_path, xdmf_path);
    // ParaView's XDMF Reader (5.11) crashes on a temporal collection without grids.
    if (times.empty()) throw Error("the run has no samples: there is nothing to show");
    for (const double t : times)
      if (!std::isfinite(t)) throw Error("a sample time is not finite: " + time_text(t));
    const SeriesShape shape{static_cast<std::int64_t>(times.size()),
                            n_nodes,
                            n_elements,
                            node_index_rows(hdf5_path, layout::body_nodes.path, n_nodes),
                            node_index_rows(hdf5_path, layout::slider_nodes.path, n_nodes),
                            joint_rows(hdf5_path)};
    check_datasets(hdf5_path, shape);
    const std::string text =
        TransientXdmfText(fs::path(hdf5_path).filename().string(), shape, readers).document(times);

    const fs::path target(xdmf_path);
    TemporaryFile temporary(temporary_sibling(target, ::getpid()));
    write_file_durably(temporary.path(), text);
    rename_into_place(temporary.path(), target);
    temporary.release();
    fsync_path(target.has_parent_path() ? target.parent_path() : fs::path("."));
  } catch (const Error& error) {
    throw Error("cannot write '" + xdmf_path + "': " + error.what());
  }
}

}  // namespace catena::io
