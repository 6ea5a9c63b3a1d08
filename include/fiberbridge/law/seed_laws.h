#pragma once
// The control (0-cycle) trilinear laws of the seed's Table 1, the reference cases of the paper's
// Fig. 8 and Fig. 10: d1 = 0.1 mm, d2 = 1.0 mm fixed, delta_c = 6 mm for PVA and 3.5 mm for the
// others (seed section 3.1).
#include "fiberbridge/law/piecewise_linear_law.h"

#include <string>

namespace fiberbridge::law {

/// material: PVA, EPI, PRF, PF or DF (solid Douglas-fir). Throws InputError for another name.
TrilinearParameters seed_control_law(const std::string& material);

} // namespace fiberbridge::law
