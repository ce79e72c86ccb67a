#include "signorini/contact/contact_set.hpp"

#include <algorithm>

namespace signorini {

Index ContactSet::num_movable() const {
  return static_cast<Index>(std::count(movable.begin(), movable.end(), true));
}

}  // namespace signorini
