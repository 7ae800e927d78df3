// write_static_result on 1, 2 and 3 ranks. A synthetic line model whose nodes and
// elements are owned in an interleaved, rank-count-dependent pattern (non-contiguous rows,
// a rank with no elements at np = 3, support rows whose rank order is not their node order,
// and at np = 3 a rank whose support block is empty, so it writes an empty selection) is
// written in parallel; rank 0 reopens the file with serial HDF5 and checks every dataset,
// every attribute and the XDMF companion against values computed from the indices — the
// same values whatever the rank count. The failure tests check that every rank throws and
// that no file appears at (or replaces) the target path.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/hdf5_writer.hpp"
#include "hdf5_id.hpp"
#include "test_directory.hpp"

namespace {

namespace fs = std::filesystem;
using catena::io::RunInfo;
using catena::io::StaticResult;
using catena::model::Model;
using catena::test::directory_listing;
using catena::test::OpenId;

int comm_rank() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

int comm_size() {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

// ---- The synthetic model and its solution, both functions of the indices only. ----

constexpr int n_line_nodes = 10;
constexpr int n_line_elements = n_line_nodes - 1;  // elements 0..8 along the line
constexpr int bar_element = 9;                     // nodes 2–7 (a dropper)
constexpr int spring_element = 10;                 // nodes 3–6
constexpr int n_elements = 11;
const std::vector<int> support_node_list{4, 9};  // elastic support, clamp

catena::Vec3 reference_position(int node) { return {1.5 * node, 0.0, 0.2 * node}; }

catena::Vec3 solved_position(int node) {
  return reference_position(node) +
         catena::Vec3(0.001 * node, -0.002 * node, -0.01 * node * (n_line_nodes - 1 - node));
}

catena::Vec3 solved_slope(int node) { return {1.0, 0.0, 0.1 * node - 0.45}; }
double axial_force(int element) { return 1000.0 + 10.0 * element; }
double axial_strain(int element) { return 1e-4 * (element + 1); }
catena::Vec3 shear_force(int element) { return {element + 0.5, -2.0 * element, 3.0}; }
catena::Vec3 bending_moment(int element) { return {-1.0, element + 0.25, 7.0 * element}; }
double torsion(int element) { return 0.1 * element - 1.0; }
catena::Vec3 reaction_force(int node) { return {node + 0.5, -2.0 * node, 100.0 + node}; }
catena::Vec3 reaction_moment(int node) { return {0.25 * node, 0.0, -1.0 * node}; }

std::int8_t expected_kind(int element) {  // cable 0, beam 1, bar 2, spring 3
  if (element == bar_element) return 2;
  if (element == spring_element) return 3;
  return element == 7 ? 1 : 0;
}

// Sets sorted by name: "contact_wire" = 0, "messenger" = 1; the bar and spring have none.
std::int32_t expected_set(int element) {
  if (element >= n_line_elements) return -1;
  return element < 5 ? 1 : 0;
}

// Scene text longer than HDF5's 64 KiB limit for compact attributes.
std::string long_scene_text() {
  std::string text = "# synthetic line for the HDF5 writer test\n";
  for (int line = 0; text.size() < 100 * 1024; ++line)
    text += "# filler line " + std::to_string(line) + " of a long scene\n";
  return text;
}

Model line_model() {
  Model model;
  model.name = "line";
  model.source_file = "scenes/line.yaml";
  model.source_text = long_scene_text();
  for (int i = 0; i < n_line_nodes; ++i) {
    catena::model::Node node;
    node.id = 100 + i;
    node.position = reference_position(i);
    model.nodes.push_back(node);
  }
  for (int e = 0; e < n_line_elements; ++e) {
    catena::model::ElementDesc element;
    element.id = 1000 + e;
    element.nodes = {e, e + 1};
    if (e == 7)
      element.props = catena::model::BeamProps{};
    else
      element.props = catena::model::CableProps{};
    element.set = e < 5 ? "messenger" : "contact_wire";
    model.elements.push_back(element);
  }
  model.elements.push_back({2000, {2, 7}, catena::model::BarProps{}, catena::Vec3::Zero(), ""});
  model.elements.push_back({3000, {3, 6}, catena::model::SpringProps{}, catena::Vec3::Zero(), ""});
  model.supports = {{9, 0x3Fu}};
  model.elastic_supports = {{4, catena::Vec3(1e5, 1e5, 1e5), catena::Vec3::Zero()}};
  return model;
}

// Interleaved ownership that depends on the rank count. np = 2: rank 0 owns nodes
// {0,1,4,5,6,8}, rank 1 {2,3,7,9}; np = 3: {0,1,7,9}, {2,3,8}, {4,5,6}, so rank 0 reports
// support 9 and rank 2 support 4: rank order differs from node order.
int node_owner(int node, int n_ranks) { return (node % 3 == 0 ? node / 3 : node / 2) % n_ranks; }

// Even elements on rank 0, odd ones on the last rank: at np = 3, rank 1 owns none.
int element_owner(int element, int n_ranks) { return element % 2 == 0 ? 0 : n_ranks - 1; }

void append(std::vector<double>& values, const catena::Vec3& v) {
  values.insert(values.end(), {v.x(), v.y(), v.z()});
}

StaticResult my_share_of_solution(int rank, int n_ranks) {
  StaticResult result;
  for (int node = 0; node < n_line_nodes; ++node) {
    if (node_owner(node, n_ranks) != rank) continue;
    result.owned_nodes.push_back(node);
    append(result.positions, solved_position(node));
    append(result.slopes, solved_slope(node));
    if (std::find(support_node_list.begin(), support_node_list.end(), node) !=
        support_node_list.end()) {
      result.support_nodes.push_back(node);
      append(result.reaction_force, reaction_force(node));
      append(result.reaction_moment, reaction_moment(node));
    }
  }
  for (int element = 0; element < n_elements; ++element) {
    if (element_owner(element, n_ranks) != rank) continue;
    result.owned_elements.push_back(element);
    result.axial_force.push_back(axial_force(element));
    result.axial_strain.push_back(axial_strain(element));
    append(result.shear_force, shear_force(element));
    append(result.bending_moment, bending_moment(element));
    result.torsion.push_back(torsion(element));
  }
  result.load_factor = 1.0;
  result.n_load_steps = 3;
  result.n_newton_iterations = 17;
  result.residual_norm = 1.25e-9;
  return result;
}

RunInfo run_info() {
  RunInfo info;
  info.code_version = "0.1.0-test";
  info.command_line = "catena scenes/line.yaml --output line.h5";
  info.petsc_options = "-snes_rtol 1e-10 -pc_type lu";
  info.n_ranks = comm_size();
  info.n_dofs = 6 * n_line_nodes;
  return info;
}

// ---- Serial reading on rank 0. ----

template <class Value>
struct Dataset {
  std::vector<hsize_t> dims;
  std::vector<Value> values;
  std::string unit;  // "" if the dataset has none
  bool stored_as_expected_type = false;
};

std::string read_string_attribute(hid_t object, const char* name) {
  const OpenId attribute(H5Aopen(object, name, H5P_DEFAULT));
  if (attribute.get() < 0) return "<missing attribute " + std::string(name) + ">";
  const OpenId type(H5Aget_type(attribute.get()));
  char* text = nullptr;
  if (H5Aread(attribute.get(), type.get(), &text) < 0 || text == nullptr)
    return "<unreadable attribute " + std::string(name) + ">";
  std::string value(text);
  H5free_memory(text);
  return value;
}

std::vector<std::string> read_string_list_attribute(hid_t object, const char* name) {
  const OpenId attribute(H5Aopen(object, name, H5P_DEFAULT));
  if (attribute.get() < 0) return {"<missing>"};
  const OpenId type(H5Aget_type(attribute.get()));
  const OpenId space(H5Aget_space(attribute.get()));
  std::vector<char*> texts(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get())));
  if (!texts.empty()) H5Aread(attribute.get(), type.get(), texts.data());
  std::vector<std::string> values;
  for (char* text : texts) {
    values.emplace_back(text != nullptr ? text : "");
    H5free_memory(text);
  }
  return values;
}

