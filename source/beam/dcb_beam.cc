#include "fiberbridge/beam/dcb_beam.h"

#include "banded_lu.h"
#include "fiberbridge/beam/arm_on_foundation.h"
#include "fiberbridge/beam/elastica.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/rigid_law.h"
#include "fiberbridge/result/numerical_fault.h"
#include "fiberbridge/result/steady_state.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

namespace fiberbridge::beam {

using result::RCurvePoint;
using result::SimulationResult;
using units::mm;

void BeamParameters::validate(const std::string& c) const {
  if (n_elements < 4)
    throw InputError(c + "/Number of elements: need at least 4, got " + std::to_string(n_elements));
  if (!(tip_advance > 0))
    throw InputError(c + "/Tip advance: must be positive (mm)");
  if (!(foundation_modulus >= 0))
    throw InputError(c + "/Foundation modulus: must be >= 0 (0 = calibrated to CBT)");
  if (!(shear_coefficient > 0))
    throw InputError(c + ": the shear coefficient must be positive");
  if (!(minimum_ligament >= 0))
    throw InputError(c + "/Minimum ligament: must be >= 0 (mm; 0 = specimen height)");
  if (!(steady_state_window > 0))
    throw InputError(c + "/Steady state window: must be positive (mm)");
  if (!(plateau_tolerance > 0 && plateau_tolerance < 1))
    throw InputError(c + "/Plateau tolerance: must be in (0, 1)");
  if (!(newton_tolerance > 0 && newton_tolerance < 1e-2))
    throw InputError(c + "/Newton tolerance: must be in (0, 0.01)");
  if (max_newton_iterations < 1)
    throw InputError(c + "/Maximum Newton iterations: must be >= 1");
  if (!(final_crack_length >= 0))
    throw InputError(c + ": the final crack length must be >= 0 (0 = stop at steady state)");
  if (max_advances < 1)
    throw InputError(c + ": max_advances must be >= 1");
}

void check_dcb_inputs(const specimen::Specimen& specimen, const specimen::Material& material,
                      const BeamParameters& parameters) {
  specimen.validate();
  material.validate();
  parameters.validate();
  const double minimum_ligament =
      parameters.minimum_ligament > 0 ? parameters.minimum_ligament : specimen.height;
  if (!(specimen.length - specimen.initial_crack > minimum_ligament))
    throw InputError(
        "Specimen: the ligament L - a0 = " + fmt((specimen.length - specimen.initial_crack) / mm) +
        " mm is not longer than the minimum ligament " + fmt(minimum_ligament / mm) +
        " mm (Beam/Minimum ligament; 0 = the specimen height)");
}

namespace {

/// Exact two-node Timoshenko element (cubic deflection, quadratic rotation: exact for an unloaded
/// span), dofs (w1, theta1, w2, theta2), Phi = 12 EI/(S l^2).
void timoshenko_stiffness(double EI, double S, double l, double K[4][4]) {
  const double phi = 12 * EI / (S * l * l);
  const double c = EI / ((1 + phi) * l * l * l);
  const double m[4][4] = {{12, 6 * l, -12, 6 * l},
                          {6 * l, (4 + phi) * l * l, -6 * l, (2 - phi) * l * l},
                          {-12, -6 * l, 12, -6 * l},
                          {6 * l, (2 - phi) * l * l, -6 * l, (4 + phi) * l * l}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      K[i][j] = c * m[i][j];
}

/// The beam model of one arm and its solver. run() reads like the algorithm.
class DcbBeamSolver {
public:
  DcbBeamSolver(const specimen::Specimen& specimen, const specimen::Material& material,
                const law::TractionLaw& law, double j_tip, const BeamParameters& parameters,
                const std::function<void(const std::string&)>& progress);
  SimulationResult run();

private:
  void setup_mesh();
  void set_tip(std::size_t tip);
  /// What Newton holds fixed while the load-point opening is free (crack-length control).
  enum class TipCondition {
    opening,   ///< k delta_tip^2/2 = J_tip: linear in u, a robust predictor
    j_integral ///< discrete tip J = J_tip: the propagation criterion
  };
  /// Newton for the state with the tip at node `tip`. Returns false (state unchanged) if it does
  /// not converge.
  bool solve_at_tip(std::size_t tip, TipCondition condition, std::string& why);
  /// Discrete tip J at u and, if asked, its gradient (dof, value) pairs.
  double tip_j(const std::vector<double>& u,
               std::vector<std::pair<std::size_t, double>>* grad) const;
  /// Residual and (if given) tangent at u. Returns the largest row sum of |terms| of the
  /// residual: its round-off floor is ~1e-16 of that.
  double assemble(const std::vector<double>& u, std::vector<double>& residual,
                  internal::BandedLU* tangent) const;
  double crack_opening(const std::vector<double>& u, std::size_t node) const {
    return 2 * u[2 * node] - delta_0_;
  }
  law::CohesiveResponse cohesive(const std::vector<double>& u, std::size_t node) const {
    return law_->respond(crack_opening(u, node), delta_max_[node], contact_stiffness_);
  }
  void commit_history();
  RCurvePoint measure_state() const;
  /// The free arm (load line to tip) of the current state at finite rotation: the load that
  /// keeps the ligament's tip deflection (hence the tip J) with the same bridging forces;
  /// `linear_energy` gets the small-rotation strain energy of the same arm.
  ElasticaState finite_free_arm(double& load, double& linear_energy) const;
  double section_j(const std::vector<double>& u, std::size_t element,
                   std::vector<std::pair<std::size_t, double>>* grad = nullptr) const;
  void finish(SimulationResult& result);
  void note(SimulationResult& r, const std::string& s) const { r.notes.push_back(s); }
  void say(const std::string& s) const {
    if (progress_)
      progress_(s);
  }

  specimen::Specimen specimen_;
  specimen::Material material_;
  const law::TractionLaw* law_;
  double j_tip_;
  BeamParameters prm_;
  std::function<void(const std::string&)> progress_;

  ArmConstants arm_;
  double delta_0_ = 0;                  // intact-ligament opening at G_tip = J_tip [m]
  double contact_stiffness_ = 0;        // [Pa/m]
  double force_scale_ = 0;              // LEFM initiation load [N], for Newton's test
  std::vector<double> x_;               // node positions; node 1 is the notch root a0
  std::vector<double> length_;          // element lengths
  std::vector<double> w_found_, w_coh_; // nodal trapezoid weights (foundation, bridging) [m]
  std::vector<double> delta_max_;       // committed history of the crack opening per node
  std::vector<double> u_;               // (w_i, theta_i) per node, one arm
  std::vector<std::array<double, 16>> element_K_;
  std::size_t tip_ = 1;
  std::size_t n_dofs_ = 0;
  double load_ = 0; // reaction at the load line [N]
};

DcbBeamSolver::DcbBeamSolver(const specimen::Specimen& specimen, const specimen::Material& material,
                             const law::TractionLaw& law, double j_tip,
                             const BeamParameters& parameters,
                             const std::function<void(const std::string&)>& progress)
    : specimen_(specimen), material_(material), law_(&law), j_tip_(j_tip), prm_(parameters),
      progress_(progress) {
  check_dcb_inputs(specimen_, material_, prm_);
  if (!(j_tip_ > 0) || !std::isfinite(j_tip_))
    throw InputError("Cohesive law/J tip: must be positive (J/m^2), got " + fmt(j_tip_));
  const double k =
      prm_.foundation_modulus > 0
          ? prm_.foundation_modulus
          : calibrated_foundation_modulus(specimen_, material_, prm_.shear_coefficient);
  arm_ = arm_constants(specimen_, material_, prm_.shear_coefficient, k);
  delta_0_ = std::sqrt(2 * j_tip_ / k);
  // Faces pressed together behave like the intact ligament.
  contact_stiffness_ = k;
  force_scale_ = lefm_state(arm_, j_tip_, specimen_.initial_crack).load;
  if (prm_.minimum_ligament == 0)
    prm_.minimum_ligament = specimen_.height;
  setup_mesh();
}

void DcbBeamSolver::setup_mesh() {
  // The sawn notch carries no load between its ends, so one exact element spans it; the
  // ligament [a0, L], where tip and zone travel, gets the uniform elements.
  const int n = prm_.n_elements;
  const double a0 = specimen_.initial_crack, L = specimen_.length;
  x_.assign(n + 2, 0.0);
  x_[1] = a0;
  for (int i = 1; i <= n; ++i)
    x_[1 + i] = a0 + (L - a0) * i / n;
  x_.back() = L;
  length_.resize(n + 1);
  element_K_.resize(n + 1);
  for (int e = 0; e <= n; ++e) {
    length_[e] = x_[e + 1] - x_[e];
    double K[4][4];
    timoshenko_stiffness(arm_.EI, arm_.S, length_[e], K);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        element_K_[e][4 * i + j] = K[i][j];
  }
  n_dofs_ = 2 * x_.size();
  u_.assign(n_dofs_, 0.0);
  delta_max_.assign(x_.size(), 0.0);
  set_tip(1);
}

void DcbBeamSolver::set_tip(std::size_t tip) {
  // Element e = [x_e, x_e+1] is notch (e = 0), bridged (1 <= e < tip) or intact (e >= tip).
  // Trapezoid weights put half of each element on its nodes: the tip node gets half an element
  // of foundation ahead and half an element of bridging behind, so the model's tip sits on the
  // node (second-order quadrature of both interfaces up to it).
  tip_ = tip;
  const std::size_t nn = x_.size();
  w_found_.assign(nn, 0.0);
  w_coh_.assign(nn, 0.0);
  for (std::size_t e = 1; e + 1 < nn; ++e) {
    auto& w = e >= tip ? w_found_ : w_coh_;
    w[e] += 0.5 * length_[e];
    w[e + 1] += 0.5 * length_[e];
  }
}

double DcbBeamSolver::assemble(const std::vector<double>& u, std::vector<double>& r,
                               internal::BandedLU* K) const {
  r.assign(n_dofs_, 0.0);
  std::vector<double> magnitude(n_dofs_, 0.0);
  if (K)
    K->set_zero();
  for (std::size_t e = 0; e < element_K_.size(); ++e) {
    const std::size_t d = 2 * e;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const double kij = element_K_[e][4 * i + j];
        r[d + i] += kij * u[d + j];
        magnitude[d + i] += std::abs(kij * u[d + j]);
        if (K)
          (*K)(d + i, d + j) += kij;
      }
  }
  const double B = arm_.width, k_w = arm_.k_w();
  for (std::size_t i = 1; i < x_.size(); ++i) {
    const std::size_t d = 2 * i;
    double f = k_w * w_found_[i] * u[d], t = k_w * w_found_[i];
    if (i == tip_ && w_coh_[i] > 0) {
      // The crack opening at the tip is zero by definition (to O(h_e^2) in the discrete
      // model); the half element of bridging lumped on the tip node carries what the law gives
      // just behind it, sigma(0+) (a rigid law's sigma_c; zero for a law with an elastic rise).
      // Evaluating respond() at a rounded zero would flip a rigid law between sigma_c and
      // contact.
      f += B * w_coh_[i] * law_->envelope(0.0);
    } else if (w_coh_[i] > 0) {
      // The traction sigma acts over B w_coh on the arm; d(delta)/dw = 2.
      const auto c = cohesive(u, i);
      f += B * w_coh_[i] * c.traction;
      t += 2 * B * w_coh_[i] * c.tangent;
    }
    r[d] += f;
    magnitude[d] += std::abs(f);
    if (K)
      (*K)(d, d) += t;
  }
  return *std::max_element(magnitude.begin(), magnitude.end());
}

bool DcbBeamSolver::solve_at_tip(std::size_t tip, TipCondition condition, std::string& why) {
  // Unknowns: every dof. Equations: equilibrium of all dofs except the load-line deflection w_0
  // (its row is the reaction, the load), plus the tip condition g(u) = 0. With w_0 eliminated
  // through an identity row, K~ du = (dw_0, -r'), so du = x1 + dw_0 x2 and the linearized
  // condition g + grad g . du = 0 fixes dw_0: two banded solves per iteration, no bordered
  // matrix to pivot.
  const std::size_t wt = 2 * tip;
  std::vector<std::pair<std::size_t, double>> grad;
  // g is scaled to be relative: (opening - target)/target or (J - J_tip)/J_tip.
  auto condition_value = [&](const std::vector<double>& v, bool with_gradient) {
    grad.clear();
    if (condition == TipCondition::opening) {
      const double target = 0.5 * delta_0_;
      if (with_gradient)
        grad.emplace_back(wt, 1 / target);
      return (v[wt] - target) / target;
    }
    const double j = tip_j(v, with_gradient ? &grad : nullptr);
    for (auto& gi : grad)
      gi.second /= j_tip_;
    return (j - j_tip_) / j_tip_;
  };
  std::vector<double> u = u_, r, x1(n_dofs_), x2(n_dofs_), trial(n_dofs_), r_trial;
  internal::BandedLU K(n_dofs_, 3, 3);
  auto merit = [&](const std::vector<double>& v, const std::vector<double>& res) {
    double m = 0;
    for (std::size_t i = 1; i < n_dofs_; ++i)
      m = std::max(m, std::abs(res[i]));
    return m / force_scale_ + std::abs(condition_value(v, false));
  };
  double magnitude = assemble(u, r, &K);
  for (int it = 0; it <= prm_.max_newton_iterations; ++it) {
    const double m = merit(u, r);
    // The residual cannot fall below the round-off of its largest terms (stiff short elements
    // or a stiff foundation make those large): 1e3 machine epsilons of them is converged too.
    const double floor = 1e3 * std::numeric_limits<double>::epsilon() * magnitude / force_scale_;
    if (m <= std::max(prm_.newton_tolerance, floor)) {
      u_ = u;
      load_ = r[0];
      return true;
    }
    if (it == prm_.max_newton_iterations)
      break;
    // The column of w_0 moves to the right-hand side of x2 (the response to a unit w_0).
    std::fill(x2.begin(), x2.end(), 0.0);
    x2[0] = 1;
    for (std::size_t j = 1; j <= 3; ++j) {
      x2[j] = -K(j, 0);
      K(0, j) = 0;
      K(j, 0) = 0;
    }
    K(0, 0) = 1;
    if (!K.factorize()) {
      why = "singular tangent";
      return false;
    }
    x1[0] = 0;
    for (std::size_t i = 1; i < n_dofs_; ++i)
      x1[i] = -r[i];
    K.solve(x1);
    K.solve(x2);
    const double g = condition_value(u, true);
    double g1 = 0, g2 = 0;
    for (const auto& [dof, value] : grad) {
      g1 += value * x1[dof];
      g2 += value * x2[dof];
    }
    if (g2 == 0) {
      why = "the tip condition does not respond to the load";
      return false;
    }
    const double dw0 = (-g - g1) / g2;
    // Backtracking on the merit: piecewise-linear laws switch branches (rise, softening,
    // unloading, contact) and a full step can overshoot a kink.
    // If no step length decreases the merit, the full step is taken anyway: on a piecewise-
    // linear law the exact Newton step onto the right branch can raise the merit first.
    double alpha = 1;
    bool decreased = false;
    for (int ls = 0; ls < 12 && !decreased; ++ls, alpha *= 0.5) {
      for (std::size_t i = 0; i < n_dofs_; ++i)
        trial[i] = u[i] + alpha * (x1[i] + dw0 * x2[i]);
      // The tangent comes with the residual: the accepted trial needs no second assembly.
      magnitude = assemble(trial, r_trial, &K);
      decreased = merit(trial, r_trial) < (1 - 1e-4 * alpha) * m;
    }
    if (!decreased) {
      for (std::size_t i = 0; i < n_dofs_; ++i)
        trial[i] = u[i] + x1[i] + dw0 * x2[i];
      magnitude = assemble(trial, r_trial, &K);
    }
    u.swap(trial);
    r.swap(r_trial);
  }
  why = "Newton did not converge in " + std::to_string(prm_.max_newton_iterations) +
        " iterations (merit " + fmt(merit(u, r)) + ")";
  return false;
}

void DcbBeamSolver::commit_history() {
  for (std::size_t i = 1; i <= tip_; ++i)
    if (w_coh_[i] > 0)
      delta_max_[i] = std::max(delta_max_[i], crack_opening(u_, i));
}

double DcbBeamSolver::section_j(const std::vector<double>& u, std::size_t e,
                                std::vector<std::pair<std::size_t, double>>* grad) const {
  // J of a beam section, from the Noether (energy-momentum) invariant of the arm's Lagrangian:
  // T = -(M^2/(2EI) + Q^2/(2S) + Q theta) + interface energy is constant wherever the interface
  // does not change its law, so J(x) = (2/B)(M^2/(2EI) + Q^2/(2S) + Q theta) for both arms is
  // J_tip + int_0^delta sigma behind the tip (Eq. 1) and the foundation energy at the tip.
  // An element carries no interface load inside, so its J is one number; it is evaluated at
  // the left end, where the exact element's end forces are (F1, C1) = -(Q, M).
  const std::size_t d = 2 * e;
  const auto& K = element_K_[e];
  double f[2] = {0, 0};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 4; ++j)
      f[i] += K[4 * i + j] * u[d + j];
  const double Q = -f[0], M = -f[1], theta = u[d + 1];
  const double c = 2 / arm_.width;
  if (grad)
    for (int j = 0; j < 4; ++j)
      grad->emplace_back(
          d + j, c * (-M / arm_.EI * K[4 + j] - (Q / arm_.S + theta) * K[j] + (j == 1 ? Q : 0.0)));
  return c * (M * M / (2 * arm_.EI) + Q * Q / (2 * arm_.S) + Q * theta);
}

double DcbBeamSolver::tip_j(const std::vector<double>& u,
                            std::vector<std::pair<std::size_t, double>>* grad) const {
  // The element just behind the tip has J = J_tip + (bridging potential at its middle) by the
  // invariant (for the initial tip that element is the free notch). The contour closes through
  // the ligament, where J - k delta^2/2 is constant and equals -k delta_L^2/2 at the free far
  // end (M = Q = 0): that term vanishes on a long ligament and matters on a short one.
  const std::size_t e = tip_ - 1;
  double j = section_j(u, e, grad);
  // Bridging potential per area at a node: int_0^delta sigma for an opening crack, the contact
  // energy when closed, and sigma(0+) delta at the tip node, which carries that force.
  auto potential = [&](std::size_t i, double& slope) {
    const double d = crack_opening(u, i);
    if (i == tip_) {
      slope = law_->envelope(0.0);
      return slope * d;
    }
    if (d <= 0) {
      slope = contact_stiffness_ * d;
      return 0.5 * contact_stiffness_ * d * d;
    }
    const double dc = law_->critical_opening();
    slope = d < dc ? law_->envelope(d) : 0.0;
    return law_->envelope_integral(std::min(d, dc));
  };
  for (std::size_t i : {e, e + 1}) {
    if (!(w_coh_[i] > 0))
      continue;
    double slope = 0;
    j -= 0.5 * potential(i, slope);
    if (grad)
      grad->emplace_back(2 * i, -0.5 * 2 * slope);
  }
  const std::size_t wl = n_dofs_ - 2;
  const double delta_end = 2 * u[wl];
  j += 0.5 * arm_.foundation_modulus * delta_end * delta_end;
  if (grad)
    grad->emplace_back(wl, 2 * arm_.foundation_modulus * delta_end);
  return j;
}

RCurvePoint DcbBeamSolver::measure_state() const {
  RCurvePoint p;
  const double B = arm_.width;
  const double dc = law_->critical_opening();
  p.a = x_[tip_];
  p.load = load_;
  p.load_point_opening = 2 * u_[0];
  double free_arm_correction = 0; // elastica minus small-rotation strain energy, one arm [J]
  if (prm_.finite_rotations) {
    double linear_energy = 0;
    const ElasticaState arm = finite_free_arm(p.load, linear_energy);
    p.load_point_opening = 2 * (u_[2 * tip_] - arm.rise);
    free_arm_correction = arm.energy - linear_energy;
  }
  // Notch root: the trailing edge of the zone, where the crack opening has passed delta_c
  // (interpolated between the last failed node and the first bridged one).
  std::size_t f = 0;
  while (f + 1 <= tip_ && delta_max_[f + 1] >= dc && w_coh_[f + 1] > 0)
    ++f;
  if (f == 0)
    p.root = x_[1];
  else if (f >= tip_)
    p.root = x_[tip_];
  else {
    const double d1 = delta_max_[f], d2 = delta_max_[f + 1];
    p.root = x_[f] + (x_[f + 1] - x_[f]) * std::clamp((d1 - dc) / (d1 - d2), 0.0, 1.0);
  }
  p.zone_length = p.a - p.root;
  // delta_root is measured at the original notch root a0, as in the experiment: it keeps
  // growing past delta_c once the root has moved, where Eq. 2 gives G_ss.
  p.delta_root = tip_ > 1 ? crack_opening(u_, 1) : 0.0;
  const double sigma_root = tip_ > 1 ? cohesive(u_, 1).traction : 0.0;
  // J_ff: the contour cuts both arms at the load line (M = 0, Q = -P, so the section J is
  // (2/B)(P^2/(2S) - P theta_0), Paris' formula) and closes through the ligament ahead of the
  // tip, which adds the far-end foundation energy k delta_L^2/2 (see tip_j).
  const double delta_end = 2 * u_[n_dofs_ - 2];
  p.J_ff = section_j(u_, 0) + 0.5 * arm_.foundation_modulus * delta_end * delta_end;
  p.R_J = p.J_ff - 0.5 * p.delta_root * sigma_root;
  p.R_eq2 = law::r_curve_eq2(*law_, j_tip_, p.delta_root);
  // The tip criterion holds the discrete tip J at J_tip; the column reports the other measure
  // of the tip's energy release rate, the foundation energy per area at the tip node
  // (Kanninen's G = k delta_tip^2/2). The two agree to O(h_e^2): 0.23 % at 400 elements.
  const double delta_tip = 2 * u_[2 * tip_];
  p.J_tip = 0.5 * arm_.foundation_modulus * delta_tip * delta_tip;

  double strain = 0;
  for (std::size_t e = 0; e < element_K_.size(); ++e)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        strain += 0.5 * u_[2 * e + i] * element_K_[e][4 * i + j] * u_[2 * e + j];
  double foundation = 0, recoverable = 0, zone_dissipated = 0;
  for (std::size_t i = 1; i < x_.size(); ++i) {
    const double w = u_[2 * i];
    foundation += 0.5 * arm_.k_w() * w_found_[i] * w * w;
    if (w_coh_[i] > 0) {
      const double dcr = crack_opening(u_, i);
      const auto c = cohesive(u_, i);
      recoverable += B * w_coh_[i] * 0.5 * c.traction * dcr; // contact: k dcr^2/2 as well
      const double dm = std::min(delta_max_[i], dc);
      const double sm = delta_max_[i] >= dc ? 0.0 : law_->envelope(dm);
      zone_dissipated += B * w_coh_[i] * (law_->envelope_integral(dm) - 0.5 * sm * dm);
    }
  }
  // Both arms: strain and foundation energy are per arm above; the interface terms are already
  // for the whole interface (traction times opening).
  p.strain_energy = 2 * (strain + free_arm_correction + foundation);
  p.zone_recoverable = recoverable;
  p.dissipated = j_tip_ * B * (p.a - specimen_.initial_crack) + zone_dissipated;
  return p;
}

ElasticaState DcbBeamSolver::finite_free_arm(double& load, double& linear_energy) const {
  // Statics of the free body [0, x_tip] of the small-rotation state: the load and the bridging
  // forces of the nodes behind the tip give the tip moment M and vertical resultant V; the tip
  // node's own lumped force has no lever arm. At finite rotation the load's lever arm shortens,
  // so a larger load is needed. The intact ligament stays linear: its tip deflection, which
  // sets the tip J (k delta_tip^2/2), is w_M M + w_Q Q with Q = -V (semi-infinite end
  // flexibility), so the finite state keeps w_M M - w_Q V, and its tip rotation follows
  // t_M M - t_Q V. The load is found by a secant on the elastica's root moment.
  const double B = arm_.width, l = x_[tip_];
  std::vector<ArmPointLoad> loads;
  double moment = load_ * l;
  for (std::size_t i = 1; i < tip_; ++i)
    if (w_coh_[i] > 0) {
      const double f = -B * w_coh_[i] * cohesive(u_, i).traction;
      loads.push_back({x_[i], f});
      moment += f * (l - x_[i]);
    }
  linear_energy = 0;
  for (std::size_t e = 0; e < tip_; ++e)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        linear_energy += 0.5 * u_[2 * e + i] * element_K_[e][4 * i + j] * u_[2 * e + j];
  const EndFlexibility fl = semi_infinite_end_flexibility(arm_);
  const double theta_tip = u_[2 * tip_ + 1];
  ElasticaState arm;
  // Root moment mismatch at load P; 400 Runge-Kutta steps over the arm keep the fourth-order
  // error below 1e-10 of the load for a DCB arm's rotations (tests/beam, Elastica* use 2000).
  auto mismatch = [&](double P) {
    const double dM = fl.w_Q / fl.w_M * (P - load_);
    const double theta_root = theta_tip + fl.t_M * dM - fl.t_Q * (P - load_);
    arm = free_arm_elastica(arm_.EI, arm_.S, l, theta_root, P, loads, 400);
    return arm.root_moment - (moment + dM);
  };
  double p0 = load_, f0 = mismatch(p0), p1 = load_ * (1 + 1e-3);
  const double scale = std::abs(moment);
  for (int it = 0; it < 60; ++it) {
    const double f1 = mismatch(p1);
    if (std::abs(f1) <= 1e-12 * scale) {
      load = p1;
      return arm;
    }
    if (f1 == f0)
      break;
    const double p2 = p1 - f1 * (p1 - p0) / (f1 - f0);
    p0 = p1;
    f0 = f1;
    p1 = p2;
  }
  throw ComputationError("Beam/Kinematics = finite: no load gives the tip moment " + fmt(moment) +
                         " N m on the rotated free arm at a = " + fmt(l / mm) + " mm");
}

SimulationResult DcbBeamSolver::run() {
  const auto start = std::chrono::steady_clock::now();
  SimulationResult result;
  result.model = "beam";
  result.n_dofs_or_particles = static_cast<long>(element_K_.size());
  // A rigid law acts as given from sigma(0+) at the tip node: the one rule of every model.
  law::note_rigid_law_insertion(*law_, result.notes);
  for (const auto& note : prm_.deprecation_notes)
    result.notes.push_back(note);
  const double a0 = specimen_.initial_crack, L = specimen_.length;
  const double dc = law_->critical_opening();
  const double h_e = length_[1];
  const std::size_t step = std::max<std::size_t>(1, std::lround(prm_.tip_advance / h_e));
  const std::size_t last_node = x_.size() - 1;

  double work = 0;
  result::SteadyStateRule rule; // the shared rule (result::find_steady_state), Beam section's keys
  rule.window = prm_.steady_state_window;
  rule.tolerance = prm_.plateau_tolerance;
  rule.root_move = 1e-12 * L;
  const bool bridging = dc > 0;
  result::SteadyState steady;
  std::size_t move_index = 0; // first state whose root has moved
  bool moved = false;
  std::string stop_reason;
  bool ligament_ran_out = false;
  int foundation_criterion_used = 0;
  double worst_ratio = 0, worst_a = 0, worst_load_error = 0;

  std::size_t tip = 1;
  for (int advance = 0;; ++advance) {
    set_tip(tip);
    // The J condition is quadratic in u (zero gradient at u = 0): the first state, and any
    // state where Newton fails from the previous one, starts from the linear opening condition.
    // If the J condition still fails from there (a zone too short for the mesh makes it
    // nonsmooth), the opening state stands: k delta_tip^2/2 = J_tip, O(h_e^2) from it, noted.
    std::string why;
    bool solved = !result.rcurve.empty() && solve_at_tip(tip, TipCondition::j_integral, why);
    if (!solved && solve_at_tip(tip, TipCondition::opening, why)) {
      solved = true;
      if (!solve_at_tip(tip, TipCondition::j_integral, why))
        ++foundation_criterion_used;
    }
    if (!solved) {
      stop_reason = "stopped at a = " + fmt(x_[tip] / mm) + " mm: " + why;
      break;
    }
    commit_history();
    RCurvePoint p = measure_state();
    // External work along the traced equilibrium path (trapezoid between states; the loading
    // up to initiation is linear, no zone yet, so W = P Delta/2 there exactly).
    if (result.rcurve.empty())
      work = 0.5 * p.load * p.load_point_opening;
    else {
      const auto& q = result.rcurve.back();
      work += 0.5 * (p.load + q.load) * (p.load_point_opening - q.load_point_opening);
    }
    p.external_work = work;
    result::check_rcurve_point(p); // NaN/Inf ends the run naming the column
    result.rcurve.push_back(p);
    // Small rotations: measure the load error against the elastica at the state of largest
    // opening per crack length (under a tenth the error is about 0.15 % or less,
    // docs/verification.md, so those states are not checked).
    const double ratio = p.load_point_opening / p.a;
    if (!prm_.finite_rotations && ratio > 0.1 && ratio > worst_ratio) {
      double finite_load = 0, unused = 0;
      // The check must not end a small-rotation run: a failed elastica only skips the note.
      try {
        finite_free_arm(finite_load, unused);
        worst_ratio = ratio;
        worst_a = p.a;
        worst_load_error = p.load / finite_load - 1;
      } catch (const ComputationError&) {
      }
    }

    if (!moved && p.root > a0 + 1e-12 * L) {
      moved = true;
      move_index = result.rcurve.size() - 1;
      say("beam: notch root moves at a = " + fmt(p.a / mm) + " mm (delta_root " +
          fmt(p.delta_root / mm) + " mm, zone " + fmt(p.zone_length / mm) + " mm)");
    }
    if (advance % 40 == 0)
      say("beam: a = " + fmt(p.a / mm) + " mm, load " + fmt(p.load) + " N, delta_root " +
          fmt(p.delta_root / mm) + " mm");

    if (!steady.reached) {
      steady = result::find_steady_state(result.rcurve, a0, arm_.width, bridging, rule);
      if (steady.reached && !(prm_.final_crack_length > 0))
        break;
    }
    if (prm_.final_crack_length > 0 && x_[tip] >= prm_.final_crack_length)
      break;
    if (tip + step > last_node || L - x_[tip + step] < prm_.minimum_ligament) {
      ligament_ran_out = true;
      stop_reason = "the ligament ran out: the tip reached a = " + fmt(x_[tip] / mm) +
                    " mm, and the minimum ligament is " + fmt(prm_.minimum_ligament / mm) + " mm";
      break;
    }
    if (advance + 1 >= prm_.max_advances) {
      stop_reason = "stopped after max_advances = " + std::to_string(prm_.max_advances);
      break;
    }
    tip += step;
  }
  if (result.rcurve.empty())
    throw ComputationError("Beam: no equilibrium at initiation (a = " +
                           fmt(specimen_.initial_crack / mm) + " mm): " + stop_reason);
  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!stop_reason.empty())
    note(result, stop_reason);
  // The bound where small rotations stop being good enough: 1 % load error against the
  // elastica (docs/verification.md, "Finite rotations of the beam arms").
  if (std::abs(worst_load_error) > 0.01)
    note(result, "small rotations: at a = " + fmt(worst_a / mm) + " mm the load-point opening is " +
                     fmt(worst_ratio, 3) + " of the crack length and the load is " +
                     fmt(100 * worst_load_error, 3) +
                     " % off the finite-rotation (elastica) load, past the 1 % bound; set "
                     "Beam/Kinematics = finite");
  if (foundation_criterion_used > 0)
    note(result, "at " + std::to_string(foundation_criterion_used) +
                     " advances Newton on the tip-J criterion did not converge and the foundation "
                     "criterion k delta_tip^2/2 = J_tip was used (the two differ by O(h_e^2))");
  // A zone shorter than a few elements is not resolved: the tip node's lumped sigma(0+) and
  // nodes that jump past delta_c in one advance then misplace the zone's work, and R_energy and
  // the energy balance go wrong by the size of J_c. That is a diagnosis, not a result.
  double shortest_zone = std::numeric_limits<double>::infinity();
  if (moved && law_->area() > 0)
    for (std::size_t k = move_index; k < result.rcurve.size(); ++k)
      shortest_zone = std::min(shortest_zone, result.rcurve[k].zone_length);
  const double step_length = static_cast<double>(step) * h_e;
  if (!steady.reached)
    steady = result::find_steady_state(result.rcurve, a0, arm_.width, bridging, rule);
  if (shortest_zone < 4 * step_length) {
    result.reached_steady_state = false;
    result.steady_state_status = result::SteadyStateStatus::zone_unresolved;
    result.G_ss = result::not_available;
    const double wanted =
        std::ceil(8 * h_e / std::max(shortest_zone, 0.01 * h_e) * prm_.n_elements);
    note(result, "unresolved bridging zone: after the root moved the zone is only " +
                     fmt(shortest_zone / mm) + " mm long, under 4 tip advances of " +
                     fmt(step_length / mm) + " mm; G_ss is not reported. Use about " +
                     fmt(wanted, 2) + " elements or more and a tip advance of at most " +
                     fmt(shortest_zone / 8 / mm, 2) + " mm (Beam section).");
  } else {
    result::report_steady_state(result, steady, rule, "Beam");
  }
  if (!steady.reached && shortest_zone >= 4 * step_length) {
    const auto& last = result.rcurve.back();
    if (!moved && !ligament_ran_out)
      note(result, "no steady state before the stop: the notch root had not moved (delta_root = " +
                       fmt(last.delta_root / mm) + " mm < delta_c = " + fmt(dc / mm) + " mm)");
    else if (!moved)
      note(result, "no steady state: the bridging zone is longer than the ligament allows; at "
                   "a = " +
                       fmt(last.a / mm) + " mm the notch root opening delta_root = " +
                       fmt(last.delta_root / mm) + " mm is still below delta_c = " + fmt(dc / mm) +
                       " mm (zone " + fmt(last.zone_length / mm) +
                       " mm). A longer specimen is needed to reach G_ss.");
    else if (ligament_ran_out)
      note(result, "the ligament ran out before R_J settled: the zone is too long for this "
                   "specimen to grow it to a plateau");
  }
  finish(result);
  return result;
}

