#include "catena/io/transient_writer.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <exception>
#include <type_traits>

#include "catena/core/error.hpp"
#include "catena/io/output_error.hpp"
#include "catena/model/supported_nodes.hpp"
#include "catenary_output.hpp"
#include "collective_hdf5_call.hpp"
#include "collective_phase.hpp"
#include "element_classes.hpp"
#include "extendible_series.hpp"
#include "hdf5_attributes.hpp"
#include "hdf5_error.hpp"
#include "hdf5_handles.hpp"
#include "hdf5_parallel_write.hpp"
#include "row_redistribution.hpp"
#include "space_probe.hpp"
#include "transient_layout.hpp"

namespace catena::io {
namespace {
namespace layout = transient_layout;
}  // namespace

struct TransientWriter::Impl {
  // First, so that it outlives the file: HDF5 prints no error stack while the file is
  // open or closing (failures are reported once, as exceptions).
  Hdf5ErrorPrintingSuppressed quiet_hdf5;
  MPI_Comm comm;
  std::string path;
  int rank = 0;
  ParallelHdf5File file;
  RowRedistribution nodes, elements, constraints;
  bool has_constraints = false;
  int multiplier_width = 3;    // values per constraint row (model::multiplier_width)
  std::vector<int> supported;  // the supported nodes, ascending (layout::support_nodes)
  RowRedistribution supports;
  bool has_supports = false;
  hsize_t n_contacts = 0;
  hsize_t n_registration = 0;
  bool has_window = false;  // catenary.window: the moves per sample and step
  hsize_t n_bodies = 0;
  hsize_t n_sliders = 0;
  hsize_t n_joints = 0;
  Series time, positions, velocities, slopes, axial, constraint_forces;
  Series body_orientation, body_angular_velocity, joint_links;
  Series slider_position, slider_speed;
  Series reaction_force, reaction_moment;
  Series contact_force, contact_position, step_contact_force, step_registration_height;
  Series step_time, step_dt, step_iterations, step_error, step_rejected;
  Series window_moves, step_window_moves;
  std::vector<StepRecord> pending_steps;
  // Samples buffered until kSamplesPerWrite of them, or flush(): one H5Dwrite per dataset
  // for many rows instead of one per row, each call paying HDF5's selection and MPI-IO
  // set-up (the Output stage of a linear EN 50318 run about 10 % shorter in two noisy
  // pairs; the larger gain was the memory space's shape, in Series::append). Per series,
  // this rank's rows in file order.
  static constexpr std::size_t kSamplesPerWrite = 32;
  struct PendingSamples {
    std::size_t n = 0;
    std::vector<double> time, positions, velocities, slopes, axial, constraint_forces;
    std::vector<double> reaction_force, reaction_moment, contact_force, contact_position;
    std::vector<double> body_orientation, body_angular_velocity, joint_links;
    std::vector<double> slider_position, slider_speed;
    std::vector<std::int32_t> window_moves;
  } pending;
  void write_pending_samples();
  // Collective. Rows whose values every rank holds alike (time, contact, bodies, sliders,
  // the step series) are written by every rank, whole, with rank 0's values (broadcast
  // here): every rank then selects the same chunks in the collective write. When rank 0
  // alone selected them, HDF5 1.10 looked the chunks up on rank 0 only, and a metadata
  // cache sync point falling due there ran on rank 0 alone while the other ranks went on
  // to the write: a 2-rank EN 50318 run hung so, 3 s into the dynamics.
  template <class Value>
  void from_root(std::vector<Value>& values) const {
    std::uint64_t n = values.size();
    MPI_Bcast(&n, 1, MPI_UINT64_T, 0, comm);
    values.resize(n);
    // In pieces of at most 1 GiB: an int counts the bytes of one broadcast.
    auto* bytes = reinterpret_cast<char*>(values.data());
    for (std::uint64_t done = 0, total = n * sizeof(Value); done < total;) {
      const std::uint64_t piece = std::min<std::uint64_t>(total - done, 1ULL << 30);
      MPI_Bcast(bytes + done, static_cast<int>(piece), MPI_BYTE, 0, comm);
      done += piece;
    }
  }
  bool failed = false;  // a write failed (on every rank alike): the file is only closed
  bool closed = false;

