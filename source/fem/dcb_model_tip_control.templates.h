#pragma once
// DcbModel<dim>'s crack-tip opening control (docs/design.md section 2, "Crack-tip opening
// control"): where the load-point opening cannot hold the state after a release (a strong short
// law), the opening of the crack-plane node next behind the tip is prescribed and the load-point
// opening becomes an unknown of a bordered Newton (two solves on one factorization per
// iteration). Split from dcb_model.templates.h at its seam (issue 30 item 7); included there, so
// the explicit instantiations in dcb_model_2d.cc and dcb_model_3d.cc cover it.
#include "dcb_model.h"
#include "newton_loop.h"
#include "root_j_secant.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/result/numerical_fault.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace fiberbridge::fem {

using namespace dealii;

template <int dim>
void DcbModel<dim>::switch_to_tip_control(const std::string& failure) {
  tip_control_ = true;
  tip_control_reason_ = "at a = " + fmt(crack_.x_tip() / units::mm) + " mm: " + failure;
  const std::string why = failure.substr(0, failure.find(". Try")); // the diagnosis, no advice
  result_.notes.push_back(
      "control: at a = " + fmt(crack_.x_tip() / units::mm) +
      " mm the load-point opening could not hold the state after a release (" + why +
      "); from there on the run prescribes the opening of the crack-plane node next behind the "
      "tip, with the load-point opening an unknown (crack-tip opening control)");
  result_.method.push_back(
      "control: crack-tip opening control from a = " + fmt(crack_.x_tip() / units::mm) +
      " mm: bordered Newton (two solves with one factorization per iteration), the opening of "
      "the node next behind the tip found by a secant on sqrt(tip J)");
}

template <int dim>
void DcbModel<dim>::fail_under_tip_control(const std::string& what) const {
  // The diagnosis keeps the failure of the load-point opening that made the run switch.
  throw ComputationError("FEM: the crack-tip opening control failed: " + what +
                         ". It took over from the load-point opening control " +
                         tip_control_reason_);
}

template <int dim>
double DcbModel<dim>::control_opening() {
  Vec c(owned_, comm_);
  crack_.station_opening_operator(control_station(), width_, owned_, c);
  return c * u_;
}

template <int dim>
bool DcbModel<dim>::load_to_critical_at_tip() {
  // The secant of load_to_critical_by_opening() (root_j_secant.h), in the controlled opening
  // eta: unlike the load-point opening it grows monotonically while the fresh segment softens.
  const double eta0 = control_opening();
  double J = 0;            // right after a release the state has no tip J of its own
  if (!release_pending_) { // an equilibrium state: its tip J is a sample
    J = timed_tip_j();
    if (J >= (1 - prm_.nonlinear.tip_tolerance) * j_tip_) {
      if (J > (1 + prm_.nonlinear.tip_tolerance) * j_tip_)
        ++n_unstable_;
      return false;
    }
  }
  RootJSecant search(j_tip_, eta0, J);
  // At criticality the field next to the tip repeats from advance to advance.
  double next = last_control_opening_ > eta0 ? last_control_opening_ : 2 * eta0;
  for (int it = 0; it < 40; ++it) {
    next = search.safeguard(next, 1e-3 * last_control_opening_);
    solve_at_tip_opening(next);
    ++n_trials_;
    J = timed_tip_j();
    if (release_pending_)
      account_release();
    path_.push_back({next, opening_, load_per_width()});
    min_opening_since_record_ = std::min(min_opening_since_record_, opening_);
    if (std::abs(J / j_tip_ - 1) <= prm_.nonlinear.tip_tolerance) {
      if (!result_.rcurve.empty() &&
          min_opening_since_record_ < result_.rcurve.back().load_point_opening)
        ++n_turned_back_;
      return true;
    }
    next = search.add(next, J);
  }
  fail_under_tip_control("could not bring the tip J to J_tip = " + fmt(j_tip_) +
                         " J/m^2 with the tip at " + fmt(crack_.x_tip() / units::mm) +
                         " mm (last J " + fmt(J) + ")");
}

template <int dim>
void DcbModel<dim>::account_release() {
  // What the release step freed: the drop of stored energy plus the work of the load on it (a
  // trapezoid between the state before the release and the first traced state).
  tip_dissipated_ += release_stored_ - stored_energy() +
                     0.5 * (release_load_ + load_per_width()) * (opening_ - release_opening_);
  j_after_release_ = timed_tip_j();
  release_pending_ = false;
}

template <int dim>
void DcbModel<dim>::solve_at_tip_opening(double eta) {
  const Vec u0 = u_;
  const double opening0 = opening_;
  Vec c(owned_, comm_), e(owned_, comm_);
  crack_.station_opening_operator(control_station(), width_, owned_, c);
  {
    // The change of the prescribed values per unit load-point opening.
    AffineConstraints<double> unit;
    make_constraints(1.0, unit);
    unit.distribute(e);
  }
  const double eta0 = c * u_;
  std::string diagnosis;
  for (unsigned attempt = 0, n = 1; attempt < 6; ++attempt, n *= 2) {
    u_ = u0;
    opening_ = opening0;
    bool ok = true;
    for (unsigned i = 1; i <= n && ok; ++i)
      ok = bordered_newton(c, e, eta0 + (eta - eta0) * double(i) / n, diagnosis);
    if (ok) {
      sync();
      return;
    }
  }
  fail_under_tip_control("no equilibrium at the crack-tip opening " + fmt(eta / units::mm) +
                         " mm with the tip at " + fmt(crack_.x_tip() / units::mm) +
                         " mm (32 sub-steps): " + diagnosis);
}

