// write_transient_xdmf / read_sample_times on a tiny time-series file written here with
// serial HDF5 in the layout of docs/output.md ("Time series"). The XDMF is checked as
// text: one Uniform grid per sample with its time; every HDF DataItem names the HDF5 file
// by its base name and a dataset that exists with the announced shape; every HyperSlab
// selects row k (k = the grid's index) of a dataset that has it, with a count equal to the
// HyperSlab's Dimensions and to the dataset's row shape. Failures (shape mismatch, wrong
// directory, no samples) must throw and leave no file behind.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/transient_xdmf.hpp"
#include "hdf5_id.hpp"
#include "test_directory.hpp"

namespace {

namespace fs = std::filesystem;
using catena::test::directory_listing;
// The flavour most tests check: HyperSlab items (the XDMF Reader's); the Xdmf3 readers'
// flavour has a test of its own below.
constexpr catena::io::XdmfReaders legacy = catena::io::XdmfReaders::xdmf2;
using catena::test::OpenId;

constexpr std::int64_t n_nodes = 4;
constexpr std::int64_t n_elements = 3;
// Not multiples of a power of two, and one needs all 17 digits to read back exactly.
const std::vector<double> sample_times{0.0, 0.1, 0.25, 1.0 / 3.0, 2.5e-7};

// A dataset of `dims` filled with 0, 1, 2, ...; extendible along the first dimension and
// chunked like TransientWriter's series when `extendible`.
template <class Value>
void write_dataset(hid_t file, const char* name, const std::vector<hsize_t>& dims, hid_t type,
                   bool extendible) {
  std::vector<hsize_t> max_dims = dims, chunk = dims;
  if (extendible) {
    max_dims[0] = H5S_UNLIMITED;
    chunk[0] = 1;
  }
  const OpenId space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), max_dims.data()));
  const OpenId create(H5Pcreate(H5P_DATASET_CREATE));
  if (extendible) H5Pset_chunk(create.get(), static_cast<int>(chunk.size()), chunk.data());
  const OpenId links(H5Pcreate(H5P_LINK_CREATE));
  H5Pset_create_intermediate_group(links.get(), 1);
  const OpenId dataset(
      H5Dcreate2(file, name, type, space.get(), links.get(), create.get(), H5P_DEFAULT));
  ASSERT_GE(dataset.get(), 0) << name;
  hsize_t n_values = 1;
  for (const hsize_t d : dims) n_values *= d;
  std::vector<Value> values(n_values);
  for (hsize_t i = 0; i < n_values; ++i) values[i] = static_cast<Value>(i);
  if (n_values > 0) {
    hid_t memory = H5T_NATIVE_DOUBLE;
    if constexpr (std::is_same_v<Value, std::int64_t>) memory = H5T_NATIVE_INT64;
    if constexpr (std::is_same_v<Value, std::int32_t>) memory = H5T_NATIVE_INT32;
    if constexpr (std::is_same_v<Value, std::int8_t>) memory = H5T_NATIVE_INT8;
    ASSERT_GE(H5Dwrite(dataset.get(), memory, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0)
        << name;
  }
}

// A variable-length string attribute of the root group, as the writer stores them.
void write_root_string(hid_t file, const char* name, const char* value) {
  const OpenId type(H5Tcopy(H5T_C_S1));
  H5Tset_size(type.get(), H5T_VARIABLE);
  const OpenId space(H5Screate(H5S_SCALAR));
  const OpenId attribute(H5Acreate2(file, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT));
  ASSERT_GE(attribute.get(), 0) << name;
  ASSERT_GE(H5Awrite(attribute.get(), type.get(), &value), 0) << name;
}