  Impl(MPI_Comm c, const std::string& p, const model::Model& m, const std::vector<int>& own_nodes,
       const std::vector<int>& own_elements, const std::vector<int>& own_constraints,
       bool existing = false)
      : comm(c),
        path(p),
        file(existing ? ParallelHdf5File(c, p, ParallelHdf5File::OpenExisting{})
                      : ParallelHdf5File(c, p)),
        nodes(c, static_cast<std::int64_t>(m.nodes.size()), own_nodes, "owned_nodes"),
        elements(c, static_cast<std::int64_t>(m.elements.size()), own_elements, "owned_elements"),
        constraints(c, static_cast<std::int64_t>(m.constraints.size()), own_constraints,
                    "owned_constraints"),
        has_constraints(!m.constraints.empty()),
        multiplier_width(model::multiplier_width(m)),
        supported(model::supported_nodes(m)),
        supports(c, static_cast<std::int64_t>(supported.size()), support_rows(supported, own_nodes),
                 "owned support nodes"),
        has_supports(!supported.empty()),
        n_contacts(static_cast<hsize_t>(m.contacts.size())),
        n_registration(static_cast<hsize_t>(m.registration_nodes.size())),
        has_window(m.catenary && m.catenary->window),
        n_bodies(static_cast<hsize_t>(m.rigid_bodies.size())),
        n_sliders(static_cast<hsize_t>(m.sliders.size())),
        n_joints(static_cast<hsize_t>(m.joints.size())) {
    MPI_Comm_rank(c, &rank);
  }

  // This rank's rows of `supported`: its owned nodes among them.
  static std::vector<int> support_rows(const std::vector<int>& supported,
                                       const std::vector<int>& own_nodes) {
    std::vector<int> rows;
    for (const int node : own_nodes)
      if (const auto it = std::lower_bound(supported.begin(), supported.end(), node);
          it != supported.end() && *it == node)
        rows.push_back(static_cast<int>(it - supported.begin()));
    std::sort(rows.begin(), rows.end());
    return rows;
  }

  // Collective. Runs a step that writes; an agreed failure (catena::OutputError, thrown on
  // every rank) leaves the file failed: it is not written again, only closed.
  template <class Step>
  void write(Step&& step) {
    if (failed) throw OutputError(path + ": not written again after a failed write");
    try {
      std::forward<Step>(step)();
    } catch (const OutputError&) {
      failed = true;
      throw;
    }
  }

  // A failed file is abandoned, not closed (hdf5_parallel_write.hpp): its datasets first.
  ~Impl() {
    if (file.failed()) abandon_file();
  }