template <int dim>
bool DcbModel<dim>::bordered_newton(const Vec& c, const Vec& e, double eta,
                                    std::string& diagnosis) {
  // Unknowns u and the load-point opening D; equations r(u, D) = 0 and c . u = eta. Per
  // iteration two solves with one Jacobian: J du1 = -r, J du2 = -dr/dD, then D moves by what
  // the linearized constraint asks. dr/dD by a difference along the prescribed values (exact
  // for the linear bulk up to round-off). The iteration is the one Newton loop's
  // (newton_loop.h); its merit holds the residual and the constraint gap in force units.
  struct Bordered {
    Bordered(DcbModel& model, const Vec& constraint, const Vec& prescribed, double target)
        : m(model), c(constraint), e(prescribed), eta(target),
          tolerance(m.prm_.nonlinear.newton_tolerance),
          gap_tol(1e-9 * std::abs(target) + 1e-15 * m.specimen_.length) {
      for (Vec* v : {&r, &rf, &rd, &du1, &du2, &step, &rhs, &tried, &rt})
        m.reinit_vector(*v);
      m.residual(m.u_, r, rf);
      ref = m.reaction_norm(rf);
      nrm = m.norm(r);
    }
    DcbModel& m;
    const Vec& c;
    const Vec& e;
    const double eta, tolerance, gap_tol;
    Vec r, rf, rd, du1, du2, step, rhs, tried, rt;
    double ref = 0, nrm = 0, gap = 0, dD = 0, w = 0, best_ref = 0;

    double merit_of(double rn, double g) const { return std::sqrt(rn * rn + w * w * g * g); }
    bool converged() {
      gap = c * m.u_ - eta;
      return std::abs(gap) <= gap_tol && nrm <= tolerance * ref;
    }
    void direction() {
      m.setup_jacobian(m.u_);
      rhs = r;
      rhs *= -1.0;
      m.solve_jacobian(rhs, du1);
      const double h = 1e-4 * std::max(std::abs(m.opening_), 1e-6 * m.specimen_.length);
      tried = m.u_;
      tried.add(h, e);
      m.residual(tried, rd, rf);
      rd -= r;
      rd *= -1.0 / h;
      m.solve_jacobian(rd, du2);
      du2 += e; // du/dD along the equilibrium at fixed eta's linearization
      dD = -(gap + c * du1) / (c * du2);
      step = du1;
      step.add(dD, du2);
      // The force per unit eta weighs the gap.
      w = m.norm(rd) / std::max(std::abs(c * du2), 1e-300);
    }
    double merit() const { return merit_of(nrm, gap); }
    double trial(double alpha) {
      tried = m.u_;
      tried.add(alpha, step);
      m.residual(tried, rt, rf);
      return merit_of(m.norm(rt), c * tried - eta);
    }
    void keep_trial(bool /*search goes on*/) { best_ref = m.reaction_norm(rf); }
    bool accept(double alpha, bool /*last*/) {
      m.u_.add(alpha, step);
      m.opening_ += alpha * dD;
      m.residual(m.u_, r, rf);
      ref = best_ref;
      const double before = nrm;
      nrm = m.norm(r);
      m.note_contraction(nrm / std::max(before, 1e-300));
      return false;
    }
    bool at_floor_and_on_constraint() const {
      return nrm <= m.roundoff_floor(m.u_) && std::abs(c * m.u_ - eta) <= gap_tol;
    }
  } newton(*this, c, e, eta);
  const unsigned max_iterations = prm_.nonlinear.max_newton_iterations;
  const NewtonStop stop = newton_loop(newton, max_iterations, info_.n_newton);
  if (stop == NewtonStop::converged || newton.at_floor_and_on_constraint())
    return true;
  if (stop == NewtonStop::no_decrease)
    diagnosis = "line search found no decrease of the residual " + fmt(newton.nrm) + " N" +
                contact_summary();
  else
    diagnosis = "no convergence in " + std::to_string(max_iterations) +
                " bordered Newton iterations (residual " + fmt(newton.nrm / newton.ref) +
                " of the reaction)" + contact_summary();
  return false;
}

template <int dim>
void DcbModel<dim>::note_snap_back() {
  // Where the recorded load-point opening falls below an earlier one, a test under load-point
  // opening control cannot follow: it jumps at the earlier maximum to the first later state with
  // that opening (or runs out of the traced curve).
  const auto& rc = result_.rcurve;
  for (const auto& [i, low, j] : result::find_snap_backs(rc)) {
    std::ostringstream m;
    m << "snap-back: the load-point opening falls from " << rc[i].load_point_opening / units::mm
      << " mm (a = " << rc[i].a / units::mm << " mm, load " << rc[i].load << " N) to "
      << rc[low].load_point_opening / units::mm << " mm (a = " << rc[low].a / units::mm
      << " mm, load " << rc[low].load << " N); a test under load-point opening control would "
      << "jump at " << rc[i].load_point_opening / units::mm
      << " mm from a = " << rc[i].a / units::mm << " mm";
    if (j < rc.size())
      m << " to about a = " << rc[j].a / units::mm << " mm (load " << rc[i].load << " -> "
        << rc[j].load << " N)";
    else
      m << " past the end of the traced curve";
    result_.notes.push_back(m.str());
  }
  if (n_turned_back_ > 0)
    result_.notes.push_back(
        "snap-back within advances: " + std::to_string(n_turned_back_) +
        " advances traced a load-point opening below the previous record's (the fresh segment "
        "softens faster than the structure unloads; a test under load-point opening control "
        "jumps there by up to one element of growth)");
}

} // namespace fiberbridge::fem