template <class Value>
Value read_scalar_attribute(hid_t object, const char* name, hid_t memory_type) {
  Value value{};
  const OpenId attribute(H5Aopen(object, name, H5P_DEFAULT));
  EXPECT_GE(attribute.get(), 0) << "missing attribute " << name;
  if (attribute.get() >= 0) H5Aread(attribute.get(), memory_type, &value);
  return value;
}

template <class Value>
Dataset<Value> read_dataset(hid_t file, const char* name, hid_t memory_type, hid_t file_type) {
  Dataset<Value> dataset;
  const OpenId handle(H5Dopen2(file, name, H5P_DEFAULT));
  EXPECT_GE(handle.get(), 0) << "missing dataset " << name;
  if (handle.get() < 0) return dataset;
  const OpenId space(H5Dget_space(handle.get()));
  dataset.dims.resize(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space.get())));
  H5Sget_simple_extent_dims(space.get(), dataset.dims.data(), nullptr);
  dataset.values.resize(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get())));
  if (!dataset.values.empty()) {
    EXPECT_GE(
        H5Dread(handle.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, dataset.values.data()),
        0);
  }
  const OpenId stored_type(H5Dget_type(handle.get()));
  dataset.stored_as_expected_type = H5Tequal(stored_type.get(), file_type) > 0;
  if (H5Aexists(handle.get(), "unit") > 0)
    dataset.unit = read_string_attribute(handle.get(), "unit");
  return dataset;
}

