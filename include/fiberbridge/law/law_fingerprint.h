#pragma once
// A law as one line that changes whenever the law does (checkpoints and the records of finished
// work that `fiberbridge run --resume` restores are tied to the law they were made with).
#include "fiberbridge/law/traction_law.h"

#include <string>

namespace fiberbridge::law {

/// Name, delta_c, area and initial stiffness of the law, and a hash of its envelope at 201
/// openings over [0, 1.05 delta_c] (a table or fitted law from a changed data file differs there
/// even when its name does not).
std::string law_fingerprint(const TractionLaw& law);

/// "%.17g unit": a value that reads back to the same double.
std::string exact_number(double value, const std::string& unit = "");

} // namespace fiberbridge::law