void DcbBeamSolver::finish(SimulationResult& result) {
  auto& rc = result.rcurve;
  result::fill_r_energy(rc, arm_.width); // d(W - U_rec)/(B da), the shared stencil
  // Unstable growth under displacement control: the states where the load-point opening is
  // below an earlier one would be passed in one jump of a displacement-controlled test.
  const auto snap_backs = result::find_snap_backs(rc);
  std::size_t unstable = 0;
  for (const auto& s : snap_backs)
    unstable += s.to - s.from - 1;
  const double first_a = unstable > 0 ? rc[snap_backs.front().from + 1].a : result::not_available;
  const double last_a = unstable > 0 ? rc[snap_backs.back().to - 1].a : result::not_available;
  if (unstable > 0)
    note(result, "snap-back: " + std::to_string(unstable) + " recorded advances between a = " +
                     fmt(first_a / mm) + " and " + fmt(last_a / mm) +
                     " mm have a load-point opening below an earlier one; a displacement-"
                     "controlled test grows the crack there unstably (several advances in one "
                     "load step). The curve is the equilibrium path under crack-length control.");
  result.method.push_back(
      "beam model: Timoshenko arms (kappa " + fmt(prm_.shear_coefficient) + "), " +
      std::to_string(prm_.n_elements) + " elements on the ligament, tip advance " +
      fmt(rc.size() > 1 ? (rc[1].a - rc[0].a) / mm : 0) + " mm; Winkler foundation k = " +
      fmt(arm_.foundation_modulus * 1e-9) + " GPa/m on the opening (" +
      (prm_.foundation_modulus > 0
           ? std::string("given")
           : "calibrated to CBT root rotation chi h = " +
                 fmt(specimen::cbt_chi(material_) * specimen_.arm_thickness() / mm) + " mm") +
      "; 2 E_T/h = " + fmt(2 * material_.E_T / specimen_.arm_thickness() * 1e-9) +
      " GPa/m); the law acts on the opening beyond delta_0 = sqrt(2 J_tip/k) = " +
      fmt(delta_0_ / mm) + " mm");
  result.method.push_back(
      "R_energy: d(W - U_rec)/(B da), central differences over the recorded states; "
      "J_ff: section J at the load line (2/B)(P^2/(2S) - P theta_0) plus the far-end "
      "foundation energy; the tip advances when the section J just behind the tip, less "
      "the bridging potential there (the discrete tip J), reaches J_tip; the J_tip "
      "column is the foundation energy k delta_tip^2/2 at the tip node; strain_energy: "
      "both arms plus the foundation (the ligament's "
      "through-thickness energy); kinetic_energy, time: not available (static model)");
  if (prm_.finite_rotations)
    result.method.push_back(
        "finite rotations (Beam/Kinematics = finite): load and load-point opening from the "
        "shearable elastica of the free arm (load line to tip) under the small-rotation "
        "bridging forces, at the load that keeps the ligament's tip deflection (tip J); strain "
        "energy with the elastica's free arm; the ligament, the bridging openings, R_J and J_ff "
        "are those of the small-rotation state");
  if (!material_.plane_stress)
    note(result, "plane strain: the arms bend with E_L/(1 - nu_LT nu_TL)");
  result.rdelta_rel_error_vs_eq2 = result::rdelta_error_vs_eq2(result, *law_, j_tip_);
  say("beam: " + std::to_string(rc.size()) + " states in " + fmt(result.wall_time_s) + " s" +
      (result.reached_steady_state ? ", G_ss = " + fmt(result.G_ss) + " J/m^2"
                                   : ", no steady state"));
}

} // namespace

result::SimulationResult simulate_dcb(const specimen::Specimen& specimen,
                                      const specimen::Material& material,
                                      const law::TractionLaw& law, double j_tip,
                                      const BeamParameters& parameters,
                                      const std::function<void(const std::string&)>& progress) {
  fiberbridge::begin_fault_context("beam");
  DcbBeamSolver solver(specimen, material, law, j_tip, parameters, progress);
  return solver.run();
}

} // namespace fiberbridge::beam
