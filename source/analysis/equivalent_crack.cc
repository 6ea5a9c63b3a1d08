// CBBM equivalent crack length (equivalent_crack.h).
#include "fiberbridge/analysis/equivalent_crack.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"

#include <algorithm>

namespace fiberbridge::analysis {

namespace {
bool has_shear(double g13) {
  return std::isfinite(g13) && g13 > 0;
}
} // namespace

double CbbmBeam::alpha() const {
  return 8 / (flexural_modulus * width * std::pow(arm_thickness, 3));
}

double CbbmBeam::beta() const {
  return has_shear(shear_modulus) ? 12 / (5 * width * arm_thickness * shear_modulus) : 0.0;
}

double CbbmBeam::compliance(double a_e) const {
  return alpha() * a_e * a_e * a_e + beta() * a_e;
}

double CbbmBeam::effective_crack(double C) const {
  // a^3 + p a + q = 0, p = beta/alpha >= 0, q = -C/alpha: the discriminant q^2/4 + p^3/27 > 0,
  // one real root u + v with u v = -p/3; v is taken as -p/(3u) rather than its own cube root,
  // which would cancel against u when p is small (little shear).
  const double p = beta() / alpha(), q = -C / alpha();
  const double u = std::cbrt(-q / 2 + std::sqrt(q * q / 4 + p * p * p / 27));
  return u > 0 ? u - p / (3 * u) : 0.0;
}

double CbbmBeam::energy_release_rate(double P, double a_e) const {
  const double B = width, h = arm_thickness;
  const double shear = has_shear(shear_modulus) ? 1 / (5 * shear_modulus) : 0.0;
  return 6 * P * P / (B * B * h) * (2 * a_e * a_e / (flexural_modulus * h * h) + shear);
}

double cbbm_flexural_modulus(double B, double h, double g13, double delta, double a0, double c0,
                             const std::string& where) {
  const double ae = a0 + delta;
  const double shear = has_shear(g13) ? 12 * ae / (5 * B * h * g13) : 0.0;
  if (!(c0 > shear))
    throw InputError(where + ": the initial compliance " + num(c0 * 1e3) +
                     " mm/N is not larger than the shear term " + num(shear * 1e3) +
                     " mm/N of CBBM at a0 + |Delta| = " + num(ae * 1e3) +
                     " mm; check the shear modulus and the geometry");
  return 8 * ae * ae * ae / (B * h * h * h) / (c0 - shear);
}

double corrected_beam_delta(double e11, double e22, double g13, double h) {
  const double gamma = 1.18 * std::sqrt(e11 * e22) / g13;
  const double r = gamma / (1 + gamma);
  return h * std::sqrt(e11 / (11 * g13) * (3 - 2 * r * r));
}

InitialCompliance initial_linear_part(const TestRecord& rec, double low, double high) {
  InitialCompliance out;
  const double peak = *std::max_element(rec.load.begin(), rec.load.end());
  std::size_t end = 0;
  while (end < rec.load.size() && rec.load[end] < high * peak)
    ++end;
  double n = 0, sp = 0, sd = 0;
  for (std::size_t i = 0; i < end; ++i)
    if (rec.load[i] >= low * peak) {
      n += 1;
      sp += rec.load[i];
      sd += rec.opening[i];
    }
  double spp = 0, spd = 0;
  const double mp = n > 0 ? sp / n : 0, md = n > 0 ? sd / n : 0;
  for (std::size_t i = 0; i < end; ++i)
    if (rec.load[i] >= low * peak) {
      spp += (rec.load[i] - mp) * (rec.load[i] - mp);
      spd += (rec.load[i] - mp) * (rec.opening[i] - md);
    }
  if (n < 3 || !(spp > 0) || !(spd > 0))
    throw InputError(rec.source + ": record '" + rec.name + "' has " + std::to_string(int(n)) +
                     " rows with a load between " + num(100 * low) + " and " + num(100 * high) +
                     " % of its peak before the load first reaches " + num(100 * high) +
                     " % of it, or no rising opening there; the initial compliance needs at "
                     "least 3");
  out.compliance = spd / spp;
  out.offset = md - out.compliance * mp;
  out.rows = static_cast<std::size_t>(n);
  out.end = end;
  return out;
}

} // namespace fiberbridge::analysis
