#pragma once
// How every model puts a rigid law (sigma(0+) > 0: linear or exponential softening) on its crack
// (docs/design.md section 2, "Rigid laws in the models"): one rule, so that the same scene gives
// the beam, the FEM and the MPM the same discrete law, the law as given.
//
// Extrinsic insertion, as dynamic-insertion codes do: a crack segment becomes cohesive when the
// tip passes it and from then on carries the law as given, starting at sigma(0+). Until then the
// segment is intact (tied in the FEM, the ligament's foundation in the beam, one velocity field in
// the MPM), so no model needs an elastic rise to hold a closed crack. An elastic rise to delta_e
// (law::ElasticRiseLaw, PiecewiseLinearLaw::with_elastic_rise) took sigma(0) delta_e/2 off the
// area and off R for good, and its kink inside the tip element cost the FEM's tip J up to 2 % of R
// early in the curve (docs/verification.md, "Rigid laws").
#include "fiberbridge/law/traction_law.h"

#include <string>
#include <vector>

namespace fiberbridge::law {

/// The one rule: a model puts the scene's `law` itself on its crack, rigid or not (extrinsic
/// insertion); for a rigid law it says so in its notes. Every model calls this once, before its
/// first step: it adds the insertion note (rigid_law_insertion_note) to `notes` when `law` is
/// rigid. (It replaced `discrete_law`, which returned `law` unchanged.)
void note_rigid_law_insertion(const TractionLaw& law, std::vector<std::string>& notes);

/// The note note_rigid_law_insertion adds when it inserts `law` extrinsically; empty when the law
/// is not rigid (it has its own elastic rise, or no bridging).
std::string rigid_law_insertion_note(const TractionLaw& law);

/// A rigid law with an elastic rise from (0,0) to (delta_e, sigma(delta_e)) (a polyline stays a
/// polyline; other laws are wrapped in law::ElasticRiseLaw, which refers to `law`: it must outlive
/// the result); nullptr when `law` is not rigid. Throws InputError naming `key` when delta_e is not
/// positive or not before the law's first kink. For comparisons with intrinsic-law codes only:
/// the models never apply it.
TractionLawPtr with_elastic_rise(const TractionLaw& law, double delta_e, const std::string& key);

} // namespace fiberbridge::law
