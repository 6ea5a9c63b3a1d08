// identify's own forward model, the beam (identify/forward_model.h).
#include "fiberbridge/identify/forward_model.h"

#include <algorithm>

namespace fiberbridge::identify {

ForwardModel beam_forward_model(const beam::BeamParameters& parameters) {
  ForwardModel m;
  m.name = "beam";
  m.run = [parameters](const specimen::Specimen& specimen, const specimen::Material& material,
                       const law::TractionLaw& law, double j_tip, double reach) {
    beam::BeamParameters bp = parameters;
    const double min_lig = bp.minimum_ligament > 0 ? bp.minimum_ligament : specimen.height;
    // Run a few advances past the last reading (the model may lag it), within the ligament.
    bp.final_crack_length =
        std::min(reach + 5 * bp.tip_advance, specimen.length - min_lig - 2 * bp.tip_advance);
    return beam::simulate_dcb(specimen, material, law, j_tip, bp);
  };
  return m;
}

} // namespace fiberbridge::identify
