// Cancellation polling shared by every long loop of the core.
#include "common/limits.hpp"

#include "common/errors.hpp"

namespace arg {

void check_interrupt(const StopRequested& stop) {
  if (stop && stop()) throw Interrupted();
}

}  // namespace arg
