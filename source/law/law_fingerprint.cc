#include "fiberbridge/law/law_fingerprint.h"

#include "fiberbridge/core/binary_archive.h"

#include <cstdio>

namespace fiberbridge::law {

std::string exact_number(double v, const std::string& unit) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return unit.empty() ? std::string(b) : std::string(b) + " " + unit;
}

std::string law_fingerprint(const TractionLaw& law) {
  const double dc = law.critical_opening();
  std::string samples;
  char b[40];
  for (int i = 0; i <= 200 && dc > 0; ++i) {
    std::snprintf(b, sizeof b, "%a;", law.envelope(1.05 * dc * i / 200));
    samples += b;
  }
  std::snprintf(b, sizeof b, "%016llx",
                static_cast<unsigned long long>(checksum64(samples.data(), samples.size())));
  return law.name() + ", delta_c " + exact_number(dc, "m") + ", area " +
         exact_number(law.area(), "J/m^2") + ", initial stiffness " +
         exact_number(law.initial_stiffness(), "Pa/m") + ", envelope hash " + b;
}

} // namespace fiberbridge::law