  // Collective. Every series `model` has: created empty, or (`resume`) reopened and cut
  // to the rows the checkpoint had.
  void open_series(const model::Model& model, const ResumePoint* resume) {
    const auto series = [&](const layout::Dataset& dataset, std::vector<hsize_t> shape, hid_t type,
                            std::int64_t resumed_rows) {
      if (!resume) return Series(file, dataset, std::move(shape), type);
      return Series(file, dataset, std::move(shape), type, static_cast<hsize_t>(resumed_rows));
    };
    const std::int64_t samples = resume ? resume->samples : 0;
    const std::int64_t steps = resume ? resume->steps : 0;
    const auto n_nodes = static_cast<hsize_t>(model.nodes.size());
    const auto n_elements = static_cast<hsize_t>(model.elements.size());
    const hid_t real = H5T_IEEE_F64LE, count = H5T_STD_I32LE;
    if (has_constraints)
      constraint_forces = series(layout::constraint_forces,
                                 {static_cast<hsize_t>(model.constraints.size()),
                                  static_cast<hsize_t>(model::multiplier_width(model))},
                                 real, samples);
    // A file to continue that lacks a series newer Catenas write: refused, naming it.
    const auto require_on_resume = [&](const layout::Dataset& dataset, const char* what) {
      if (!resume) return;
      const std::string why = std::string("missing: written by an older Catena, without ") + what +
                              "; run afresh (without --restart)";
      run_collective_phase(comm, [&] {
        if (H5Lexists(file.id(), dataset.path, H5P_DEFAULT) <= 0)
          throw InputError({path, 0, dataset.path}, why);
      });
    };
    if (has_supports) {
      require_on_resume(layout::reaction_force, "the supports' reactions over time");
      const auto n_supported = static_cast<hsize_t>(supported.size());
      reaction_force = series(layout::reaction_force, {n_supported, 3}, real, samples);
      reaction_moment = series(layout::reaction_moment, {n_supported, 3}, real, samples);
    }
    if (n_contacts > 0) {
      contact_force = series(layout::contact_force, {n_contacts}, real, samples);
      contact_position = series(layout::contact_position, {n_contacts}, real, samples);
      step_contact_force = series(layout::step_contact_force, {n_contacts}, real, steps);
    }
    if (n_registration > 0) {
      require_on_resume(layout::step_registration_height,
                        "the registration points' heights per step");
      step_registration_height =
          series(layout::step_registration_height, {n_registration}, real, steps);
    }
    if (n_bodies > 0) {
      require_on_resume(layout::body_orientation, "the rigid bodies' poses");
      body_orientation = series(layout::body_orientation, {n_bodies, 4}, real, samples);
      body_angular_velocity = series(layout::body_angular_velocity, {n_bodies, 3}, real, samples);
    }
    if (n_joints > 0) {
      require_on_resume(layout::joint_links, "the joints' links");
      joint_links = series(layout::joint_links, {n_joints, 4, 3}, real, samples);
    }
    if (n_sliders > 0) {
      require_on_resume(layout::slider_position, "the sliders' travel");
      slider_position = series(layout::slider_position, {n_sliders}, real, samples);
      slider_speed = series(layout::slider_speed, {n_sliders}, real, samples);
    }
    if (has_window) {
      window_moves = series(layout::window_moves, {}, count, samples);
      step_window_moves = series(layout::step_window_moves, {}, count, steps);
    }
    time = series(layout::time, {}, real, samples);
    positions = series(layout::positions, {n_nodes, 3}, real, samples);
    velocities = series(layout::velocities, {n_nodes, 3}, real, samples);
    slopes = series(layout::slopes, {n_nodes, 3}, real, samples);
    axial = series(layout::axial_force, {n_elements}, real, samples);
    step_time = series(layout::step_time, {}, real, steps);
    step_dt = series(layout::step_dt, {}, real, steps);
    step_iterations = series(layout::step_newton_iterations, {}, count, steps);
    step_error = series(layout::step_error, {}, real, steps);
    step_rejected = series(layout::step_rejected, {}, count, steps);
  }

  std::vector<Series*> all_series() {
    return {&time,
            &positions,
            &velocities,
            &slopes,
            &axial,
            &constraint_forces,
            &reaction_force,
            &reaction_moment,
            &contact_force,
            &contact_position,
            &step_contact_force,
            &step_registration_height,
            &step_time,
            &step_dt,
            &step_iterations,
            &step_error,
            &step_rejected,
            &body_orientation,
            &body_angular_velocity,
            &joint_links,
            &slider_position,
            &slider_speed,
            &window_moves,
            &step_window_moves};
  }

  // Collective. Closes every dataset, then the file.
  void close_file() {
    for (Series* series : all_series()) series->reset();
    file.close();
  }

