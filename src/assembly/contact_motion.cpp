// SecondOrderSystem, part: pantographs' contact points moved with a moving window's state
// (the class: include/catena/assembly/second_order_system.hpp).
#include "catena/assembly/second_order_system.hpp"
#include "catena/couplings/bilateral_contact.hpp"
#include "catena/couplings/pantograph_contact.hpp"

namespace catena::assembly {

void SecondOrderSystem::move_contacts_back(double ds) {
  for (auto& coupling : couplings_) {
    if (auto* penalty = dynamic_cast<couplings::PantographContact*>(coupling.get()))
      penalty->move_back_along_path(ds);
    else if (auto* bilateral = dynamic_cast<couplings::BilateralContact*>(coupling.get()))
      bilateral->move_back_along_path(ds);
  }
}

}  // namespace catena::assembly
