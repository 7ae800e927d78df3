#include "memory_check.hpp"

#include <map>
#include <optional>

#include "catena/model/node_kinds.hpp"

namespace catena::model::detail {
namespace {

std::string advice(const MemoryBudget& budget) {
  return std::string("; expected a scene whose run fits") +
         (budget.ranks_on_host > 1 ? " (or fewer ranks per host: each holds the whole model)"
                                   : "") +
         ": fewer elements, or more hosts; --memory-limit GIB overrides the limit "
         "(docs/scene.md, \"Memory\")";
}

// Refuses at `where` the `made` ("the lines make") elements of `size` if even they alone
// (a lower bound of the run) exceed the budget.
void refuse_lower_bound_over(const Field& where, const std::string& made, const ProblemSize& size,
                             const MemoryBudget& budget) {
  const MemoryEstimate estimate = estimate_memory(size);
  if (estimate.per_host_bytes(budget.ranks, budget.ranks_on_host) <= budget.host_bytes) return;
  where.fail(made + " " + std::to_string(size.elements) +
             " elements, and a run of them alone needs an estimated " +
             estimate.describe(budget.ranks, budget.ranks_on_host) + ", more than " +
             budget.describe() + advice(budget));
}

}  // namespace

void check_lines_fit(const Field& lines, const SectionTable& sections, const SceneBuild& build,
                     const MemoryBudget& budget) {
  if (!budget.active() || !lines.is_list()) return;
  ProblemSize size;
  size.nodes = build.model.nodes.size();
  size.factor_multiple = 1.0;
  // Fields are never assigned: a YAML::Node's operator= writes into the document.
  std::optional<Field> largest;
  std::int64_t largest_count = 0;
  for (const Field& line : lines.items()) {
    if (!line.is_map()) continue;
    const Field count = line.child("elements");
    const Field section = line.child("section");
    if (!count.is_scalar() || !section.is_scalar()) continue;
    const std::optional<std::int64_t> n = parse_integer(count.node().Scalar());
    const auto found = sections.find(section.node().Scalar());
    if (!n || *n < 1 || *n > 10'000'000 || found == sections.end()) continue;
    const std::int64_t d = element_node_dofs(found->second.props);
    size.nodes += *n - 1;
    size.elements += *n;
    size.dofs += *n * d;
    size.matrix_nonzeros += *n * 3 * d * d;  // a diagonal and two off-diagonal blocks
    if (*n > largest_count) {
      largest_count = *n;
      largest.emplace(count);
    }
  }
  if (largest_count == 0) return;
  refuse_lower_bound_over(*largest, "the lines make", size, budget);
}

void check_catenary_fits(const Field& element_length, const CatenaryDesign& d,
                         const SceneBuild& build, const MemoryBudget& budget) {
  if (!budget.active() || !(d.element_length > 0.0)) return;
  const std::int64_t cable_dofs = kind_info(UnknownKind::ancf_cable).size;
  std::int64_t wire_elements = 0;  // contact wire and messenger, each span at least one
  for (const double span : d.span_lengths)
    wire_elements +=
        2 * std::max<std::int64_t>(1, static_cast<std::int64_t>(span / d.element_length));
  if (d.stitch && d.span_lengths.size() > 1)
    wire_elements +=
        static_cast<std::int64_t>(d.span_lengths.size() - 1) *
        std::max<std::int64_t>(1, static_cast<std::int64_t>(d.stitch->length / d.element_length));
  std::int64_t droppers = 0;
  for (const std::vector<double>& span : d.droppers.positions)
    droppers += static_cast<std::int64_t>(span.size());
  const bool cables = d.droppers.model == DropperModel::cable;
  const std::int64_t chain = cables ? d.droppers.cable_elements : 0;  // elements per dropper
  ProblemSize size;
  size.factor_multiple = 1.0;
  size.nodes = static_cast<std::int64_t>(build.model.nodes.size()) + wire_elements +
               droppers * (cables ? chain + 1 : 0);
  size.elements = wire_elements + droppers * (cables ? chain + 2 : 1);
  size.dofs = (wire_elements + droppers * (cables ? chain + 1 : 0)) * cable_dofs;
  size.matrix_nonzeros = (wire_elements + droppers * chain) * 3 * cable_dofs * cable_dofs;
  refuse_lower_bound_over(element_length, "the catenary makes at least", size, budget);
}

void check_model_fits(const Field& scene, const SceneBuild& build, const MemoryBudget& budget) {
  if (!budget.active()) return;
  const MemoryEstimate estimate = estimate_memory(problem_size(build.model));
  if (estimate.per_host_bytes(budget.ranks, budget.ranks_on_host) <= budget.host_bytes) return;
  // The entry that made the most elements: a line's count, the catenary's element length.
  std::map<std::string, std::pair<int, Field>> per_entry;
  for (std::size_t e = 0; e < build.model.elements.size(); ++e) {
    const Field& origin = build.element_origin(static_cast<int>(e));
    auto [it, inserted] = per_entry.try_emplace(origin.path(), 0, origin);
    ++it->second.first;
  }
  const Field* origin = nullptr;
  int most = 0;
  for (const auto& [path, entry] : per_entry)
    if (entry.first > most) {
      most = entry.first;
      origin = &entry.second;
    }
  // Fields are never assigned: a YAML::Node's operator= writes into the document.
  std::optional<Field> where;
  if (!origin)
    where.emplace(scene);
  else if (origin->is_map() && origin->child("elements").present())
    where.emplace(origin->child("elements"));
  else if (origin->is_map() && origin->child("element_length").present())
    where.emplace(origin->child("element_length"));
  else
    where.emplace(*origin);
  where->fail("the scene makes " + std::to_string(build.model.elements.size()) + " elements (" +
              std::to_string(most) + " from here), and its run needs an estimated " +
              estimate.describe(budget.ranks, budget.ranks_on_host) + ", more than " +
              budget.describe() + advice(budget));
}

}  // namespace catena::model::detail
