#pragma once
// Scene item "mpm" (items/item_mpm.cc): what a test reads of its section besides the registry's
// entry (scene/models.h).
#include "fiberbridge/mpm/parameters.h"

#include <deal.II/base/parameter_handler.h>

namespace fiberbridge::app {

/// The MPM section read and validated, with the notes on deprecated keys it met.
mpm::MpmParameters read_mpm_section(dealii::ParameterHandler& prm);

} // namespace fiberbridge::app
