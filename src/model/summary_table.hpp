#pragma once
// The pieces of the `catena check` summary (model_summary.hpp): the aligned label/value
// table, and the parts that describe a catenary and the moving loads and pantographs
// (what is modelled, what is left out, and warnings about the analysis' time range).
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "catena/model/model.hpp"

namespace catena::model::detail {

// Concatenation by appending (GCC 12's -Wrestrict misfires on chains of operator+ with
// temporaries at -O2).
template <class... Parts>
std::string cat(const Parts&... parts) {
  std::string text;
  (text.append(parts), ...);
  return text;
}

// "1 span", "3 spans".
std::string plural(long long n, const std::string& word);

// Rows "  label<pad>value"; labels are padded to one column (18 characters from the
// indent 2), deeper indents eat into the padding so that values stay aligned.
class SummaryTable {
 public:
  static constexpr int label_width = 18;
  void row(const std::string& label, const std::string& value, int indent = 2) {
    out_ << std::string(static_cast<std::size_t>(indent), ' ') << label;
    const int pad = label_width - static_cast<int>(label.size()) - (indent - 2);
    out_ << std::string(static_cast<std::size_t>(std::max(pad, 1)), ' ') << value << "\n";
  }
  void heading(const std::string& text) { out_ << text << "\n"; }
  std::string str() const { return out_.str(); }

 private:
  std::ostringstream out_;
};

// What the summary collects besides its rows: things the model leaves out (printed under
// "Left out:") and warnings (printed last, each on a line starting "warning: ").
struct SummaryNotes {
  std::vector<std::string> left_out;
  std::vector<std::string> warnings;
};

// Not collective. Rows describing model.catenary (which must be set): spans, dimension,
// element length, wires, stitch wires, droppers, clamp masses, steady arms, messenger
// supports, damping; and its left-out items.
void describe_catenary(const Model& model, SummaryTable& table, SummaryNotes& notes);

// Not collective. Rows for the moving loads and pantographs (path, speed, forces, stages,
// contact, the time on the path within the analysis), their left-out items and warnings
// (a load or pantograph leaving its path before the analysis ends, an evaluation section
// not traversed within the duration).
void describe_moving(const Model& model, SummaryTable& table, SummaryNotes& notes);

// Not collective. The "Advice:" heading and its rows for a dynamic run of a catenary with
// pantographs (nothing otherwise): each pantograph's speed against the contact wire's wave
// speed, pantographs in another's wake, the structure model measured to hold on such a
// run, the droppers' static pull against the pantographs' uplift, and the contact spring's
// mode against the step (structure_advice.cpp; docs/accuracy.md).
void advise_structure(const Model& model, SummaryTable& table);

// Not collective. True if anything outside the pantographs damps the structure: cable or
// beam damping_time or Rayleigh damping, bar damping, spring or elastic-support damping.
bool structure_is_damped(const Model& model);

}  // namespace catena::model::detail