// The layout of docs/output.md with `times` as /time; root attribute format = `format`
// (none if null).
void write_series_file(const fs::path& path, const std::vector<double>& times,
                       const char* format = "catena-transient-1") {
  const OpenId file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  ASSERT_GE(file.get(), 0) << path;
  if (format != nullptr) write_root_string(file.get(), "format", format);
  const auto s = static_cast<hsize_t>(times.size());
  const auto n = static_cast<hsize_t>(n_nodes), e = static_cast<hsize_t>(n_elements);
  write_dataset<std::int64_t>(file.get(), "/mesh/node_ids", {n}, H5T_STD_I64LE, false);
  write_dataset<double>(file.get(), "/mesh/node_positions", {n, 3}, H5T_IEEE_F64LE, false);
  write_dataset<std::int64_t>(file.get(), "/mesh/element_ids", {e}, H5T_STD_I64LE, false);
  write_dataset<std::int64_t>(file.get(), "/mesh/element_nodes", {e, 2}, H5T_STD_I64LE, false);
  write_dataset<std::int8_t>(file.get(), "/mesh/element_kind", {e}, H5T_STD_I8LE, false);
  write_dataset<std::int32_t>(file.get(), "/mesh/element_set", {e}, H5T_STD_I32LE, false);
  for (const char* name : {"/samples/positions", "/samples/velocities", "/samples/slopes"})
    write_dataset<double>(file.get(), name, {s, n, 3}, H5T_IEEE_F64LE, true);
  write_dataset<double>(file.get(), "/samples/axial_force", {s, e}, H5T_IEEE_F64LE, true);
  // /time last, with the real values.
  const hsize_t max_rows = H5S_UNLIMITED, chunk = 16;
  const OpenId space(H5Screate_simple(1, &s, &max_rows));
  const OpenId create(H5Pcreate(H5P_DATASET_CREATE));
  H5Pset_chunk(create.get(), 1, &chunk);
  const OpenId time(H5Dcreate2(file.get(), "/time", H5T_IEEE_F64LE, space.get(), H5P_DEFAULT,
                               create.get(), H5P_DEFAULT));
  ASSERT_GE(time.get(), 0);
  if (!times.empty()) {
    ASSERT_GE(H5Dwrite(time.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, times.data()),
              0);
  }
}

// A scene's rigid bodies, joints and sliders, added to a file of write_series_file: their
// node indices (0, 1, ...: nodes of the mesh unless `n_bodies` exceeds it) and their series.
void add_bodies_and_sliders(const fs::path& path, hsize_t n_samples, hsize_t n_bodies,
                            hsize_t n_sliders, hsize_t n_joints = 3) {
  const OpenId file(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
  ASSERT_GE(file.get(), 0) << path;
  const hsize_t s = n_samples, b = n_bodies, r = n_sliders;
  write_dataset<std::int64_t>(file.get(), "/mesh/body_nodes", {b}, H5T_STD_I64LE, false);
  write_dataset<double>(file.get(), "/samples/body_orientation", {s, b, 4}, H5T_IEEE_F64LE, true);
  write_dataset<double>(file.get(), "/samples/body_angular_velocity", {s, b, 3}, H5T_IEEE_F64LE,
                        true);
  if (n_joints > 0)
    write_dataset<double>(file.get(), "/samples/joint_links", {s, n_joints, 4, 3}, H5T_IEEE_F64LE,
                          true);
  write_dataset<std::int64_t>(file.get(), "/mesh/slider_nodes", {r}, H5T_STD_I64LE, false);
  write_dataset<double>(file.get(), "/samples/slider_position", {s, r}, H5T_IEEE_F64LE, true);
  write_dataset<double>(file.get(), "/samples/slider_speed", {s, r}, H5T_IEEE_F64LE, true);
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::int64_t> numbers(const std::string& text) {
  std::vector<std::int64_t> values;
  std::istringstream in(text);
  for (std::int64_t value = 0; in >> value;) values.push_back(value);
  return values;
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t count = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++count;
  return count;
}

std::vector<std::int64_t> dataset_dims(hid_t file, const std::string& dataset) {
  const OpenId handle(H5Dopen2(file, dataset.c_str(), H5P_DEFAULT));
  if (handle.get() < 0) return {};
  const OpenId space(H5Dget_space(handle.get()));
  std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space.get())));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return {dims.begin(), dims.end()};
}