Dataset<double> read_doubles(hid_t file, const char* name) {
  return read_dataset<double>(file, name, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE);
}

Dataset<std::int64_t> read_int64s(hid_t file, const char* name) {
  return read_dataset<std::int64_t>(file, name, H5T_NATIVE_INT64, H5T_STD_I64LE);
}

void expect_vectors(const Dataset<double>& dataset, const std::vector<int>& rows,
                    catena::Vec3 (*expected)(int), const char* name) {
  ASSERT_EQ(dataset.dims, (std::vector<hsize_t>{rows.size(), 3})) << name;
  for (std::size_t k = 0; k < rows.size(); ++k)
    for (int i = 0; i < 3; ++i)
      EXPECT_DOUBLE_EQ(dataset.values[3 * k + static_cast<std::size_t>(i)], expected(rows[k])[i])
          << name << " row " << k << " component " << i;
}

std::vector<int> all_nodes() {
  std::vector<int> nodes(n_line_nodes);
  for (int i = 0; i < n_line_nodes; ++i) nodes[static_cast<std::size_t>(i)] = i;
  return nodes;
}

catena::Vec3 displacement(int node) { return solved_position(node) - reference_position(node); }

void check_mesh(hid_t file) {
  const Model model = line_model();
  const auto node_ids = read_int64s(file, "/mesh/node_ids");
  ASSERT_EQ(node_ids.dims, (std::vector<hsize_t>{n_line_nodes}));
  EXPECT_TRUE(node_ids.stored_as_expected_type);
  for (int i = 0; i < n_line_nodes; ++i) EXPECT_EQ(node_ids.values[std::size_t(i)], 100 + i);

  const auto node_positions = read_doubles(file, "/mesh/node_positions");
  expect_vectors(node_positions, all_nodes(), reference_position, "node_positions");
  EXPECT_EQ(node_positions.unit, "m");

  const auto element_ids = read_int64s(file, "/mesh/element_ids");
  const auto element_nodes = read_int64s(file, "/mesh/element_nodes");
  ASSERT_EQ(element_ids.dims, (std::vector<hsize_t>{n_elements}));
  ASSERT_EQ(element_nodes.dims, (std::vector<hsize_t>{n_elements, 2}));
  EXPECT_TRUE(element_nodes.stored_as_expected_type);
  for (std::size_t e = 0; e < std::size_t(n_elements); ++e) {
    EXPECT_EQ(element_ids.values[e], model.elements[e].id);
    EXPECT_EQ(element_nodes.values[2 * e], model.elements[e].nodes[0]) << "element " << e;
    EXPECT_EQ(element_nodes.values[2 * e + 1], model.elements[e].nodes[1]) << "element " << e;
  }

  const auto kinds =
      read_dataset<std::int8_t>(file, "/mesh/element_kind", H5T_NATIVE_INT8, H5T_STD_I8LE);
  const auto sets =
      read_dataset<std::int32_t>(file, "/mesh/element_set", H5T_NATIVE_INT32, H5T_STD_I32LE);
  ASSERT_EQ(kinds.dims, (std::vector<hsize_t>{n_elements}));
  ASSERT_EQ(sets.dims, (std::vector<hsize_t>{n_elements}));
  EXPECT_TRUE(kinds.stored_as_expected_type);
  EXPECT_TRUE(sets.stored_as_expected_type);
  for (int e = 0; e < n_elements; ++e) {
    EXPECT_EQ(kinds.values[std::size_t(e)], expected_kind(e)) << "element " << e;
    EXPECT_EQ(sets.values[std::size_t(e)], expected_set(e)) << "element " << e;
  }
  const OpenId kind_dataset(H5Dopen2(file, "/mesh/element_kind", H5P_DEFAULT));
  EXPECT_EQ(read_string_attribute(kind_dataset.get(), "kinds"), "cable,beam,bar,spring");
  const OpenId set_dataset(H5Dopen2(file, "/mesh/element_set", H5P_DEFAULT));
  EXPECT_EQ(read_string_list_attribute(set_dataset.get(), "set_names"),
            (std::vector<std::string>{"contact_wire", "messenger"}));
}

