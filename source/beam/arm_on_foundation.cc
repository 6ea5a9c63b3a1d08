#include "fiberbridge/beam/arm_on_foundation.h"

#include "fiberbridge/core/error.h"

#include <cmath>
#include <complex>
#include <sstream>

namespace fiberbridge::beam {

double arm_bending_modulus(const specimen::Material& m) {
  // A wide arm in plane strain cannot contract across its width: E_L/(1 - nu_LT nu_TL) is the
  // plane-strain modulus along the beam within the LT plane (the out-of-plane constants, which
  // the scene does not give, are taken as the LT ones).
  return m.plane_stress ? m.E_L : m.E_L / (1 - m.nu_LT * m.nu_TL());
}

ArmConstants arm_constants(const specimen::Specimen& s, const specimen::Material& m, double kappa,
                           double foundation_modulus) {
  ArmConstants arm;
  arm.width = s.width;
  arm.thickness = s.arm_thickness();
  const double h = arm.thickness;
  arm.EI = arm_bending_modulus(m) * s.width * h * h * h / 12;
  arm.S = kappa * m.G_LT * s.width * h;
  arm.foundation_modulus = foundation_modulus;
  return arm;
}

namespace {
using cplx = std::complex<double>;

/// Decaying solution for given end resultants. With w = C e^{r x}, theta = phi C e^{r x}:
/// EI r^2 phi + S (r - phi) = 0 gives phi = S r/(S - EI r^2), and the second equation then gives
/// r^4 - (k_w/S) r^2 + k_w/EI = 0. The two roots with negative real part decay into the ligament.
void end_response(const ArmConstants& arm, double k_w, double M0, double Q0, double& w0,
                  double& t0) {
  const double EI = arm.EI, S = arm.S;
  const cplx b = k_w / S;
  const cplx disc = std::sqrt(b * b - 4.0 * k_w / EI);
  const cplx p[2] = {0.5 * (b + disc), 0.5 * (b - disc)};
  cplx r[2], phi[2];
  for (int i = 0; i < 2; ++i) {
    r[i] = -std::sqrt(p[i]); // principal root has Re >= 0: its negative decays
    phi[i] = S * r[i] / (S - EI * r[i] * r[i]);
  }
  // M(0) = EI sum C_i phi_i r_i, Q(0) = S sum C_i (r_i - phi_i).
  const cplx a11 = EI * phi[0] * r[0], a12 = EI * phi[1] * r[1];
  const cplx a21 = S * (r[0] - phi[0]), a22 = S * (r[1] - phi[1]);
  const cplx det = a11 * a22 - a12 * a21;
  const cplx c1 = (M0 * a22 - a12 * Q0) / det;
  const cplx c2 = (a11 * Q0 - a21 * M0) / det;
  w0 = (c1 + c2).real();
  t0 = (c1 * phi[0] + c2 * phi[1]).real();
}
} // namespace

EndFlexibility semi_infinite_end_flexibility(const ArmConstants& arm) {
  if (!(arm.EI > 0 && arm.S > 0 && arm.foundation_modulus > 0))
    throw InputError("beam: the arm needs positive EI, S and foundation modulus");
  double k_w = arm.k_w();
  // A double root (k_w EI = 4 S^2 exactly) makes the two exponentials coincide; the flexibilities
  // are continuous there, so step off it by a relative 1e-7 (changes them by about as much).
  if (std::abs(k_w * arm.EI - 4 * arm.S * arm.S) < 1e-9 * k_w * arm.EI)
    k_w *= 1 + 1e-7;
  EndFlexibility f;
  end_response(arm, k_w, 1.0, 0.0, f.w_M, f.t_M);
  end_response(arm, k_w, 0.0, 1.0, f.w_Q, f.t_Q);
  return f;
}

double root_rotation_length(const ArmConstants& arm) {
  return arm.EI * std::abs(semi_infinite_end_flexibility(arm).t_M);
}

double calibrated_foundation_modulus(const specimen::Specimen& s, const specimen::Material& m,
                                     double kappa) {
  s.validate();
  m.validate();
  const double h = s.arm_thickness();
  const double target = specimen::cbt_chi(m) * h;
  ArmConstants arm = arm_constants(s, m, kappa, 1.0);
  // A rigid foundation still lets the section rotate through shear: c -> sqrt(EI/S) as k -> inf.
  // The root rotation decreases monotonically with k, so CBT is reachable only above that.
  const double c_rigid = std::sqrt(arm.EI / arm.S);
  if (!(target > c_rigid * (1 + 1e-6))) {
    std::ostringstream msg;
    msg << "Beam: corrected beam theory's root rotation chi h = " << target * 1e3
        << " mm is not above the shear-only value sqrt(EI/S) = " << c_rigid * 1e3
        << " mm, so no foundation stiffness reproduces it; set 'Foundation modulus' explicitly";
    throw InputError(msg.str());
  }
  auto c_of = [&](double k) {
    arm.foundation_modulus = k;
    return root_rotation_length(arm);
  };
  // Bracket around the physical guess 2 E_T/h (the through-thickness stiffness of half an arm),
  // then bisect in log k.
  double lo = 2 * m.E_T / h, hi = lo;
  for (int i = 0; i < 200 && c_of(lo) < target; ++i)
    lo *= 0.5;
  for (int i = 0; i < 200 && c_of(hi) > target; ++i)
    hi *= 2;
  if (!(c_of(lo) >= target && c_of(hi) <= target))
    throw ComputationError("Beam: could not bracket the foundation modulus matching CBT");
  for (int i = 0; i < 200 && hi / lo > 1 + 1e-13; ++i) {
    const double mid = std::sqrt(lo * hi);
    (c_of(mid) > target ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

LefmState lefm_state(const ArmConstants& arm, double j_tip, double a) {
  const EndFlexibility f = semi_infinite_end_flexibility(arm);
  // A load P (away from the crack plane) at the load line a ahead of the ligament leaves the
  // resultants M = P a and Q = -P at the tip (M' + Q = 0 in the free arm, M = 0 at the load).
  const double w_per_P = a * f.w_M - f.w_Q;
  const double t_per_P = a * f.t_M - f.t_Q;
  const double delta_0 = std::sqrt(2 * j_tip / arm.foundation_modulus);
  LefmState st;
  st.load = 0.5 * delta_0 / w_per_P;
  // Load-line deflection: the Timoshenko cantilever clamped at the tip plus the rigid motion of
  // the tip section (w_tip and rotation theta_tip carried over the arm length a).
  const double P = st.load;
  const double w_load = P * (a * a * a / (3 * arm.EI) + a / arm.S) + P * w_per_P - P * t_per_P * a;
  st.load_point_opening = 2 * w_load;
  return st;
}

} // namespace fiberbridge::beam