  // Not collective (every rank does it alike). Forgets the datasets and the file.
  void abandon_file() {
    for (Series* series : all_series()) series->abandon();
    file.abandon();
  }
};

TransientWriter::TransientWriter(MPI_Comm comm, const std::string& path, const model::Model& model,
                                 const RunInfo& info, std::vector<int> owned_nodes,
                                 std::vector<int> owned_elements,
                                 std::vector<int> owned_constraints)
    : impl_(std::make_unique<Impl>(comm, path, model, owned_nodes, owned_elements,
                                   owned_constraints)) {
  Impl& s = *impl_;
  const hid_t f = s.file.id();
  const auto n_nodes = static_cast<std::int64_t>(model.nodes.size());
  const auto n_elements = static_cast<std::int64_t>(model.elements.size());
  const std::string& p = s.path;
  // Mesh: every rank holds the model and writes its balanced block.
  const RowBlock& nb = s.nodes.block();
  const RowBlock& eb = s.elements.block();
  std::vector<std::int64_t> ids;
  std::vector<double> reference;
  for (std::int64_t k = 0; k < nb.count; ++k) {
    const model::Node& node = model.nodes[static_cast<size_t>(nb.begin + k)];
    ids.push_back(node.id);
    reference.insert(reference.end(), {node.position.x(), node.position.y(), node.position.z()});
  }
  // A mesh dataset of `rows` × `columns`, this rank's `block` of them.
  const auto write_mesh = [&](const layout::Dataset& dataset, std::int64_t rows, int columns,
                              const RowBlock& block, const auto& values) {
    using Value = typename std::decay_t<decltype(values)>::value_type;
    write_block_dataset<Value>(s.file, {dataset.path, rows, columns, dataset.unit}, block, values);
  };
  create_group(s.file, layout::mesh_group);
  write_mesh(layout::node_ids, n_nodes, 1, nb, ids);
  write_mesh(layout::node_positions, n_nodes, 3, nb, reference);
  std::vector<std::int64_t> element_ids, element_nodes;
  for (std::int64_t k = 0; k < eb.count; ++k) {
    const model::ElementDesc& e = model.elements[static_cast<size_t>(eb.begin + k)];
    element_ids.push_back(e.id);
    element_nodes.push_back(e.nodes.front());
    element_nodes.push_back(e.nodes.back());
  }
  write_mesh(layout::element_ids, n_elements, 1, eb, element_ids);
  write_mesh(layout::element_nodes, n_elements, layout::nodes_per_element, eb, element_nodes);
  write_element_classes(s.file, model, eb);

  if (s.has_constraints) {
    const RowBlock& cb = s.constraints.block();
    std::vector<std::int64_t> ends;
    for (std::int64_t k = 0; k < cb.count; ++k) {
      const model::Constraint& c = model.constraints[static_cast<size_t>(cb.begin + k)];
      ends.push_back(c.node_a);
      ends.push_back(c.node_b);
    }
    write_mesh(layout::constraint_nodes, static_cast<std::int64_t>(model.constraints.size()), 2, cb,
               ends);
  }
  if (s.has_supports) {
    const RowBlock& sb = s.supports.block();
    const auto first = s.supported.begin() + sb.begin;
    write_mesh(layout::support_nodes, static_cast<std::int64_t>(s.supported.size()), 1, sb,
               std::vector<std::int64_t>(first, first + sb.count));
  }

  if (s.n_contacts > 0) {
    create_group(s.file, layout::pantographs_group);
    for (size_t i = 0; i < model.contacts.size(); ++i) {
      const std::string name =
          std::string(layout::pantographs_group) + "/" + model.contacts[i].name;
      const GroupHandle group = create_group(s.file, name.c_str());
      run_output_phase(s.comm, [&] {
        namespace attribute = layout::pantograph_attribute;
        const AttributeTarget target{group.get(), p};
        write_int64_attribute(target, attribute::index, static_cast<std::int64_t>(i));
        write_double_attribute(target, attribute::speed, model.contacts[i].speed);
        // Along the line (a catenary window's path starts where the window does).
        const double origin =
            model.catenary && model.catenary->window ? model.catenary->window->origin_arc() : 0.0;
        write_double_attribute(target, attribute::start, model.contacts[i].start + origin);
        write_string_attribute(target, attribute::path,
                               model.paths[static_cast<size_t>(model.contacts[i].path)].name);
      });
    }
  }
  if (s.n_bodies > 0) {
    const auto n_bodies = static_cast<std::int64_t>(s.n_bodies);
    std::vector<std::int64_t> nodes;
    if (s.rank == 0)
      for (const model::RigidBody& b : model.rigid_bodies) nodes.push_back(b.node);
    write_mesh(layout::body_nodes, n_bodies, 1, RowBlock{0, s.rank == 0 ? n_bodies : 0}, nodes);
    create_group(s.file, layout::bodies_group);
    for (size_t i = 0; i < model.rigid_bodies.size(); ++i) {
      const std::string name = std::string(layout::bodies_group) + "/" + model.rigid_bodies[i].name;
      const GroupHandle group = create_group(s.file, name.c_str());
      run_output_phase(s.comm, [&] {
        write_int64_attribute({group.get(), p}, layout::body_index_attribute,
                              static_cast<std::int64_t>(i));
      });
    }
  }
  if (s.n_sliders > 0) {
    const auto n_sliders = static_cast<std::int64_t>(s.n_sliders);
    std::vector<std::int64_t> nodes;
    if (s.rank == 0)
      for (const model::Slider& slider : model.sliders) nodes.push_back(slider.node);
    write_mesh(layout::slider_nodes, n_sliders, 1, RowBlock{0, s.rank == 0 ? n_sliders : 0}, nodes);
    create_group(s.file, layout::sliders_group);
    for (size_t i = 0; i < model.sliders.size(); ++i) {
      const std::string name = std::string(layout::sliders_group) + "/" + model.sliders[i].name;
      const GroupHandle group = create_group(s.file, name.c_str());
      run_output_phase(s.comm, [&] {
        write_int64_attribute({group.get(), p}, layout::body_index_attribute,
                              static_cast<std::int64_t>(i));
        write_int64_attribute({group.get(), p}, layout::slider_constraint_attribute,
                              static_cast<std::int64_t>(model.sliders[i].constraint));
      });
    }
  }
  {
    const auto n_reg = static_cast<std::int64_t>(model.registration_nodes.size());
    std::vector<std::int64_t> reg;
    const RowBlock rb{0, s.rank == 0 ? n_reg : 0};
    if (s.rank == 0) reg.assign(model.registration_nodes.begin(), model.registration_nodes.end());
    write_mesh(layout::registration_nodes, n_reg, 1, rb, reg);
  }
  write_catenary_layout(s.file, model);
  s.open_series(model, nullptr);

  run_output_phase(s.comm, [&] {
    namespace attribute = layout::root_attribute;
    const AttributeTarget root{f, p};
    write_string_attribute(root, attribute::format, layout::format);
    write_string_attribute(root, attribute::scene_text, model.source_text);
    write_string_attribute(root, attribute::scene_file, model.source_file);
    write_string_attribute(root, attribute::code_version, info.code_version);
    write_string_attribute(root, attribute::command_line, info.command_line);
    write_string_attribute(root, attribute::run_id, info.run_id);
    write_string_attribute(root, attribute::petsc_options, info.petsc_options);
    write_int64_attribute(root, attribute::n_ranks, info.n_ranks);
    write_int64_attribute(root, attribute::n_dofs, info.n_dofs);
    write_string_attribute(root, attribute::analysis, layout::analysis_dynamic);
    write_string_attribute(root, attribute::status, layout::status_running);
    write_double_attribute(root, attribute::evaluation_start, model.evaluation_start);
    write_double_attribute(root, attribute::evaluation_end, model.evaluation_end);
    if (!model.acceptance.empty())
      write_string_attribute(root, attribute::acceptance, model.acceptance);
    if (model.catenary && model.catenary->window)
      write_double_attribute(root, attribute::window_shift_x, model.catenary->window->shift_x());
  });
  flush();
}

TransientWriter::TransientWriter(MPI_Comm comm, const std::string& path, const model::Model& model,
                                 std::vector<int> owned_nodes, std::vector<int> owned_elements,
                                 std::vector<int> owned_constraints, const ResumePoint& resume)
    : impl_(std::make_unique<Impl>(comm, path, model, owned_nodes, owned_elements,
                                   owned_constraints, true)) {
  Impl& s = *impl_;
  const hid_t f = s.file.id();
  run_collective_phase(s.comm, [&] { layout::require_transient_format(f, s.path); });
  s.open_series(model, &resume);
  run_output_phase(s.comm, [&] {
    const char* status = layout::root_attribute::status;
    check_hdf5_status(H5Adelete(f, status), "H5Adelete", s.path, status);
    write_string_attribute({f, s.path}, status, layout::status_running);
  });
  flush();
}

TransientWriter::~TransientWriter() = default;

std::int64_t TransientWriter::samples_written() const {
  return static_cast<std::int64_t>(impl_->time.rows() + impl_->pending.n);
}
std::int64_t TransientWriter::steps_written() const {
  return static_cast<std::int64_t>(impl_->step_time.rows() + impl_->pending_steps.size());
}  // handles close locally (see header)

void TransientWriter::append_sample(double t, const std::vector<double>& positions,
                                    const std::vector<double>& velocities,
                                    const std::vector<double>& slopes,
                                    const std::vector<double>& axial_force,
                                    const std::vector<double>& constraint_forces,
                                    const ContactSample& contacts, const SupportSample& supports,
                                    const BodySample& bodies, const SliderSample& sliders) {
  Impl& s = *impl_;
  Impl::PendingSamples& b = s.pending;
  const auto add = [](std::vector<double>& to, const std::vector<double>& rows) {
    to.insert(to.end(), rows.begin(), rows.end());
  };
  s.write([&] {  // the redistributions are collective, and agreed like a write
    if (s.rank == 0) b.time.push_back(t);
    add(b.positions, s.nodes.to_block(positions, 3));
    add(b.velocities, s.nodes.to_block(velocities, 3));
    add(b.slopes, s.nodes.to_block(slopes, 3));
    add(b.axial, s.elements.to_block(axial_force, 1));
    if (s.has_constraints)
      add(b.constraint_forces, s.constraints.to_block(constraint_forces, s.multiplier_width));
    if (s.has_supports) {
      add(b.reaction_force, s.supports.to_block(supports.force, 3));
      add(b.reaction_moment, s.supports.to_block(supports.moment, 3));
    }
    if (s.n_contacts > 0 && s.rank == 0) {
      // Replicated values: rank 0 writes the row.
      CATENA_ASSERT(contacts.force.size() == s.n_contacts, "one force per contact");
      add(b.contact_force, contacts.force);
      add(b.contact_position, contacts.position);
    }
    if (s.has_window && s.rank == 0)
      b.window_moves.push_back(static_cast<std::int32_t>(contacts.window_moves));
    if (s.n_bodies > 0 && s.rank == 0) {
      CATENA_ASSERT(bodies.orientation.size() == 4 * s.n_bodies, "one quaternion per body");
      add(b.body_orientation, bodies.orientation);
      add(b.body_angular_velocity, bodies.angular_velocity);
    }
    if (s.n_joints > 0 && s.rank == 0) {
      CATENA_ASSERT(bodies.joint_links.size() == 12 * s.n_joints, "four points per joint");
      add(b.joint_links, bodies.joint_links);
    }
    if (s.n_sliders > 0 && s.rank == 0) {
      CATENA_ASSERT(sliders.position.size() == s.n_sliders, "one arc length per slider");
      add(b.slider_position, sliders.position);
      add(b.slider_speed, sliders.speed);
    }
  });
  ++b.n;
  if (b.n >= Impl::kSamplesPerWrite) s.write_pending_samples();
}

void TransientWriter::Impl::write_pending_samples() {
  if (pending.n == 0) return;
  write([&] {
    const hid_t x = file.collective_transfer();
    const auto n = static_cast<hsize_t>(pending.n);
    from_root(pending.time);
    time.append(x, n, RowBlock{0, 1}, pending.time.data());
    positions.append(x, n, nodes.block(), pending.positions.data());
    velocities.append(x, n, nodes.block(), pending.velocities.data());
    slopes.append(x, n, nodes.block(), pending.slopes.data());
    axial.append(x, n, elements.block(), pending.axial.data());
    if (has_constraints)
      constraint_forces.append(x, n, constraints.block(), pending.constraint_forces.data());
    if (has_supports) {
      reaction_force.append(x, n, supports.block(), pending.reaction_force.data());
      reaction_moment.append(x, n, supports.block(), pending.reaction_moment.data());
    }
    if (n_contacts > 0) {
      const RowBlock all{0, static_cast<std::int64_t>(n_contacts)};
      from_root(pending.contact_force);
      from_root(pending.contact_position);
      contact_force.append(x, n, all, pending.contact_force.data());
      contact_position.append(x, n, all, pending.contact_position.data());
    }
    if (n_bodies > 0) {
      const RowBlock all{0, static_cast<std::int64_t>(n_bodies)};
      from_root(pending.body_orientation);
      from_root(pending.body_angular_velocity);
      body_orientation.append(x, n, all, pending.body_orientation.data());
      body_angular_velocity.append(x, n, all, pending.body_angular_velocity.data());
    }
    if (n_joints > 0) {
      from_root(pending.joint_links);
      joint_links.append(x, n, RowBlock{0, static_cast<std::int64_t>(n_joints)},
                         pending.joint_links.data());
    }
    if (has_window) {
      from_root(pending.window_moves);
      window_moves.append(x, n, RowBlock{0, 1}, pending.window_moves.data());
    }
    if (n_sliders > 0) {
      const RowBlock all{0, static_cast<std::int64_t>(n_sliders)};
      from_root(pending.slider_position);
      from_root(pending.slider_speed);
      slider_position.append(x, n, all, pending.slider_position.data());
      slider_speed.append(x, n, all, pending.slider_speed.data());
    }
  });
  pending = PendingSamples{};
}

void TransientWriter::append_step(const StepRecord& record) {
  impl_->pending_steps.push_back(record);
}

void TransientWriter::flush() {
  Impl& s = *impl_;
  s.write_pending_samples();
  s.write([&] {
    const hid_t x = s.file.collective_transfer();
    const auto n = static_cast<hsize_t>(s.pending_steps.size());
    if (n > 0) {
      std::vector<double> t, dt, error;
      std::vector<std::int32_t> iterations, rejected;
      for (const StepRecord& r : s.pending_steps) {
        t.push_back(r.time);
        dt.push_back(r.dt);
        error.push_back(r.error);
        iterations.push_back(r.newton_iterations);
        rejected.push_back(r.rejected);
      }
      const RowBlock rows{0, static_cast<std::int64_t>(n)};
      s.from_root(t);
      s.from_root(dt);
      s.from_root(error);
      s.from_root(iterations);
      s.from_root(rejected);
      s.step_time.append(x, n, rows, t.data());
      s.step_dt.append(x, n, rows, dt.data());
      s.step_iterations.append(x, n, rows, iterations.data());
      s.step_error.append(x, n, rows, error.data());
      s.step_rejected.append(x, n, rows, rejected.data());
      if (s.has_window) {
        std::vector<std::int32_t> moves;
        for (const StepRecord& r : s.pending_steps)
          moves.push_back(static_cast<std::int32_t>(r.window_moves));
        s.from_root(moves);
        s.step_window_moves.append(x, n, rows, moves.data());
      }
      if (s.n_contacts > 0) {
        std::vector<double> forces;
        for (const StepRecord& r : s.pending_steps)
          for (hsize_t i = 0; i < s.n_contacts; ++i)
            forces.push_back(i < r.contact_force.size() ? r.contact_force[i] : 0.0);
        const RowBlock all{0, static_cast<std::int64_t>(s.n_contacts)};
        s.from_root(forces);
        s.step_contact_force.append(x, n, all, forces.data());
      }
      if (s.n_registration > 0) {
        std::vector<double> heights;
        for (const StepRecord& r : s.pending_steps) {
          if (r.registration_height.size() != s.n_registration)
            throw Error("TransientWriter: a step record with " +
                        std::to_string(r.registration_height.size()) +
                        " registration heights, the model has " + std::to_string(s.n_registration));
          heights.insert(heights.end(), r.registration_height.begin(), r.registration_height.end());
        }
        const RowBlock all{0, static_cast<std::int64_t>(s.n_registration)};
        s.from_root(heights);
        s.step_registration_height.append(x, n, all, heights.data());
      }
      s.pending_steps.clear();
    }
    s.file.flush();
  });
}

void TransientWriter::close(const std::string& status,
                            const std::vector<std::pair<std::string, double>>& statistics) {
  Impl& s = *impl_;
  if (s.closed) return;
  s.closed = true;  // whatever happens below, the file is not touched again
  // Every step is tried, each agreed on its own, so that the file is closed even when
  // writing failed; the first failure is reported.
  std::exception_ptr first_failure;
  std::string recorded_status = status;
  const auto attempt = [&](auto&& step) {
    try {
      step();
    } catch (const OutputError& e) {
      if (!first_failure) first_failure = std::current_exception();
      if (recorded_status.rfind("failed", 0) != 0)
        recorded_status = std::string("failed: ") + e.what();
    }
  };
  if (!s.failed) attempt([&] { flush(); });
  if (s.file.failed()) {
    // Closing writes the last metadata: only if something can still be written there.
    if (const std::string why = failed_test_write_beside(s.comm, s.path); !why.empty()) {
      s.abandon_file();
      if (first_failure) std::rethrow_exception(first_failure);
      throw OutputError("'" + s.path + "' is left unclosed, as at its last flush: nothing can " +
                        "be written beside it (" + why + ")");
    }
  }
  attempt([&] {
    run_output_phase(s.comm, [&] {
      const AttributeTarget root{s.file.id(), s.path};
      const char* status_name = layout::root_attribute::status;
      check_hdf5_status(H5Adelete(s.file.id(), status_name), "H5Adelete", s.path, status_name);
      write_string_attribute(root, status_name, recorded_status);
      for (const auto& [name, value] : statistics) {
        // A restarted run replaces its predecessor's statistics (they describe the last run).
        if (H5Aexists(s.file.id(), name.c_str()) > 0)
          check_hdf5_status(H5Adelete(s.file.id(), name.c_str()), "H5Adelete", s.path, name);
        write_double_attribute(root, name.c_str(), value);
      }
    });
  });
  attempt([&] { s.close_file(); });
  if (first_failure) std::rethrow_exception(first_failure);
}

}  // namespace catena::io
