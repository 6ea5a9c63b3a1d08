#include "fiberbridge/mpm/dcb.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/output_guard.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/rigid_law.h"
#include "fiberbridge/mpm/checkpoint.h"
#include "fiberbridge/mpm/crack.h"
#include "fiberbridge/mpm/explicit_solver.h"
#include "fiberbridge/mpm/j_integral.h"
#include "fiberbridge/mpm/vtu_writer.h"
#include "fiberbridge/result/numerical_fault.h"
#include "fiberbridge/result/rcurve.h"
#include "fiberbridge/result/steady_state.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <sstream>

namespace fiberbridge::mpm {

double arm_vibration_period(const specimen::Specimen& s, const specimen::Material& m, double a) {
  const double h = s.arm_thickness();
  const double I = s.width * h * h * h / 12;
  return 1.787 * a * a * std::sqrt(m.density * s.width * h / (m.E_L * I));
}

namespace {

using units::mm;

} // namespace

void check_dcb_inputs(const specimen::Specimen& s, const specimen::Material& m,
                      const MpmParameters& p, const law::TractionLaw* law) {
  p.validate();
  s.validate();
  m.validate();
  const double c = p.cell_size, h = s.arm_thickness(), L = s.length;
  if (h < 2 * c)
    throw InputError("MPM/Cell size: " + fmt(c / mm) +
                     " mm leaves fewer than 2 cells through an arm of " + fmt(h / mm) +
                     " mm; use at most " + fmt(h / 2 / mm) + " mm");
  // As DcbModel::setup_body places them: the tip on the node column nearest to the sawn crack's
  // end, the last tip position one minimum ligament before the far end.
  const double ligament = p.end_ligament > 0 ? p.end_ligament : s.height;
  const double a0 = std::round(s.initial_crack / c) * c;
  if (!(L - ligament > a0 + 2 * c))
    throw InputError("MPM/Minimum ligament: the tip could not grow: initial crack " +
                     fmt(s.initial_crack / mm) + " mm + ligament " + fmt(ligament / mm) +
                     " mm leave no room in a " + fmt(L / mm) + " mm specimen");
  // Rigid laws need no check here: they are inserted as given (law/rigid_law.h).
  (void)law;
}

DcbModel::DcbModel(const specimen::Specimen& s, const specimen::Material& m,
                   const law::TractionLaw& law, double j_tip, const MpmParameters& p,
                   const std::string& output_dir,
                   const std::function<void(const std::string&)>& progress)
    : spec_(s), mat_(m), user_law_(law), j_tip_(j_tip), prm_(p), out_dir_(output_dir),
      progress_(progress), elastic_(m) {
  check_dcb_inputs(spec_, mat_, prm_, nullptr); // choose_law() regularizes (and checks) the law
  if (!(j_tip > 0) || !std::isfinite(j_tip))
    throw InputError("Cohesive law/J tip: must be positive (J/m^2), got " + fmt(j_tip));
  choose_law();
  setup_body();
  setup_loading();
}

void DcbModel::choose_law() {
  // The one rule for rigid laws (law::note_rigid_law_insertion, extrinsic insertion): the crack
  // carries the law as given. A fresh segment starts at sigma(0+) with delta_max = 0; its traction
  // is explicit and bounded by the law, so a rigid law needs no elastic rise for the time step (the
  // secant of a segment that closes below its delta_max is bounded the same way).
  law_ = &user_law_;
  law::note_rigid_law_insertion(user_law_, notes_);
  for (const auto& n : prm_.deprecation_notes)
    notes_.push_back(n);
}

void DcbModel::setup_body() {
  const double c = prm_.cell_size;
  const double h = spec_.arm_thickness(), L = spec_.length;
  cell_ = c;
  // check_dcb_inputs() made sure of at least 2 cells through an arm. Under 3 a cantilever bends
  // over 5 % too stiff (the bound tests/mpm, MpmCantilever.BendingNeedsCellsThroughTheThickness,
  // asserts; the measured figures: docs/verification.md, MPM table).
  if (h < 3 * c * (1 - 1e-9))
    notes_.push_back("thin arm: MPM/Cell size " + fmt(c / mm) + " mm gives " + fmt(h / c, 3) +
                     " cells through the " + fmt(h / mm) +
                     " mm arm; under 3 the arms bend over 5 % too stiff (use at most " +
                     fmt(h / 3 / mm) + " mm)");
  const double ligament = prm_.end_ligament > 0 ? prm_.end_ligament : spec_.height;
  end_tip_ = L - ligament;
  // The tip sits on a node column, the fields split up to the column one cell behind it
  // (Crack::splits): the nearest column to the sawn crack's end. Columns lie at multiples of the
  // cell from the load line.
  a0_ = std::round(spec_.initial_crack / c) * c;
  if (std::fabs(a0_ - spec_.initial_crack) > 1e-9 * c)
    notes_.push_back("initial crack tip placed on the nearest node column: " + fmt(a0_ / mm) +
                     " mm instead of " + fmt(spec_.initial_crack / mm) + " mm");
  // check_dcb_inputs() made sure that end_tip_ > a0_ + 2 c (room for the tip to grow).

  const int ppc = prm_.particles_per_cell;
  const int n_arm = std::max(1, static_cast<int>(std::lround(h / c * ppc)));
  const int n_x = std::max(1, static_cast<int>(std::lround(L / c * ppc)));
  Particles particles =
      Particles::rectangle(0.0, -h, L, 2 * h, n_x, 2 * n_arm, mat_.density, spec_.width);

  // Room for the arms to swing open: twice the LEFM opening with the whole steady-state
  // toughness at the last crack length (a bridged DCB opens less than that at the same tip).
  const double G_ss = j_tip_ + law_->area();
  const double P_end = specimen::cbt_load_at_crack_length(spec_, mat_, G_ss, end_tip_);
  opening_allowance_ = 2 * specimen::cbt_opening(spec_, mat_, P_end, end_tip_);
  // The crack plane y = 0 lies in mid-cell, so no node sits on it.
  const int k = static_cast<int>(std::ceil((h + 0.5 * opening_allowance_) / c)) + 3;
  const int nx = static_cast<int>(std::ceil(L / c)) + 5;
  Grid grid(-2 * c, -(k + 0.5) * c, c, nx, 2 * k + 2);

  // Explicit time step: the CFL limit of the bulk, and the limit of the stiffest traction spring.
  // A crack point spreads its force over nodes whose lightest field holds about rho c^2 B / 8;
  // with a spring k_t (Pa/m) over a segment of c/2 this gives omega^2 ~ 4 k_t / (rho c) and
  // dt <= 2/omega = sqrt(rho c / k_t); the same CFL factor applies.
  double dt = prm_.cfl * c / elastic_.max_wave_speed();
  const double kt = law_->initial_stiffness();
  if (kt > 0 && std::isfinite(kt)) {
    const double dt_t = prm_.cfl * std::sqrt(mat_.density * c / kt);
    if (dt_t < dt) {
      notes_.push_back("time step limited by the traction law's initial stiffness: " + fmt(dt_t) +
                       " s instead of " + fmt(dt) + " s");
      dt = dt_t;
    }
  }
  solver_ = std::make_unique<ExplicitSolver>(std::move(grid), std::move(particles), elastic_, dt,
                                             prm_.pic_fraction, spec_.width);
  solver_->set_threads(prm_.threads);
  step_ = prm_.growth_step_cells * c;
  crack_ = std::make_unique<Crack>(-1.5 * c, a0_, 0.5 * c, *law_, c);
  solver_->set_crack(crack_.get());

  // Loading block: the column of nodes on the load line x = 0; each arm's field gets its half of
  // the opening rate in y, x is free (the pins let the arm ends rotate).
  VelocityConstraint top, bottom;
  const Grid& g = solver_->grid();
  for (int j = 0; j < g.ny(); ++j) {
    top.fields.emplace_back(g.node(2, j), above);
    bottom.fields.emplace_back(g.node(2, j), below);
  }
  solver_->constraints() = {top, bottom};
  // Check the tip after a wave has crossed the arm: the field around a new tip has then
  // rearranged, and the tip speed stays below c_wave * step / (h) (far below it).
  n_check_ = std::max(1, static_cast<int>(std::lround(h / elastic_.max_wave_speed() / dt)));
}

void DcbModel::setup_loading() {
  const double a0 = spec_.initial_crack;
  t_vib0_ = arm_vibration_period(spec_, mat_, a0);
  const double P0 = specimen::cbt_load_at_crack_length(spec_, mat_, j_tip_, a0);
  opening0_ = specimen::cbt_opening(spec_, mat_, P0, a0);
  rate_ = opening0_ / (prm_.loading_periods * t_vib0_);
  ramp_time_ = prm_.ramp_periods * t_vib0_;
  // A ramp of a few arm periods or less excites the arms: say so instead of calling it static.
  notes_.push_back(std::string(prm_.loading_periods >= 4
                                   ? "quasi-static loading"
                                   : "FAST loading (dynamic: inertia enters the R curve, see the "
                                     "kinetic energy)") +
                   ": opening rate " + fmt(rate_) + " m/s reaches the LEFM initiation opening " +
                   fmt(opening0_ / mm) + " mm after " + fmt(prm_.loading_periods) +
                   " vibration periods of the a0 arm (t_vib = " + fmt(t_vib0_ * 1e3) +
                   " ms; time step " + fmt(solver_->dt()) + " s, " + fmt(t_vib0_ / solver_->dt()) +
                   " steps per period)");
  if (!out_dir_.empty() && prm_.vtu_every_advances > 0)
    vtu_ = std::make_unique<ParticleVtuWriter>(out_dir_, "mpm_particles");
  growth_ = std::make_unique<GrowthCriterion>(spec_, mat_, j_tip_, prm_.j_window_periods, step_,
                                              n_check_ * solver_->dt());
  set_growth_window();
}

void DcbModel::set_growth_window() {
  growth_->set_window(crack_->tip(), std::max(opening_, opening0_), rate_, !rcurve_.empty());
}

double DcbModel::opening_rate(double t) const {
  // Smooth start (half cosine) so that the arms are not struck.
  if (t < ramp_time_)
    return rate_ * 0.5 * (1 - std::cos(std::acos(-1.0) * t / ramp_time_));
  return rate_;
}

void DcbModel::advance_tip(double j_measured) {
  ExplicitSolver& s = *solver_;
  Crack& crack = *crack_;
  const double B = spec_.width;
  // Crack particles every half cell over the released length, so that a bridging traction is
  // resolved as finely as on the notch.
  const double x_new = crack.tip() + step_;
  const int n_sub = 2 * prm_.growth_step_cells;
  const double x_old = crack.tip();
  for (int k = 1; k <= n_sub; ++k) {
    const double x = x_old + step_ * k / n_sub;
    double ux, uy;
    s.material_displacement(x, 0.0, ux, uy);
    crack.advance(x, ux, uy);
  }

  result::RCurvePoint pt;
  pt.a = x_new;
  pt.J_tip = j_measured;
  pt.time = s.time();
  pt.load = load_;
  pt.load_point_opening = opening_;
  const int k = crack.root_segment();
  if (k >= 0) {
    const CrackParticle& r = crack.particles()[k];
    pt.root = r.X;
    pt.delta_root = std::max(0.0, r.opening());
  } else { // no bridging law: the zone is empty, the root is the tip
    pt.root = x_new;
    pt.delta_root = 0;
  }
  pt.zone_length = pt.a - pt.root;
  pt.J_ff = far_field_j();
  const double sigma_root =
      pt.delta_root < law_->critical_opening() ? law_->envelope(pt.delta_root) : 0.0;
  pt.R_J = pt.J_ff - 0.5 * pt.delta_root * sigma_root;
  pt.R_eq2 = law::r_curve_eq2(user_law_, j_tip_, pt.delta_root);
  pt.external_work = s.external_work();
  pt.strain_energy = s.strain_energy();
  pt.kinetic_energy = s.kinetic_energy();
  pt.zone_recoverable = crack.zone_recoverable(B);
  // An MPM tip has no dissipation of its own: what its advance releases leaves through the
  // explicit update (ExplicitSolver::numerical_loss, mostly within 50 steps of each advance:
  // the unbalanced stress of the cut acts on light node fields at the newly split column) and
  // the PIC damping. Both count as dissipated, beside the zone's share of the law.
  pt.dissipated = crack.zone_dissipated(B) + s.damping_loss() + s.numerical_loss();
  result::check_rcurve_point(pt); // NaN/Inf ends the run naming the column
  rcurve_.push_back(pt);
  if (pt.strain_energy > 0)
    max_kinetic_ratio_ = std::max(max_kinetic_ratio_, pt.kinetic_energy / pt.strain_energy);

  if (crack.max_plane_offset() > 0.25 * cell_)
    throw ComputationError("MPM: the crack surfaces lost their symmetry about the mid-plane (mean "
                           "offset " +
                           fmt(crack.max_plane_offset() / mm) +
                           " mm > a quarter "
                           "cell); the response is no longer a symmetric DCB opening");
  if (progress_)
    progress_("mpm: t " + fmt(pt.time * 1e3) + " ms, a " + fmt(pt.a / mm) + " mm, root " +
              fmt(pt.root / mm) + " mm, delta_root " + fmt(pt.delta_root / mm) + " mm, load " +
              fmt(pt.load) + " N, J_tip " + fmt(j_measured) + ", J_ff " + fmt(pt.J_ff) +
              " J/m^2, KE/U " + fmt(pt.kinetic_energy / pt.strain_energy, 3));
  if (vtu_ && rcurve_.size() % prm_.vtu_every_advances == 0)
    vtu_->write(s);
}

bool DcbModel::step(bool grow) {
  ExplicitSolver& s = *solver_;
  if (s.steps() >= prm_.max_steps) {
    stop_reason_ = "step limit (MPM/Maximum steps) reached";
    return false;
  }
  VelocityConstraint& top = s.constraints()[0];
  VelocityConstraint& bottom = s.constraints()[1];
  const double v = opening_rate(s.time() + 0.5 * s.dt());
  top.velocity = 0.5 * v;
  bottom.velocity = -0.5 * v;
  s.step();
  opening_ += v * s.dt();
  // The reaction of a velocity constraint rings with waves across the arm; the load is its
  // exponential moving average over a twentieth of the arm period, which lags the quasi-static
  // load by about 0.05 t_vib / (loading_periods t_vib) < 0.5 %.
  const double reaction = 0.5 * (top.reaction - bottom.reaction);
  const double alpha = std::min(1.0, s.dt() / (0.05 * t_vib0_));
  load_ += alpha * (reaction - load_);
  if (opening_ > opening_allowance_) {
    stop_reason_ = "the load-line opening reached the grid's allowance of " +
                   fmt(opening_allowance_ / mm) + " mm";
    return false;
  }
  if (!grow || s.steps() % n_check_ != 0)
    return true;
  const double J_now = tip_j();
  if (!std::isfinite(J_now))
    throw ComputationError("MPM: the tip J integral is not finite at t = " + fmt(s.time()) +
                           " s; the run became unstable");
  double J = 0;
  if (!growth_->advance_due(J_now, J))
    return true;
  if (crack_->tip() + step_ > end_tip_) {
    stop_reason_ =
        "the tip reached the end ligament (" + fmt((spec_.length - end_tip_) / mm) + " mm)";
    return false;
  }
  advance_tip(J);
  set_growth_window();
  const int k = crack_->root_segment();
  if (prm_.steady_growth > 0 && k >= 0 && crack_->particles()[k].X - a0_ >= prm_.steady_growth) {
    stop_reason_ = "the notch root moved by the requested steady growth";
    return false;
  }
  return true;
}

double DcbModel::tip_j() const {
  // The contour frame runs from tip_j_cells to tip_j_cells + 2 cells around the tip.
  return tip_j_integral(*solver_, *crack_, prm_.tip_j_cells * cell_,
                        (prm_.tip_j_cells + 2) * cell_);
}

double DcbModel::far_field_j() const {
  // Strips two cells wide. The left one lies halfway between the load line and the initial
  // crack tip: behind any notch root and clear of the loading block. The right one lies halfway
  // between the tip's J domain and the far end (uncracked ligament).
  const double w = 2 * cell_;
  const double x_left = 0.5 * spec_.initial_crack;
  const double x_right = 0.5 * (crack_->tip() + (prm_.tip_j_cells + 2) * cell_ + spec_.length);
  if (!(x_left - 0.5 * w > 1.5 * cell_ && x_right + 0.5 * w < spec_.length))
    return result::not_available;
  return far_field_j_integral(*solver_, x_left, x_right, w);
}

const ExplicitSolver& DcbModel::solver() const {
  return *solver_;
}
const Crack& DcbModel::crack() const {
  return *crack_;
}

result::SimulationResult DcbModel::run() {
  session_start_ = std::chrono::steady_clock::now();
  running_ = true;
  // Checkpoints (mpm/checkpoint.h): continue from one when asked to; a fresh run removes a
  // stale one so that a later --resume cannot pick up another run's state.
  bool resumed = resumed_;
  if (!resumed && prm_.resume)
    resumed = resume_from_checkpoint();
  else if (!resumed && !out_dir_.empty() && output_enabled()) {
    std::error_code ec;
    std::filesystem::remove(checkpoint_path(out_dir_), ec);
  }
  const ExplicitSolver& s = *solver_;
  if (vtu_ && !resumed)
    vtu_->write(s);
  const bool checkpoints = !out_dir_.empty() && prm_.checkpoint_interval > 0 && output_enabled();
  auto last_checkpoint = std::chrono::steady_clock::now();
  while (step(true)) {
    if (checkpoints &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - last_checkpoint).count() >=
            prm_.checkpoint_interval) {
      write_checkpoint();
      last_checkpoint = std::chrono::steady_clock::now();
    }
  }
  if (vtu_ && (rcurve_.empty() || rcurve_.size() % prm_.vtu_every_advances != 0))
    vtu_->write(s);