void check_solution(hid_t file) {
  const auto positions = read_doubles(file, "/static/positions");
  expect_vectors(positions, all_nodes(), solved_position, "positions");
  EXPECT_EQ(positions.unit, "m");
  const auto slopes = read_doubles(file, "/static/slopes");
  expect_vectors(slopes, all_nodes(), solved_slope, "slopes");
  EXPECT_EQ(slopes.unit, "1");
  const auto displacements = read_doubles(file, "/static/displacements");
  expect_vectors(displacements, all_nodes(), displacement, "displacements");
  EXPECT_EQ(displacements.unit, "m");

  const auto forces = read_doubles(file, "/static/axial_force");
  const auto strains = read_doubles(file, "/static/axial_strain");
  ASSERT_EQ(forces.dims, (std::vector<hsize_t>{n_elements}));
  ASSERT_EQ(strains.dims, (std::vector<hsize_t>{n_elements}));
  for (int e = 0; e < n_elements; ++e) {
    EXPECT_DOUBLE_EQ(forces.values[std::size_t(e)], axial_force(e));
    EXPECT_DOUBLE_EQ(strains.values[std::size_t(e)], axial_strain(e));
  }
  EXPECT_EQ(forces.unit, "N");
  EXPECT_EQ(strains.unit, "1");
  const auto shear = read_doubles(file, "/static/shear_force");
  const auto moment = read_doubles(file, "/static/bending_moment");
  const auto twist = read_doubles(file, "/static/torsion");
  ASSERT_EQ(shear.dims, (std::vector<hsize_t>{n_elements, 3}));
  ASSERT_EQ(moment.dims, (std::vector<hsize_t>{n_elements, 3}));
  ASSERT_EQ(twist.dims, (std::vector<hsize_t>{n_elements}));
  for (int e = 0; e < n_elements; ++e) {
    for (int d = 0; d < 3; ++d) {
      EXPECT_DOUBLE_EQ(shear.values[std::size_t(3 * e + d)], shear_force(e)[d]);
      EXPECT_DOUBLE_EQ(moment.values[std::size_t(3 * e + d)], bending_moment(e)[d]);
    }
    EXPECT_DOUBLE_EQ(twist.values[std::size_t(e)], torsion(e));
  }
  EXPECT_EQ(shear.unit, "N");
  EXPECT_EQ(moment.unit, "N m");
  EXPECT_EQ(twist.unit, "N m");

  const auto supports = read_int64s(file, "/static/support_nodes");
  ASSERT_EQ(supports.dims, (std::vector<hsize_t>{support_node_list.size()}));
  EXPECT_EQ(supports.values, (std::vector<std::int64_t>{4, 9}));  // node order, any np
  const auto reactions = read_doubles(file, "/static/reaction_force");
  expect_vectors(reactions, support_node_list, reaction_force, "reaction_force");
  EXPECT_EQ(reactions.unit, "N");
  const auto moments = read_doubles(file, "/static/reaction_moment");
  expect_vectors(moments, support_node_list, reaction_moment, "reaction_moment");
  EXPECT_EQ(moments.unit, "N m");
}