// Every DataItem pointing into the HDF5 file: the base name, an existing dataset, its shape;
// `n_expected` of them (by default the mesh grids' 13 each).
void check_hdf_references(const std::string& xml, const fs::path& hdf5_path,
                          const std::string& file_name_in_xml, std::size_t n_expected = 0) {
  const OpenId file(H5Fopen(hdf5_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  ASSERT_GE(file.get(), 0);
  const std::regex hdf_item(
      R"re(<DataItem Dimensions="([^"]*)"[^>]*Format="HDF">([^<:]*):([^<]*)</DataItem>)re");
  std::size_t n_items = 0;
  for (auto match = std::sregex_iterator(xml.begin(), xml.end(), hdf_item);
       match != std::sregex_iterator(); ++match, ++n_items) {
    EXPECT_EQ((*match)[2], file_name_in_xml);
    const std::string dataset = (*match)[3];
    const std::vector<std::int64_t> dims = dataset_dims(file.get(), dataset);
    ASSERT_FALSE(dims.empty()) << "the XDMF refers to a missing dataset " << dataset;
    EXPECT_EQ(numbers((*match)[1]), dims) << dataset;
  }
  // Per grid: element_nodes, positions four times (geometry, displacement, and sample k and
  // sample 0 of displacement_from_static), node_positions, velocities, slopes, axial_force,
  // node_ids, element_ids, element_kind, element_set.
  EXPECT_EQ(n_items, n_expected > 0 ? n_expected : 13 * count_of(xml, "GridType=\"Uniform\""));
}

// Every HyperSlab in grid k selects row k of its dataset, all of the row, stride 1 — but
// one: displacement_from_static's static position, row 0 of /samples/positions.
void check_hyperslabs(const std::string& grid, std::int64_t k, hid_t file) {
  int static_rows = 0;
  const std::regex hyperslab(
      R"re(<DataItem ItemType="HyperSlab" Dimensions="([^"]*)"[^>]*>(?:<!--[^>]*-->)?\s*)re"
      R"re(<DataItem Dimensions="3 ([0-9]+)"[^>]*Format="XML">([^<]*)</DataItem>\s*)re"
      R"re(<DataItem Dimensions="[^"]*"[^>]*Format="HDF">[^<:]*:([^<]*)</DataItem>\s*</DataItem>)re");
  std::vector<std::string> selected;
  for (auto match = std::sregex_iterator(grid.begin(), grid.end(), hyperslab);
       match != std::sregex_iterator(); ++match) {
    const std::string dataset = (*match)[4];
    selected.push_back(dataset);
    const std::vector<std::int64_t> dims = dataset_dims(file, dataset);
    const auto rank = static_cast<std::size_t>(std::stoll((*match)[2]));
    ASSERT_EQ(rank, dims.size()) << dataset;
    const std::vector<std::int64_t> selection = numbers((*match)[3]);
    ASSERT_EQ(selection.size(), 3 * rank) << dataset;
    const std::vector<std::int64_t> start(selection.begin(), selection.begin() + rank);
    const std::vector<std::int64_t> stride(selection.begin() + rank, selection.begin() + 2 * rank);
    const std::vector<std::int64_t> count(selection.begin() + 2 * rank, selection.end());
    std::vector<std::int64_t> expected_start(rank, 0), row = dims;
    expected_start[0] = k;
    if (k > 0 && start[0] == 0 && dataset == "/samples/positions") {
      ++static_rows;
      expected_start[0] = 0;
    }
    row[0] = 1;
    EXPECT_EQ(start, expected_start) << dataset << " in grid " << k;
    EXPECT_EQ(stride, std::vector<std::int64_t>(rank, 1)) << dataset;
    EXPECT_EQ(count, row) << dataset;
    EXPECT_EQ(numbers((*match)[1]), count) << "HyperSlab Dimensions of " << dataset;
    EXPECT_LT(k, dims[0]) << dataset;
  }
  std::sort(selected.begin(), selected.end());
  EXPECT_EQ(selected, (std::vector<std::string>{"/samples/axial_force", "/samples/positions",
                                                "/samples/positions", "/samples/positions",
                                                "/samples/positions", "/samples/slopes",
                                                "/samples/velocities"}))
      << "grid " << k;
  EXPECT_EQ(static_rows, k > 0 ? 1 : 0) << "grid " << k;
}

class TransientXdmfTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    directory_ =
        fs::temp_directory_path() / ("catena_test_transient_xdmf_" + std::string(test->name()) +
                                     "_" + std::to_string(::getpid()));
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }

  fs::path directory_;
};

TEST_F(TransientXdmfTest, ReadsSampleTimesBack) {
  const fs::path h5 = directory_ / "run.h5";
  write_series_file(h5, sample_times);
  EXPECT_EQ(catena::io::read_sample_times(h5.string()), sample_times);
}

TEST_F(TransientXdmfTest, XdmfPathReplacesTheExtension) {
  EXPECT_EQ(catena::io::transient_xdmf_path("out/run.h5"), "out/run.xmf");
  EXPECT_EQ(catena::io::transient_xdmf_path("run"), "run.xmf");
}

TEST_F(TransientXdmfTest, OneGridPerSampleSelectingItsRow) {
  const fs::path h5 = directory_ / "run.h5";
  write_series_file(h5, sample_times);
  const std::string xmf = catena::io::transient_xdmf_path(h5.string());
  catena::io::write_transient_xdmf(h5.string(), xmf, n_nodes, n_elements,
                                   catena::io::read_sample_times(h5.string()), legacy);
  EXPECT_EQ(directory_listing(directory_), (std::vector<std::string>{"run.h5", "run.xmf"}));

  const std::string xml = read_text(xmf);
  EXPECT_EQ(count_of(xml, "GridType=\"Collection\" CollectionType=\"Temporal\""), 1u);
  EXPECT_EQ(count_of(xml, "GridType=\"Uniform\""), sample_times.size());
  EXPECT_EQ(count_of(xml, "TopologyType=\"Polyline\" NodesPerElement=\"2\" NumberOfElements=\"3\""),
            sample_times.size());
  EXPECT_EQ(count_of(xml, "GeometryType=\"XYZ\""), sample_times.size());
  for (const char* attribute : {"Name=\"displacement\" AttributeType=\"Vector\" Center=\"Node\"",
                                "Name=\"velocities\" AttributeType=\"Vector\" Center=\"Node\"",
                                "Name=\"slopes\" AttributeType=\"Vector\" Center=\"Node\"",
                                "Name=\"axial_force\" AttributeType=\"Scalar\" Center=\"Cell\"",
                                "Name=\"node_ids\" AttributeType=\"Scalar\" Center=\"Node\"",
                                "Name=\"element_ids\" AttributeType=\"Scalar\" Center=\"Cell\"",
                                "Name=\"displacement_from_static\" AttributeType=\"Vector\" "
                                "Center=\"Node\"",
                                "Name=\"element_kind\" AttributeType=\"Scalar\" Center=\"Cell\"",
                                "Name=\"element_set\" AttributeType=\"Scalar\" Center=\"Cell\""})
    EXPECT_EQ(count_of(xml, attribute), sample_times.size()) << attribute;
  EXPECT_EQ(count_of(xml, "Function=\"$0 - $1\""), 2 * sample_times.size());
  check_hdf_references(xml, h5, "run.h5");

  const OpenId file(H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  ASSERT_GE(file.get(), 0);
  const std::string grid_tag = "<Grid Name=\"sample_";
  std::size_t at = xml.find(grid_tag);
  for (std::size_t k = 0; k < sample_times.size(); ++k) {
    ASSERT_NE(at, std::string::npos) << "grid " << k << " missing";
    const std::size_t next = xml.find(grid_tag, at + 1);
    const std::string grid = xml.substr(at, next == std::string::npos ? next : next - at);
    EXPECT_EQ(grid.rfind(grid_tag + std::to_string(k) + "\"", 0), 0u);
    const std::smatch time = [&] {
      std::smatch match;
      std::regex_search(grid, match, std::regex(R"re(<Time Value="([^"]*)"/>)re"));
      return match;
    }();
    ASSERT_FALSE(time.empty()) << "grid " << k;
    EXPECT_EQ(std::stod(time[1]), sample_times[k]) << "the time must read back exactly";
    // The geometry cache key of ParaView's XDMF Reader: unique per grid.
    EXPECT_EQ(count_of(grid, "<!-- sample " + std::to_string(k) + " -->"), 1u);
    check_hyperslabs(grid, static_cast<std::int64_t>(k), file.get());
    at = next;
  }
  EXPECT_EQ(at, std::string::npos) << "more grids than samples";
}

// The Xdmf3 readers' flavour: no HyperSlab or Function item; every sampled HDF reference of
// grid k selects row k in the "|start:stride:count:dimensions" syntax, with the dataset's
// shape as dimensions and the DataItem's Dimensions equal to the count; the mesh datasets
// referenced whole; no displacement attributes.
TEST_F(TransientXdmfTest, TheXdmf3FlavourSelectsTheSampleInsideTheReference) {
  const fs::path h5 = directory_ / "run.h5";
  write_series_file(h5, sample_times);
  const std::string xmf = catena::io::transient_xdmf_path(h5.string());
  EXPECT_EQ(catena::io::transient_xdmf2_path(h5.string()), xmf + "2");
  catena::io::write_transient_xdmf(h5.string(), xmf, n_nodes, n_elements, sample_times,
                                   catena::io::XdmfReaders::xdmf3);
  const std::string xml = read_text(xmf);
  EXPECT_EQ(count_of(xml, "HyperSlab"), 0u);
  EXPECT_EQ(count_of(xml, "Function"), 0u);
  EXPECT_EQ(count_of(xml, "Name=\"displacement"), 0u);
  EXPECT_EQ(count_of(xml, "GridType=\"Uniform\""), sample_times.size());
  const OpenId file(H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  ASSERT_GE(file.get(), 0);
  const std::regex item(
      R"re(<DataItem Dimensions="([^"]*)"[^>]*Format="HDF">(?:<!--[^>]*-->)?run\.h5:([^<|]*)(?:\|([^<]*))?</DataItem>)re");
  std::vector<std::int64_t> per_grid;
  std::int64_t grid = -1, selections = 0, whole = 0;
  const std::string grid_tag = "<Grid Name=\"sample_";
  for (std::size_t at = xml.find(grid_tag); at != std::string::npos;) {
    ++grid;
    const std::size_t next = xml.find(grid_tag, at + 1);
    const std::string text = xml.substr(at, next == std::string::npos ? next : next - at);
    for (auto m = std::sregex_iterator(text.begin(), text.end(), item); m != std::sregex_iterator();
         ++m) {
      const std::string dataset = (*m)[2];
      const std::vector<std::int64_t> dims = dataset_dims(file.get(), dataset);
      ASSERT_FALSE(dims.empty()) << dataset;
      if (!(*m)[3].matched) {
        ++whole;
        EXPECT_EQ(numbers((*m)[1]), dims) << dataset;
        continue;
      }
      ++selections;
      std::string selection = (*m)[3];
      std::replace(selection.begin(), selection.end(), ':', ' ');
      const std::vector<std::int64_t> values = numbers(selection);
      const std::size_t rank = dims.size();
      ASSERT_EQ(values.size(), 4 * rank) << dataset;
      std::vector<std::int64_t> start(rank, 0), stride(rank, 1), count = dims;
      start[0] = grid;
      count[0] = 1;
      EXPECT_EQ(std::vector<std::int64_t>(values.begin(), values.begin() + rank), start);
      EXPECT_EQ(std::vector<std::int64_t>(values.begin() + rank, values.begin() + 2 * rank),
                stride);
      EXPECT_EQ(std::vector<std::int64_t>(values.begin() + 2 * rank, values.begin() + 3 * rank),
                count);
      EXPECT_EQ(std::vector<std::int64_t>(values.begin() + 3 * rank, values.end()), dims);
      EXPECT_EQ(numbers((*m)[1]), count) << dataset;
    }
    at = next;
  }
  const auto n = static_cast<std::int64_t>(sample_times.size());
  EXPECT_EQ(grid + 1, n);
  // Per grid: positions, velocities, slopes, axial_force selected; element_nodes, node_ids,
  // element_ids, element_kind, element_set whole.
  EXPECT_EQ(selections, 4 * n);
  EXPECT_EQ(whole, 5 * n);
}

// Bodies and sliders are nodes outside the elements: a temporal collection each of vertex
// grids at their nodes (the node lists whole, the sampled positions and series at row k),
// and one of the joints' links (two segments per joint on row k of /samples/joint_links),
// in both flavours.
TEST_F(TransientXdmfTest, BodiesAndSlidersGetVertexGridsAtTheirNodes) {
  const fs::path h5 = directory_ / "run.h5";
  write_series_file(h5, sample_times);
  const auto n = static_cast<hsize_t>(sample_times.size());
  add_bodies_and_sliders(h5, n, 2, 1);
  const OpenId file(H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  ASSERT_GE(file.get(), 0);
  for (const auto readers : {legacy, catena::io::XdmfReaders::xdmf3}) {
    const std::string xmf = catena::io::transient_xdmf_path(h5.string());
    catena::io::write_transient_xdmf(h5.string(), xmf, n_nodes, n_elements, sample_times, readers);
    const std::string xml = read_text(xmf);
    for (const char* collection : {"samples", "bodies", "joints", "sliders"})
      EXPECT_EQ(count_of(xml, std::string("<Grid Name=\"") + collection +
                                  "\" GridType=\"Collection\" CollectionType=\"Temporal\">"),
                1u)
          << collection;
    EXPECT_EQ(count_of(xml, "GridType=\"Uniform\""), 4 * n);
    // Three joints: six segments over twelve points, each segment's joint as a cell value.
    EXPECT_EQ(count_of(xml,
                       "TopologyType=\"Polyline\" NodesPerElement=\"2\" "
                       "NumberOfElements=\"6\""),
              n);
    EXPECT_EQ(count_of(xml, "Format=\"XML\">0 1 2 3 4 5 6 7 8 9 10 11</DataItem>"), n);
    EXPECT_EQ(count_of(xml, "Format=\"XML\">0 0 1 1 2 2</DataItem>"), n);
    EXPECT_EQ(count_of(xml,
                       "TopologyType=\"Polyvertex\" NodesPerElement=\"1\" "
                       "NumberOfElements=\"2\""),
              n);
    EXPECT_EQ(count_of(xml,
                       "TopologyType=\"Polyvertex\" NodesPerElement=\"1\" "
                       "NumberOfElements=\"1\""),
              n);
    for (const char* attribute : {"Name=\"orientation\" AttributeType=\"Matrix\" Center=\"Cell\"",
                                  "Name=\"angular_velocity\" AttributeType=\"Vector\" "
                                  "Center=\"Cell\"",
                                  "Name=\"slider_position\" AttributeType=\"Scalar\" "
                                  "Center=\"Cell\"",
                                  "Name=\"slider_speed\" AttributeType=\"Scalar\" Center=\"Cell\""})
      EXPECT_EQ(count_of(xml, attribute), n) << attribute;
    // Per body grid: body_nodes, positions, velocities, slopes, orientation, angular
    // velocity; per slider grid: slider_nodes, positions, velocities, slider position and
    // speed; per joint grid: joint_links.
    if (readers == legacy) check_hdf_references(xml, h5, "run.h5", (13 + 6 + 5 + 1) * n);
    // Grid k of each collection: its time, and every sampled reference at row k.
    for (const std::string prefix : {"bodies_", "joints_", "sliders_"}) {
      for (std::size_t k = 0; k < n; ++k) {
        const std::string tag = "<Grid Name=\"" + prefix + std::to_string(k) + "\"";
        const std::size_t at = xml.find(tag);
        ASSERT_NE(at, std::string::npos) << tag;
        const std::string grid = xml.substr(at, xml.find("</Grid>", at) - at);
        std::smatch time;
        ASSERT_TRUE(std::regex_search(grid, time, std::regex(R"re(<Time Value="([^"]*)"/>)re")));
        EXPECT_EQ(std::stod(time[1]), sample_times[k]) << tag;
        const std::string row = std::to_string(k);
        // xdmf2: the HyperSlab's start, "k 0 ..." (its selection item has 3 rows); xdmf3:
        // "|k 0 ...:".
        const std::regex start(
            readers == legacy
                ? R"re(Dimensions="3 [0-9]+" NumberType="Int" Format="XML">([0-9]+) )re"
                : R"re(\|([0-9]+) )re");
        std::size_t n_selections = 0;
        for (auto m = std::sregex_iterator(grid.begin(), grid.end(), start);
             m != std::sregex_iterator(); ++m, ++n_selections)
          EXPECT_EQ((*m)[1], row) << tag;
        EXPECT_EQ(n_selections, prefix == "bodies_" ? 5u : prefix == "joints_" ? 1u : 4u) << tag;
      }
    }
    fs::remove(xmf);
  }
}

TEST_F(TransientXdmfTest, ReplacesAnOldXdmfAndEscapesTheFileName) {
  const fs::path h5 = directory_ / "a&b.h5";
  const fs::path xmf = directory_ / "a&b.xmf";
  write_series_file(h5, sample_times);
  std::ofstream(xmf) << "stale";
  catena::io::write_transient_xdmf(h5.string(), xmf.string(), n_nodes, n_elements, sample_times,
                                   legacy);
  const std::string xml = read_text(xmf);
  EXPECT_EQ(xml.find("stale"), std::string::npos);
  EXPECT_EQ(xml.find("a&b.h5"), std::string::npos);
  check_hdf_references(xml, h5, "a&amp;b.h5");
  EXPECT_EQ(directory_listing(directory_), (std::vector<std::string>{"a&b.h5", "a&b.xmf"}));
}

// Expects a catena::Error whose message contains every one of `parts`, and no .xmf.
template <class Write>
void expect_refused(const fs::path& directory, Write write, const std::vector<std::string>& parts,
                    const std::vector<std::string>& files_left) {
  try {
    write();
    ADD_FAILURE() << "no exception";
  } catch (const catena::Error& error) {
    for (const std::string& part : parts)
      EXPECT_NE(std::string(error.what()).find(part), std::string::npos)
          << "'" << part << "' not in: " << error.what();
  }
  EXPECT_EQ(directory_listing(directory), files_left);
}

// Bodies without joints: no joints collection (and a slider-only scene none of the bodies').
TEST_F(TransientXdmfTest, BodiesWithoutJointsGetNoJointGrids) {
  const fs::path h5 = directory_ / "run.h5";
  write_series_file(h5, sample_times);
  add_bodies_and_sliders(h5, sample_times.size(), 2, 1, 0);
  const std::string xmf = catena::io::transient_xdmf_path(h5.string());
  catena::io::write_transient_xdmf(h5.string(), xmf, n_nodes, n_elements, sample_times, legacy);
  const std::string xml = read_text(xmf);
  EXPECT_EQ(count_of(xml, "<Grid Name=\"bodies\" "), 1u);
  EXPECT_EQ(count_of(xml, "<Grid Name=\"joints"), 0u);
  EXPECT_EQ(count_of(xml, "joint_links"), 0u);
  check_hdf_references(xml, h5, "run.h5", (13 + 6 + 5) * sample_times.size());
}

// A joint_links dataset of another rank than (samples, joints, 4, 3) is refused.
TEST_F(TransientXdmfTest, RefusesJointLinksOfAnotherShape) {
  const fs::path h5 = directory_ / "run.h5";
  write_series_file(h5, sample_times);
  add_bodies_and_sliders(h5, sample_times.size(), 2, 1, 0);
  {
    const OpenId file(H5Fopen(h5.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
    write_dataset<double>(file.get(), "/samples/joint_links", {sample_times.size(), 3, 12},
                          H5T_IEEE_F64LE, true);
  }
  expect_refused(directory_,
                 [&] {
                   catena::io::write_transient_xdmf(h5.string(), (directory_ / "run.xmf").string(),
                                                    n_nodes, n_elements, sample_times, legacy);
                 },
                 {"run.xmf", "/samples/joint_links", "expected (samples, joints, 4, 3)"},
                 {"run.h5"});
}

// A body or slider node that is not a node of the mesh: the XDMF would draw a vertex that does
// not exist; refused, naming the dataset and the index.
TEST_F(TransientXdmfTest, RefusesABodyNodeOutsideTheMesh) {
  const fs::path h5 = directory_ / "run.h5";
  write_series_file(h5, sample_times);
  add_bodies_and_sliders(h5, sample_times.size(), n_nodes + 1, 1);
  expect_refused(directory_,
                 [&] {
                   catena::io::write_transient_xdmf(h5.string(), (directory_ / "run.xmf").string(),
                                                    n_nodes, n_elements, sample_times, legacy);
                 },
                 {"run.xmf", "/mesh/body_nodes", "node index 4", "mesh's 4 nodes"}, {"run.h5"});
}

// ParaView's XDMF Reader crashes on an empty temporal collection: no samples, no XDMF.
TEST_F(TransientXdmfTest, RefusesAFileWithoutSamples) {
  const fs::path h5 = directory_ / "empty.h5";
  write_series_file(h5, {});
  const std::vector<double> times = catena::io::read_sample_times(h5.string());
  EXPECT_TRUE(times.empty());
  expect_refused(directory_,
                 [&] {
                   catena::io::write_transient_xdmf(h5.string(),
                                                    (directory_ / "empty.xmf").string(), n_nodes,
                                                    n_elements, times, legacy);
                 },
                 {"empty.xmf", "no samples"}, {"empty.h5"});
}

TEST_F(TransientXdmfTest, RefusesShapesThatDoNotMatchTheFile) {
  const fs::path h5 = directory_ / "run.h5";
  const std::string xmf = (directory_ / "run.xmf").string();
  write_series_file(h5, sample_times);
  const std::vector<std::string> only_h5{"run.h5"};
  expect_refused(
      directory_,
      [&] {
        catena::io::write_transient_xdmf(h5.string(), xmf, n_nodes + 1, n_elements, sample_times,
                                         legacy);
      },
      {"run.xmf", "/mesh/node_ids", "shape (4), expected (5)"}, only_h5);
  expect_refused(
      directory_,
      [&] {
        catena::io::write_transient_xdmf(h5.string(), xmf, n_nodes, n_elements - 1, sample_times,
                                         legacy);
      },
      {"/mesh/element_ids"}, only_h5);
  const std::vector<double> fewer(sample_times.begin(), sample_times.end() - 1);
  expect_refused(
      directory_,
      [&] {
        catena::io::write_transient_xdmf(h5.string(), xmf, n_nodes, n_elements, fewer, legacy);
      },
      {"/time", "shape (5), expected (4)"}, only_h5);
  expect_refused(
      directory_,
      [&] {
        catena::io::write_transient_xdmf((directory_ / "missing.h5").string(), xmf, n_nodes,
                                         n_elements, sample_times, legacy);
      },
      {"H5Fopen", "missing.h5"}, only_h5);
}

// A file of another format (another version, or a static result) or of none is refused by
// both functions, naming the file, the format found and the one expected.
TEST_F(TransientXdmfTest, RefusesAFileOfAnotherFormat) {
  const fs::path h5 = directory_ / "other.h5";
  const std::string xmf = (directory_ / "other.xmf").string();
  for (const char* format : {"catena-transient-0", "catena-static-1"}) {
    write_series_file(h5, sample_times, format);
    const std::string found = std::string("format '") + format + "'";
    expect_refused(directory_, [&] { catena::io::read_sample_times(h5.string()); },
                   {"other.h5", found, "expected 'catena-transient-1'"}, {"other.h5"});
    expect_refused(directory_,
                   [&] {
                     catena::io::write_transient_xdmf(h5.string(), xmf, n_nodes, n_elements,
                                                      sample_times, legacy);
                   },
                   {"other.xmf", "other.h5", found, "expected 'catena-transient-1'"}, {"other.h5"});
  }
  write_series_file(h5, sample_times, nullptr);
  expect_refused(directory_, [&] { catena::io::read_sample_times(h5.string()); },
                 {"other.h5", "'format': missing", "expected 'catena-transient-1'"}, {"other.h5"});
}

TEST_F(TransientXdmfTest, RefusesAnXdmfOutsideTheHdf5Directory) {
  const fs::path h5 = directory_ / "run.h5";
  write_series_file(h5, sample_times);
  fs::create_directory(directory_ / "elsewhere");
  expect_refused(directory_,
                 [&] {
                   catena::io::write_transient_xdmf(h5.string(),
                                                    (directory_ / "elsewhere" / "run.xmf").string(),
                                                    n_nodes, n_elements, sample_times, legacy);
                 },
                 {"base name"}, {"elsewhere", "run.h5"});
  expect_refused(directory_,
                 [&] {
                   catena::io::write_transient_xdmf(h5.string(), h5.string(), n_nodes, n_elements,
                                                    sample_times, legacy);
                 },
                 {"would replace"}, {"elsewhere", "run.h5"});
  EXPECT_TRUE(fs::is_empty(directory_ / "elsewhere"));
}

}  // namespace