  result::SimulationResult r;
  r.model = "mpm";
  r.rcurve = rcurve_;
  r.n_dofs_or_particles = static_cast<long>(s.particles().size());
  r.notes = notes_;
  r.notes.push_back("stopped: " + stop_reason_ + " after " + std::to_string(s.steps()) +
                    " steps, " + fmt(s.time() * 1e3) + " ms");
  finish(r);
  // The zone must span cells as it must span elements in the FEM (issue 13 item 6): one rule.
  // The MPM's zone reading (tip - root) is never under about two cells: the tip advances a whole
  // cell and its cell is only partly split, so the root lags (the measured case:
  // docs/verification.md, "Strong short laws", the MPM on the case).
  constexpr double root_reading_cells = 2;
  result::note_zone_resolution(r, cell_, "cells", "MPM/Cell size", root_reading_cells);
  // Every session's wall time: a resumed run reports what the whole run cost.
  r.wall_time_s = earlier_wall_seconds_ + session_seconds();
  running_ = false;
  const double* ph = s.phase_seconds();
  const double other = r.wall_time_s - ph[0] - ph[1] - ph[2];
  auto pct = [&](double t) { return fmt(100 * t / r.wall_time_s, 3) + " %"; };
  r.notes.push_back(
      "performance: " +
      fmt(static_cast<double>(s.particles().size()) * s.steps() / r.wall_time_s, 3) +
      " particle-steps per second; " + std::to_string(s.steps()) + " steps, " +
      std::to_string(s.parallel_steps()) +
      " of them with the helper threads (MPM/Threads; the faster way, timed every 1000 "
      "steps); wall time: scatter to the grid " +
      pct(ph[0]) + ", grid update, crack and contact " + pct(ph[1]) +
      ", grid to particles with stress and next weights " + pct(ph[2]) +
      ", growth checks (J integrals) and the rest " + pct(other));
  return r;
}

result::SimulationResult simulate_dcb(const specimen::Specimen& specimen,
                                      const specimen::Material& material,
                                      const law::TractionLaw& law, double j_tip,
                                      const MpmParameters& params, const std::string& output_dir,
                                      const std::function<void(const std::string&)>& progress) {
  fiberbridge::begin_fault_context("mpm");
  DcbModel model(specimen, material, law, j_tip, params, output_dir, progress);
  return model.run();
}

} // namespace fiberbridge::mpm