void check_attributes(hid_t file) {
  const RunInfo info = run_info();
  EXPECT_EQ(read_string_attribute(file, "format"), "catena-static-1");
  EXPECT_EQ(read_string_attribute(file, "units"), "SI");
  EXPECT_EQ(read_string_attribute(file, "scene_text"), long_scene_text());
  EXPECT_EQ(read_string_attribute(file, "scene_file"), "scenes/line.yaml");
  EXPECT_EQ(read_string_attribute(file, "code_version"), info.code_version);
  EXPECT_EQ(read_string_attribute(file, "command_line"), info.command_line);
  EXPECT_EQ(read_string_attribute(file, "petsc_options"), info.petsc_options);
  EXPECT_EQ(read_scalar_attribute<std::int64_t>(file, "n_ranks", H5T_NATIVE_INT64), comm_size());
  EXPECT_EQ(read_scalar_attribute<std::int64_t>(file, "n_dofs", H5T_NATIVE_INT64), info.n_dofs);

  const OpenId solution(H5Gopen2(file, "/static", H5P_DEFAULT));
  ASSERT_GE(solution.get(), 0);
  EXPECT_DOUBLE_EQ(read_scalar_attribute<double>(solution.get(), "load_factor", H5T_NATIVE_DOUBLE),
                   1.0);
  EXPECT_EQ(read_scalar_attribute<std::int64_t>(solution.get(), "n_load_steps", H5T_NATIVE_INT64),
            3);
  EXPECT_EQ(
      read_scalar_attribute<std::int64_t>(solution.get(), "n_newton_iterations", H5T_NATIVE_INT64),
      17);
  EXPECT_DOUBLE_EQ(
      read_scalar_attribute<double>(solution.get(), "residual_norm", H5T_NATIVE_DOUBLE), 1.25e-9);
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every DataItem must point into the HDF5 file by its base name, at a dataset that exists
// with the shape the DataItem announces.
void check_xdmf(const fs::path& xdmf_path, const fs::path& hdf5_path) {
  ASSERT_TRUE(fs::is_regular_file(xdmf_path)) << xdmf_path;
  const std::string xml = read_text(xdmf_path);
  EXPECT_NE(xml.find("TopologyType=\"Polyline\""), std::string::npos);
  EXPECT_NE(xml.find("NodesPerElement=\"2\""), std::string::npos);
  EXPECT_NE(xml.find("GeometryType=\"XYZ\""), std::string::npos);

  const OpenId file(H5Fopen(hdf5_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  ASSERT_GE(file.get(), 0);
  const std::regex data_item(
      R"re(<DataItem Dimensions="([^"]*)"[^>]*>([^<:]*):([^<]*)</DataItem>)re");
  std::map<std::string, std::string> dimensions_of;
  for (auto match = std::sregex_iterator(xml.begin(), xml.end(), data_item);
       match != std::sregex_iterator(); ++match) {
    const std::string file_name = (*match)[2], dataset = (*match)[3];
    EXPECT_EQ(file_name, hdf5_path.filename().string());
    dimensions_of[dataset] = (*match)[1];
    const OpenId handle(H5Dopen2(file.get(), dataset.c_str(), H5P_DEFAULT));
    ASSERT_GE(handle.get(), 0) << "the XDMF refers to a missing dataset " << dataset;
    const OpenId space(H5Dget_space(handle.get()));
    std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space.get())));
    H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
    std::string shape;
    for (const hsize_t d : dims) {
      if (!shape.empty()) shape += ' ';
      shape += std::to_string(d);
    }
    EXPECT_EQ((*match)[1], shape) << dataset;
  }
  for (const char* required : {"/mesh/element_nodes", "/static/positions", "/static/displacements",
                               "/static/axial_force", "/static/axial_strain", "/mesh/element_kind"})
    EXPECT_EQ(dimensions_of.count(required), 1u) << required;
}

// ---- Fixture: a fresh directory per test, shared by all ranks. ----

class Hdf5WriterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_pid_ = catena::test::root_process_id();
    directory_ = catena::test::fresh_test_directory("catena_test_io");
  }

  void TearDown() override { catena::test::remove_test_directory(directory_); }

  fs::path temporary_name(const fs::path& target) const {
    fs::path name = target;
    name += ".tmp-" + std::to_string(root_pid_);
    return name;
  }

  // Collective. Writes the synthetic solution; returns the message if it threw
  // catena::Error (any other exception fails the test).
  std::string write_and_catch(const fs::path& path, const StaticResult& result) const {
    try {
      catena::io::write_static_result(MPI_COMM_WORLD, path.string(), line_model(), result,
                                      run_info());
    } catch (const catena::Error& error) {
      return error.what();
    }
    return {};
  }

  // Collective. Expects write to fail on every rank with a message containing `expected`.
  void expect_failure_on_every_rank(const fs::path& path, const StaticResult& result,
                                    const std::string& expected) const {
    const std::string message = write_and_catch(path, result);
    EXPECT_FALSE(message.empty()) << "rank " << comm_rank() << " did not throw";
    EXPECT_NE(message.find(expected), std::string::npos) << message;
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    MPI_Barrier(MPI_COMM_WORLD);
  }

  static void write_text(const fs::path& path, const std::string& text) {
    std::ofstream(path) << text;
  }

  fs::path directory_;
  long long root_pid_ = 0;
};

