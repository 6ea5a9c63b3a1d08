#pragma once
// Bridging traction laws sigma(delta) (docs/design.md section 1). SI units: opening in m, traction
// in Pa, energies per unit crack area in J/m^2.
//
// A law is its monotonic-loading envelope. History (unloading to the origin: an elastic-damage
// zone, seed Fig. 1B) and contact in closing are handled once, in respond(), for every law.
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace fiberbridge::law {

/// State of one cohesive point under a history: what respond() returns.
struct CohesiveResponse {
  double traction = 0;  ///< normal traction [Pa], positive in opening, negative in contact
  double tangent = 0;   ///< d traction / d opening at fixed history [Pa/m] (consistent tangent)
  double delta_max = 0; ///< updated history: largest opening reached [m]
  bool failed = false;  ///< delta_max has passed delta_c: the point is traction-free in opening
};

class TractionLaw {
public:
  virtual ~TractionLaw() = default;

  /// Short name used in outputs ("trilinear", "linear", ...).
  virtual std::string name() const = 0;
  /// Envelope traction for monotonic opening delta >= 0 [Pa]; zero for delta >= delta_c.
  virtual double envelope(double delta) const = 0;
  /// d envelope / d delta [Pa/m] (right derivative at kinks).
  virtual double envelope_slope(double delta) const = 0;
  /// int_0^delta envelope [J/m^2], exact (closed form where the law has one).
  virtual double envelope_integral(double delta) const = 0;
  /// Critical opening delta_c [m]: traction-free beyond. Zero for the no-bridging law.
  virtual double critical_opening() const = 0;
  /// Openings where the envelope has kinks, including 0 and delta_c (for exact quadrature,
  /// grids and plots).
  virtual std::vector<double> kinks() const = 0;

  /// Area under the law, J_c = int_0^delta_c sigma (seed Eq. 8 for the trilinear law) [J/m^2].
  double area() const { return envelope_integral(critical_opening()); }
  /// Largest envelope traction and the opening where it occurs.
  std::pair<double, double> peak() const;
  /// True when sigma(0+) > 0 (linear or exponential softening): the law has no elastic rise; the
  /// models insert it extrinsically, from sigma(0+) (law/rigid_law.h).
  bool rigid_at_zero_opening() const { return envelope(0.0) > 0.0; }
  /// Slope of the first elastic rise sigma(d1)/d1 [Pa/m]; +inf for a rigid law, 0 for none.
  double initial_stiffness() const;

  /// Traction at `opening` given the committed history `delta_max` (unload/reload along the
  /// secant to the origin below delta_max; envelope above; contact with `contact_stiffness`
  /// [Pa/m] for negative opening, storing no damage and doing no negative work).
  CohesiveResponse respond(double opening, double delta_max, double contact_stiffness) const;
};

using TractionLawPtr = std::shared_ptr<const TractionLaw>;

/// The forward R curve of seed Eq. 2 for an elastic-damage zone:
/// R(delta) = J_tip + int_0^delta sigma - delta*sigma(delta)/2 for delta <= delta_c, G_ss beyond.
double r_curve_eq2(const TractionLaw& law, double j_tip, double delta);

/// Eq. 1: far-field J integral J_ff = J_tip + int_0^delta sigma (path independence).
double j_far_field_eq1(const TractionLaw& law, double j_tip, double delta);

} // namespace fiberbridge::law
