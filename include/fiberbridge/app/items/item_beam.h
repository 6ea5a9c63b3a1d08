#pragma once
// Scene item "beam" (items/item_beam.cc): what a test reads of its section besides the registry's
// entry (scene/models.h).
#include "fiberbridge/beam/dcb_beam.h"

#include <deal.II/base/parameter_handler.h>

namespace fiberbridge::app {

/// The Beam section read and validated, with the notes on deprecated keys it met (the item reads it
/// so; tests/app/section_tests.cc).
beam::BeamParameters read_beam_section(dealii::ParameterHandler& prm);

} // namespace fiberbridge::app