TEST_F(Hdf5WriterTest, WritesEveryDatasetAndAttributeIndependentlyOfTheRankCount) {
  const fs::path path = directory_ / "line.h5";
  if (comm_rank() == 0) write_text(path, "an older result, to be replaced");
  MPI_Barrier(MPI_COMM_WORLD);

  const std::string message = write_and_catch(path, my_share_of_solution(comm_rank(), comm_size()));
  ASSERT_EQ(message, "");
  if (comm_rank() != 0) return;

  ASSERT_GT(H5Fis_hdf5(path.c_str()), 0);
  {
    const OpenId file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
    ASSERT_GE(file.get(), 0);
    check_mesh(file.get());
    check_solution(file.get());
    check_attributes(file.get());
  }
  check_xdmf(directory_ / "line.xmf", path);
  EXPECT_EQ(directory_listing(directory_), (std::vector<std::string>{"line.h5", "line.xmf"}));
}

TEST_F(Hdf5WriterTest, MissingDirectoryFailsOnEveryRankAndCreatesNothing) {
  const fs::path path = directory_ / "no_such_directory" / "line.h5";
  expect_failure_on_every_rank(path, my_share_of_solution(comm_rank(), comm_size()),
                               "does not exist");
  if (comm_rank() == 0) {
    EXPECT_TRUE(directory_listing(directory_).empty());
  }
}

