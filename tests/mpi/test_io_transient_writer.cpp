// The time-series file of TransientWriter on 1, 2 and 3 ranks, read back on rank 0: the
// objects and root attributes are exactly those of docs/output.md ("Time series",
// "Contact forces and pantographs"), with `format` = "catena-transient-1" and the scene in
// `scene_text`; the run reader of `catena stats` (catena::io::read_contact_run) reads the
// writer's file; and a file of another format, or of none, is refused by the reader and by
// a restart's writer, naming the file, the format found and the one expected.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/io/contact_run_reader.hpp"
#include "catena/io/transient_writer.hpp"
#include "hdf5_id.hpp"
#include "model_builders.hpp"
#include "test_directory.hpp"

namespace {

namespace fs = std::filesystem;
using catena::test::OpenId;

int comm_rank() { return catena::mpi_rank(MPI_COMM_WORLD); }
int comm_size() { return catena::mpi_size(MPI_COMM_WORLD); }

constexpr int n_elements = 8;
constexpr int n_nodes = n_elements + 1;
constexpr int n_samples = 6;
constexpr double interval = 0.1;  // s between samples
constexpr double speed = 20.0;    // m/s
constexpr double start = 1.0;     // m
const std::vector<int> registration{0, 4, 8};

// An 8 m line along x (node i at x = i) with one pantograph running along it.
catena::model::Model line_with_pantograph() {
  catena::model::Model model;
  model.name = "line";
  model.source_file = "line.yaml";
  model.source_text = "# a line with a pantograph\n";
  catena::test::add_line(model, {0, 0, 0}, {double(n_elements), 0, 0}, n_elements,
                         catena::model::CableProps{});
  catena::model::ElementPath wire{"wire", {}};
  for (int e = 0; e < n_elements; ++e) wire.elements.push_back(e);
  model.paths.push_back(wire);
  catena::model::MovingContact pantograph;
  pantograph.name = "leading";
  pantograph.path = 0;
  pantograph.speed = speed;
  pantograph.start = start;
  model.contacts.push_back(pantograph);
  model.registration_nodes = registration;
  model.evaluation_start = 2.0;
  model.evaluation_end = 7.0;
  return model;
}

std::vector<int> my_rows(int n_rows) {
  std::vector<int> rows;
  for (int row = comm_rank(); row < n_rows; row += comm_size()) rows.push_back(row);
  return rows;
}

double height(int node, int sample) { return 0.001 * sample * (node + 1); }
double contact_force(int sample) { return 100.0 + sample; }
// The steps' heights differ from the samples', so that a reader taking one for the other
// is caught.
double step_height(int node, int step) { return 0.5 + height(node, step); }

// Collective. Writes n_samples samples of made-up values and closes with "complete".
void write_run(const fs::path& path, const catena::model::Model& model) {
  catena::io::RunInfo info;
  info.n_ranks = comm_size();
  info.run_id = "0123456789abcdef0123456789abcdef";
  catena::io::TransientWriter writer(MPI_COMM_WORLD, path.string(), model, info, my_rows(n_nodes),
                                     my_rows(n_elements));
  for (int k = 0; k < n_samples; ++k) {
    const double t = k * interval;
    std::vector<double> positions, zeros, axial;
    for (const int node : my_rows(n_nodes)) {
      positions.insert(positions.end(), {double(node), 0.0, height(node, k)});
      zeros.insert(zeros.end(), {0.0, 0.0, 0.0});
    }
    for (const int element : my_rows(n_elements)) axial.push_back(1000.0 + element);
    const catena::io::ContactSample contacts{{contact_force(k)}, {start + speed * t}};
    writer.append_sample(t, positions, zeros, zeros, axial, {}, contacts);
    std::vector<double> step_heights;
    for (const int node : registration) step_heights.push_back(step_height(node, k));
    writer.append_step({t, interval, 2, -1.0, 0, {contact_force(k)}, step_heights});
  }
  writer.close("complete", {{"steps_accepted", double(n_samples)}});
}

// Every link's path below the root (groups and datasets), and every attribute's name.
herr_t collect_link(hid_t, const char* name, const H5L_info_t*, void* names) {
  static_cast<std::set<std::string>*>(names)->insert(name);
  return 0;
}
herr_t collect_attribute(hid_t, const char* name, const H5A_info_t*, void* names) {
  static_cast<std::set<std::string>*>(names)->insert(name);
  return 0;
}

std::string root_string(hid_t file, const char* name) {
  const OpenId attribute(H5Aopen(file, name, H5P_DEFAULT));
  if (attribute.get() < 0) return "<no attribute " + std::string(name) + ">";
  const OpenId type(H5Aget_type(attribute.get()));
  char* text = nullptr;
  if (H5Aread(attribute.get(), type.get(), &text) < 0 || text == nullptr) return "<unreadable>";
  std::string value = text;
  H5free_memory(text);
  return value;
}

// Not collective. Replaces the root attribute format (none: `format` null).
void set_format(const fs::path& path, const char* format) {
  const OpenId file(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
  ASSERT_GE(file.get(), 0);
  ASSERT_GE(H5Adelete(file.get(), "format"), 0);
  if (format == nullptr) return;
  const OpenId type(H5Tcopy(H5T_C_S1));
  H5Tset_size(type.get(), H5T_VARIABLE);
  const OpenId space(H5Screate(H5S_SCALAR));
  const OpenId attribute(
      H5Acreate2(file.get(), "format", type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT));
  ASSERT_GE(H5Awrite(attribute.get(), type.get(), &format), 0);
}

// The message of the catena::Error that `call` throws ("" if none).
template <class Call>
std::string error_of(Call call) {
  try {
    call();
  } catch (const catena::Error& error) {
    return error.what();
  }
  return "";
}

void expect_parts(const std::string& message, const std::vector<std::string>& parts) {
  EXPECT_FALSE(message.empty()) << "rank " << comm_rank() << " did not throw";
  for (const std::string& part : parts)
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

class TransientWriterTest : public ::testing::Test {
 protected:
  void SetUp() override { directory_ = catena::test::fresh_test_directory("catena_test_series"); }
  void TearDown() override { catena::test::remove_test_directory(directory_); }

  // Collective. Reopens `path` to continue it after its 3rd sample, as a restart does.
  std::string error_of_resuming(const fs::path& path) const {
    return error_of([&] {
      catena::io::TransientWriter(MPI_COMM_WORLD, path.string(), model_, my_rows(n_nodes),
                                  my_rows(n_elements), {}, catena::io::ResumePoint{3, 3});
    });
  }

  const catena::model::Model model_ = line_with_pantograph();
  fs::path directory_;
};

TEST_F(TransientWriterTest, WritesTheDocumentedObjectsAndRootAttributes) {
  const fs::path path = directory_ / "run.h5";
  write_run(path, model_);
  if (comm_rank() == 0) {
    const OpenId file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
    ASSERT_GE(file.get(), 0);
    std::set<std::string> objects;
    ASSERT_GE(H5Lvisit(file.get(), H5_INDEX_NAME, H5_ITER_INC, collect_link, &objects), 0);
    EXPECT_EQ(objects, (std::set<std::string>{"mesh",
                                              "mesh/node_ids",
                                              "mesh/node_positions",
                                              "mesh/element_ids",
                                              "mesh/element_nodes",
                                              "mesh/element_kind",
                                              "mesh/element_set",
                                              "mesh/registration_nodes",
                                              "time",
                                              "samples",
                                              "samples/positions",
                                              "samples/velocities",
                                              "samples/slopes",
                                              "samples/axial_force",
                                              "samples/contact_force",
                                              "samples/contact_position",
                                              "steps",
                                              "steps/time",
                                              "steps/dt",
                                              "steps/newton_iterations",
                                              "steps/error",
                                              "steps/rejected",
                                              "steps/contact_force",
                                              "steps/registration_height",
                                              "pantographs",
                                              "pantographs/leading"}));
    std::set<std::string> attributes;
    ASSERT_GE(H5Aiterate2(file.get(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_attribute,
                          &attributes),
              0);
    EXPECT_EQ(attributes, (std::set<std::string>{
                              "format", "scene_text", "scene_file", "code_version", "command_line",
                              "run_id", "petsc_options", "n_ranks", "n_dofs", "analysis", "status",
                              "evaluation_start", "evaluation_end", "steps_accepted"}));
    EXPECT_EQ(root_string(file.get(), "format"), "catena-transient-1");
    EXPECT_EQ(root_string(file.get(), "scene_text"), model_.source_text);
    EXPECT_EQ(root_string(file.get(), "status"), "complete");
    std::set<std::string> pantograph;
    const OpenId group(H5Gopen2(file.get(), "pantographs/leading", H5P_DEFAULT));
    H5Aiterate2(group.get(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_attribute, &pantograph);
    EXPECT_EQ(pantograph, (std::set<std::string>{"index", "speed", "start", "path"}));
  }
  MPI_Barrier(MPI_COMM_WORLD);
}

// The reader of `catena stats` reads what the writer wrote, on any number of writing ranks.
TEST_F(TransientWriterTest, TheRunReaderReadsTheWritersFile) {
  const fs::path path = directory_ / "run.h5";
  write_run(path, model_);
  if (comm_rank() == 0) {
    const catena::io::ContactRun run = catena::io::read_contact_run(path.string());
    EXPECT_EQ(run.n_samples, std::size_t(n_samples));
    EXPECT_NEAR(run.dt, interval, 1e-15);
    ASSERT_TRUE(run.evaluation_section.has_value());
    EXPECT_EQ(run.evaluation_section->x_start, 2.0);
    EXPECT_EQ(run.evaluation_section->x_end, 7.0);
    ASSERT_EQ(run.pantographs.size(), 1u);
    EXPECT_EQ(run.pantographs[0].name, "leading");
    EXPECT_EQ(run.pantographs[0].speed, speed);
    ASSERT_EQ(run.pantographs[0].force.size(), std::size_t(n_samples));
    for (int k = 0; k < n_samples; ++k) {
      EXPECT_EQ(run.pantographs[0].force[k], contact_force(k));
      EXPECT_EQ(run.pantographs[0].position[k], start + speed * (k * interval));
    }
    EXPECT_TRUE(run.has_registration_nodes);
    ASSERT_EQ(run.registration_points.size(), registration.size());
    for (std::size_t j = 0; j < registration.size(); ++j) {
      EXPECT_EQ(run.registration_points[j].reference_x, double(registration[j]));
      ASSERT_EQ(run.registration_points[j].z.size(), std::size_t(n_samples));
      for (int k = 0; k < n_samples; ++k)
        EXPECT_EQ(run.registration_points[j].z[k], height(registration[j], k));
    }
    // From the steps: the first sample, then every step after it (/steps/registration_height).
    const catena::io::ContactRun steps = catena::io::read_contact_run_steps(path.string());
    ASSERT_EQ(steps.registration_points.size(), registration.size());
    for (std::size_t j = 0; j < registration.size(); ++j) {
      ASSERT_EQ(steps.registration_points[j].z.size(), std::size_t(n_samples));
      EXPECT_EQ(steps.registration_points[j].z[0], height(registration[j], 0));
      for (int k = 1; k < n_samples; ++k)
        EXPECT_EQ(steps.registration_points[j].z[k], step_height(registration[j], k));
    }
  }
  MPI_Barrier(MPI_COMM_WORLD);
}

// A file of another format is neither read nor continued; one without a format is said to
// come from an older Catena.
TEST_F(TransientWriterTest, RefusesAFileOfAnotherFormatOrOfNone) {
  const fs::path path = directory_ / "run.h5";
  write_run(path, model_);
  if (comm_rank() == 0) set_format(path, "catena-transient-0");
  MPI_Barrier(MPI_COMM_WORLD);
  const std::vector<std::string> other{path.string(), "format 'catena-transient-0'",
                                       "expected 'catena-transient-1'"};
  expect_parts(error_of_resuming(path), other);
  if (comm_rank() == 0)
    expect_parts(error_of([&] { catena::io::read_contact_run(path.string()); }), other);

  if (comm_rank() == 0) set_format(path, nullptr);
  MPI_Barrier(MPI_COMM_WORLD);
  const std::vector<std::string> none{path.string(), "'format': missing",
                                      "expected 'catena-transient-1'", "older Catena"};
  expect_parts(error_of_resuming(path), none);
  if (comm_rank() == 0)
    expect_parts(error_of([&] { catena::io::read_contact_run(path.string()); }), none);
  MPI_Barrier(MPI_COMM_WORLD);
}

// Its own format is continued (the check does not refuse the writer's files).
TEST_F(TransientWriterTest, ContinuesAFileOfItsFormat) {
  const fs::path path = directory_ / "run.h5";
  write_run(path, model_);
  EXPECT_EQ(error_of_resuming(path), "");
}

// With supports, the reactions of every supported node (fixed DOFs or an elastic support)
// are rows of /samples/reaction_force and /samples/reaction_moment, in the order of
// /mesh/support_nodes, whichever rank owns them; a file written without them is not
// continued by a run that has supports.
TEST_F(TransientWriterTest, WritesTheSupportsReactionsAndRefusesToContinueAFileWithout) {
  catena::model::Model supported = model_;
  catena::test::pin(supported, 0);
  catena::test::pin(supported, n_nodes - 1);
  supported.elastic_supports.push_back({3, catena::Vec3(0, 0, 1e4), catena::Vec3::Zero()});
  const std::vector<int> support_nodes{0, 3, n_nodes - 1};
  const auto reaction = [](int node, int sample, double scale) {
    return catena::Vec3(scale * node, -scale * sample, scale * (node + sample + 1));
  };
  const fs::path path = directory_ / "supported.h5";
  {
    catena::io::RunInfo info;
    info.n_ranks = comm_size();
    catena::io::TransientWriter writer(MPI_COMM_WORLD, path.string(), supported, info,
                                       my_rows(n_nodes), my_rows(n_elements));
    for (int k = 0; k < n_samples; ++k) {
      std::vector<double> zeros, axial(my_rows(n_elements).size(), 0.0);
      catena::io::SupportSample reactions;
      for (const int node : my_rows(n_nodes)) {
        zeros.insert(zeros.end(), {0.0, 0.0, 0.0});
        if (std::find(support_nodes.begin(), support_nodes.end(), node) == support_nodes.end())
          continue;
        for (int d = 0; d < 3; ++d) {
          reactions.force.push_back(reaction(node, k, 1.0)[d]);
          reactions.moment.push_back(reaction(node, k, 0.5)[d]);
        }
      }
      const catena::io::ContactSample contacts{{contact_force(k)}, {start}};
      writer.append_sample(k * interval, zeros, zeros, zeros, axial, {}, contacts, reactions);
    }
    writer.close("complete", {});
  }
  if (comm_rank() == 0) {
    const OpenId file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
    ASSERT_GE(file.get(), 0);
    const auto read = [&](const char* name, hid_t type, void* out) {
      const OpenId dataset(H5Dopen2(file.get(), name, H5P_DEFAULT));
      ASSERT_GE(dataset.get(), 0) << name;
      ASSERT_GE(H5Dread(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out), 0) << name;
    };
    std::vector<std::int64_t> nodes(support_nodes.size());
    read("/mesh/support_nodes", H5T_NATIVE_INT64, nodes.data());
    EXPECT_EQ(nodes, std::vector<std::int64_t>(support_nodes.begin(), support_nodes.end()));
    std::vector<double> force(n_samples * support_nodes.size() * 3), moment(force.size());
    read("/samples/reaction_force", H5T_NATIVE_DOUBLE, force.data());
    read("/samples/reaction_moment", H5T_NATIVE_DOUBLE, moment.data());
    for (int k = 0; k < n_samples; ++k)
      for (std::size_t j = 0; j < support_nodes.size(); ++j)
        for (int d = 0; d < 3; ++d) {
          const std::size_t at = (k * support_nodes.size() + j) * 3 + d;
          EXPECT_EQ(force[at], reaction(support_nodes[j], k, 1.0)[d]);
          EXPECT_EQ(moment[at], reaction(support_nodes[j], k, 0.5)[d]);
        }
  }
  MPI_Barrier(MPI_COMM_WORLD);
  // The file without supports (write_run), continued by a run with them.
  const fs::path without = directory_ / "run.h5";
  write_run(without, model_);
  expect_parts(error_of([&] {
                 catena::io::TransientWriter(MPI_COMM_WORLD, without.string(), supported,
                                             my_rows(n_nodes), my_rows(n_elements), {},
                                             catena::io::ResumePoint{3, 3});
               }),
               {without.string(), "without the supports' reactions", "run afresh"});
}

}  // namespace
