#pragma once
// What a pantograph run says at its end about the contact force's own quality: where the
// steps did not resolve it (post/contact_resolution.hpp), and where the head lost contact
// and struck the wire again often enough that the loss of contact is the step's and the
// method's as much as the line's (post/contact_strikes.hpp).
#include <vector>

#include "catena/model/model.hpp"
#include "catena/post/contact_resolution.hpp"
#include "catena/post/contact_strikes.hpp"

namespace catena::app {

// Not collective (rank 0). Names each pantograph whose contact force the steps did not
// resolve: its statistics are then the step's.
void warn_unresolved_contact(const model::Model& m,
                             const std::vector<post::ContactResolution>& resolution);

// Not collective (rank 0). Names each pantograph that struck the wire again
// post::ContactStrikes::kRepeated times or more after losing contact (penalty contacts: a
// bilateral one's force is a multiplier that may change sign without leaving the wire).
void warn_repeated_strikes(const model::Model& m, const std::vector<post::ContactStrikes>& strikes);

}  // namespace catena::app
