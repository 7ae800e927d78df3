#include "contact_warnings.hpp"

#include <cstdio>

namespace catena::app {

void warn_unresolved_contact(const model::Model& m,
                             const std::vector<post::ContactResolution>& resolution) {
  for (std::size_t c = 0; c < resolution.size() && c < m.contacts.size(); ++c) {
    if (!resolution[c].unresolved()) continue;
    if (m.contacts[c].bilateral) {
      std::fprintf(stderr,
                   "catena: warning: pantograph '%s': the steps do not resolve its contact "
                   "force (roughness %.2f > %.1f: the force changes from step to step by more "
                   "than a sine with 9 steps per period does); a bilateral contact's force "
                   "follows every wave of the wire under the head, and the statistics are then "
                   "the step's, not the line's: halve integrator.dt until this warning goes "
                   "(docs/accuracy.md, \"Where each method stops working\")\n",
                   m.contacts[c].name.c_str(), resolution[c].roughness(),
                   post::ContactResolution::kUnresolved);
      continue;
    }
    std::fprintf(stderr,
                 "catena: warning: pantograph '%s': the steps do not resolve its contact force "
                 "(roughness %.2f > %.1f: the force changes from step to step by more than a "
                 "sine with 9 steps per period does); the contact spring's own mode "
                 "(contact.stiffness %g N/m between the head and the wire) is the usual cause, "
                 "and the force statistics are then the step's, not the line's: halve "
                 "integrator.dt until this warning goes, lower contact.stiffness, or use an "
                 "L-stable method (radau) (docs/accuracy.md, \"Where each method stops "
                 "working\")\n",
                 m.contacts[c].name.c_str(), resolution[c].roughness(),
                 post::ContactResolution::kUnresolved, m.contacts[c].stiffness);
  }
}

void warn_repeated_strikes(const model::Model& m,
                           const std::vector<post::ContactStrikes>& strikes) {
  for (std::size_t c = 0; c < strikes.size() && c < m.contacts.size(); ++c) {
    // A bilateral contact cannot leave the wire: its force is a multiplier of either sign.
    if (m.contacts[c].bilateral || !strikes[c].repeated()) continue;
    std::fprintf(stderr,
                 "catena: warning: pantograph '%s' lost contact %zu times and struck the wire "
                 "again %zu times: each strike is an impact far shorter than the contact "
                 "spring's own mode, and how much contact is lost then depends on the step and "
                 "the method more than the filtered force does (100 times EN 50318's contact "
                 "stiffness on a single wire, dt 0.05 ms: loss of contact 2.27 %% with radau, "
                 "1.07 %% with hht, 0.93 %% with bdf, sigma within 1 %% for all): confirm the "
                 "loss of contact and the extremes with a run at half integrator.dt or with "
                 "catena study (docs/accuracy.md, \"Repeated strikes\")\n",
                 m.contacts[c].name.c_str(), strikes[c].losses(), strikes[c].strikes());
  }
}

}  // namespace catena::app
