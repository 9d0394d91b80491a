#include "models/model.hpp"

#include <stdexcept>
#include <string>

namespace iwb::models {

// Reached only if a model declares StressPointUpdate::kIncrement without overriding update: a
// programming error, not a user's.
void Model::update(const StateVector&, const InterfaceStrain&, StateVector&) const {
  throw std::logic_error(std::string(name()) + " has no closed-form increment");
}
void Model::update(const StateVectorT<Dual>&, const InterfaceStrainT<Dual>&,
                   StateVectorT<Dual>&) const {
  throw std::logic_error(std::string(name()) + " has no closed-form increment");
}

}  // namespace iwb::models
