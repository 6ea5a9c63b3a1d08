#pragma once
// The fiber-bridging model of seed section 3.4 (Eqs. 9-15). SI units.
namespace fiberbridge::analysis {

struct BridgingFiber {
  double E_f = 40e9;         ///< fiber modulus [Pa] (tracheid: 40 GPa)
  double r_f = 20e-6;        ///< fiber radius [m] (tracheid: 20 um)
  double sigma_fb = 648e6;   ///< fiber strength [Pa] (tracheid: 648 MPa); eps_fb = sigma_fb / E_f
  double G_c = 200;          ///< peeling toughness [J/m^2]
  double area() const;       ///< A_f = pi r_f^2 (cylinder)
  double peel_width() const; ///< W_f = pi r_f
};

/// The seed's individual tracheid (the struct's defaults): E_f 40 GPa, r_f 20 um, sigma_f 648 MPa,
/// G_c 200 J/m^2 (seed section 3.4, refs. 30, 31).
BridgingFiber seed_tracheid_fiber();
/// The seed's fiber bundle as stated: E_f 10 GPa, r_f 200 um, sigma_f 100 MPa, peeling toughness
/// `G_c` (the seed's lower value 50 J/m^2 by default).
BridgingFiber seed_bundle_fiber(double G_c = 50);

/// Eq. 9, exact: fiber strain for root opening delta, opening slope k, r = 1 - x/l_b, with the
/// linear opening profile delta(x) = k (l_b - x).
double fiber_strain_exact(double delta, double k, double r, double l_b);

/// Eq. 9, small-k form: k^2 r / (2 (1 - r)^2) (the strain Eqs. 10-14 are built on).
double fiber_strain_small_k(double k, double r);

/// Eq. 11's integral factor F(r_b) = (2 r_b - 1)/(1 - r_b)^2 - ln(1 - r_b)/r_b (F(0) = 0 limit),
/// which equals (1/r_b) int_0^r_b r(1+r)/(1-r)^3 dr (the 1/r_b of Eq. 11's first line included).
/// Domain [0, 1); InputError outside.
double eq11_factor(double r_b);

/// Eq. 12: r_b where the fiber reaches its breaking strain, r_b = 1 + phi^2 - phi sqrt(2 + phi^2),
/// phi = k / (2 sqrt(eps_fb)).
double r_b_breaking(double k, const BridgingFiber& f);

/// Eq. 14: r_b where peeling reaches G_c, r/(1-r)^4 = 4 W_f G_c / (A_f E_f k^4), solved
/// numerically (unique root in (0,1): the left side increases monotonically).
double r_b_peeling(double k, const BridgingFiber& f);

enum class BridgingMechanism { breaking, peeling, governing };

/// The mechanism that sets x_b at opening slope k: the one with the larger x_b (smaller r_b).
/// Returns breaking or peeling (breaking on an exact tie).
BridgingMechanism governing_mechanism(double k, const BridgingFiber& f);
/// r_b of Eq. 12, Eq. 14 or the governing one of the two.
double r_b(double k, const BridgingFiber& f, BridgingMechanism m);

/// Eq. 11 with r_b from Eq. 12 or 14 (`governing`: the mechanism with the larger x_b, i.e. the
/// smaller r_b, seed section 3.4): sigma(delta) for density rho_b [1/m^2], zone length l_b [m].
double bridging_stress_exact(double delta, double l_b, double rho_b, const BridgingFiber& f,
                             BridgingMechanism m);

/// Small-k limits: Eq. 13 (breaking) and Eq. 15 (peeling), linear in delta.
double bridging_stress_eq13(double delta, double l_b, double rho_b, const BridgingFiber& f);
double bridging_stress_eq15(double delta, double l_b, double rho_b, const BridgingFiber& f);

/// Bridged-fiber density [1/m^2] that makes the model give `sigma` at `delta` (seed: sigma at
/// delta = 0.1 mm, i.e. sigma_1), for the small-k forms (Eq. 13 or 15) or the exact form.
double bridged_density(double sigma, double delta, double l_b, const BridgingFiber& f,
                       BridgingMechanism m, bool small_k);

/// The fiber-bridging model at one point of a measured law (seed section 3.4): the bridged-fiber
/// densities that carry `sigma` at opening `delta` over a zone of length `zone_length` by Eq. 15
/// (peeling), Eq. 13 (breaking) and the exact governing form, and which mechanism governs.
struct BridgingEstimate {
  double sigma = 0, delta = 0, zone_length = 0; ///< [Pa], [m], [m]
  BridgingFiber fiber;
  double rho_peeling = 0, rho_breaking = 0, rho_exact = 0; ///< [1/m^2]
  bool peeling_governs = false;
  /// The model's law at an opening: exact (governing), Eq. 13 and Eq. 15, with rho_exact [Pa].
  double stress_exact(double d) const;
  double stress_eq13(double d) const;
  double stress_eq15(double d) const;
};
BridgingEstimate estimate_bridging(double sigma, double delta, double zone_length,
                                   const BridgingFiber& f);

} // namespace fiberbridge::analysis