// H5Fcreate itself fails (its temporary name is taken by a directory): the error names the
// HDF5 call, and the existing file at the target path is left as it was.
TEST_F(Hdf5WriterTest, FailingH5FcreateNamesTheCallAndKeepsTheOldFile) {
  const fs::path path = directory_ / "line.h5";
  if (comm_rank() == 0) {
    write_text(path, "old");
    fs::create_directory(temporary_name(path));
  }
  MPI_Barrier(MPI_COMM_WORLD);
  expect_failure_on_every_rank(path, my_share_of_solution(comm_rank(), comm_size()),
                               "H5Fcreate failed");
  if (comm_rank() != 0) return;
  EXPECT_EQ(read_text(path), "old");
  EXPECT_TRUE(fs::is_directory(temporary_name(path))) << "not ours to remove";
  EXPECT_FALSE(fs::exists(directory_ / "line.xmf"));
}

// The HDF5 data are complete when the XDMF cannot be written (its temporary name is taken):
// the finished HDF5 temporary is removed and neither target appears or changes.
TEST_F(Hdf5WriterTest, FailureAfterTheDataAreWrittenRemovesTheTemporaryFile) {
  const fs::path path = directory_ / "line.h5";
  const fs::path xdmf_path = directory_ / "line.xmf";
  if (comm_rank() == 0) {
    write_text(path, "old");
    fs::create_directory(temporary_name(xdmf_path));
  }
  MPI_Barrier(MPI_COMM_WORLD);
  expect_failure_on_every_rank(path, my_share_of_solution(comm_rank(), comm_size()), "open failed");
  if (comm_rank() != 0) return;
  EXPECT_EQ(read_text(path), "old");
  EXPECT_FALSE(fs::exists(temporary_name(path)));
  EXPECT_FALSE(fs::exists(xdmf_path));
}

// One rank drops a node it owns: the gap is found by whichever rank writes that row, and
// every rank reports it.
TEST_F(Hdf5WriterTest, NodeOwnedByNoRankFailsOnEveryRank) {
  StaticResult result = my_share_of_solution(comm_rank(), comm_size());
  constexpr int dropped_node = 5;
  if (node_owner(dropped_node, comm_size()) == comm_rank()) {
    const auto at = std::find(result.owned_nodes.begin(), result.owned_nodes.end(), dropped_node);
    const auto row = at - result.owned_nodes.begin();
    result.owned_nodes.erase(at);
    result.positions.erase(result.positions.begin() + 3 * row,
                           result.positions.begin() + 3 * row + 3);
    result.slopes.erase(result.slopes.begin() + 3 * row, result.slopes.begin() + 3 * row + 3);
  }
  const fs::path path = directory_ / "line.h5";
  expect_failure_on_every_rank(path, result,
                               "row 5 of StaticResult::owned_nodes is owned by no rank");
  if (comm_rank() == 0) {
    EXPECT_TRUE(directory_listing(directory_).empty());
  }
}

// A malformed result on the last rank only: checked before any file is created.
TEST_F(Hdf5WriterTest, MalformedResultOnOneRankFailsOnEveryRank) {
  StaticResult result = my_share_of_solution(comm_rank(), comm_size());
  if (comm_rank() == comm_size() - 1) result.axial_strain.push_back(0.0);
  const fs::path path = directory_ / "line.h5";
  expect_failure_on_every_rank(path, result, "StaticResult::axial_strain");
  if (comm_rank() == 0) {
    EXPECT_TRUE(directory_listing(directory_).empty());
  }
}

}  // namespace
