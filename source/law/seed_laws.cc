#include "fiberbridge/law/seed_laws.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

namespace fiberbridge::law {

TrilinearParameters seed_control_law(const std::string& material) {
  using units::kPa;
  using units::mm;
  struct Row {
    const char* name;
    double s1_kPa, s2_kPa, dc_mm;
  };
  // Table 1, column "0" (control): sigma1, sigma2; delta_c from section 3.1.
  static const Row rows[] = {{"PVA", 661, 187, 6.0},
                             {"EPI", 579, 177, 3.5},
                             {"PRF", 319, 192, 3.5},
                             {"PF", 599, 176, 3.5},
                             {"DF", 57, 25, 3.5}};
  for (const auto& r : rows)
    if (material == r.name)
      return {0.1 * mm, r.s1_kPa * kPa, 1.0 * mm, r.s2_kPa * kPa, r.dc_mm * mm};
  throw InputError("seed control law: unknown material '" + material +
                   "', expected PVA, EPI, PRF, PF or DF");
}

} // namespace fiberbridge::law
