#include "fiberbridge/mpm/explicit_solver.h"

#include "fiberbridge/core/binary_archive.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/mpm/shape_function.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <sstream>
#include <utility>

namespace fiberbridge::mpm {

ExplicitSolver::ExplicitSolver(Grid grid, Particles particles, const OrthotropicElastic& material,
                               double dt, double pic_fraction, double thickness)
    : grid_(std::move(grid)), particles_(std::move(particles)), material_(material), dt_(dt),
      beta_(pic_fraction), thickness_(thickness), wave_speed_(material.max_wave_speed()) {
  if (!(dt > 0) || !(pic_fraction >= 0 && pic_fraction <= 1) || !(thickness > 0))
    throw InputError("MPM solver: need dt > 0, 0 <= PIC fraction <= 1 and a positive thickness");
  const double c = grid_.cell();
  if (particles_.spacing_x > c * (1 + 1e-12) || particles_.spacing_y > c * (1 + 1e-12))
    throw InputError("MPM solver: particles must not be farther apart than a cell (uGIMP needs a "
                     "particle box no larger than the cell)");
  const std::size_t n = particles_.size();
  i0_.resize(n);
  j0_.resize(n);
  for (auto* w : {&sx_, &dsx_, &sy_, &dsy_})
    w->resize(3 * n);
  own_side_.resize(n);
  for (std::size_t p = 0; p < n; ++p)
    own_side_[p] = particles_.Y[p] >= 0 ? above : below;
  row_side_.resize(grid_.ny());
  for (int j = 0; j < grid_.ny(); ++j)
    row_side_[j] = grid_.side_of(j);
  split_column_.assign(grid_.nx(), 0);
  team_ = std::make_unique<WorkTeam>(1);
}

ExplicitSolver::~ExplicitSolver() = default;

void ExplicitSolver::set_threads(int n) {
  threads_ = n > 1 ? n : 1;
  team_ = std::make_unique<WorkTeam>(threads_);
}

template <class Body>
void ExplicitSolver::for_particles(Body&& body) {
  // Chunks of about 256 particles whatever the threads, so that the energy sums, added per
  // chunk in chunk order, do not depend on them (6 chunks on the 5 mm DCB, 26 on the 2.5 mm).
  const long n = static_cast<long>(particles_.size());
  const int n_chunks = static_cast<int>(std::max(1L, n / 256));
  chunk_sums_.assign(3 * n_chunks, 0.0);
  std::vector<long> off(n_chunks, -1);
  const std::function<void(int)> run_chunk = [&](int k) {
    off[k] = body(n * k / n_chunks, n * (k + 1) / n_chunks, &chunk_sums_[3 * k]);
  };
  team_->run(n_chunks, run_chunk);
  for (long o : off)
    if (o >= 0)
      off_grid_ = o;
}

void ExplicitSolver::step() {
  // Helper threads pay only while the cores are free; on cores shared with other processes a
  // descheduled helper stalls every step (measured: 1.3x slower than one thread at a load of
  // 5.6 on 2 cores). Every probe_period steps the solver times probe_steps steps without and
  // probe_steps with the helpers and runs the rest of the period the faster way. Both ways
  // compute the same chunks in the same order: the results do not depend on it.
  constexpr long probe_period = 1000, probe_steps = 20;
  const long phase = steps_ % probe_period;
  const bool probing = team_->threads() > 1 && phase < 2 * probe_steps;
  if (probing)
    team_->set_parallel(phase >= probe_steps);
  if (team_->parallel())
    ++parallel_steps_;
  using clock = std::chrono::steady_clock;
  auto lap = [this, t = clock::now()](int k) mutable {
    const auto now = clock::now();
    phase_seconds_[k] += std::chrono::duration<double>(now - t).count();
    t = now;
  };
  const double before = phase_seconds_[0] + phase_seconds_[1] + phase_seconds_[2];
  particles_to_grid();
  lap(0);
  if (crack_) {
    crack_->update_tractions();
    crack_->add_traction_forces(grid_, thickness_);
  }
  update_grid();
  if (crack_)
    contact();
  apply_constraints();
  lap(1);
  grid_to_particles();
  lap(2);
  if (crack_)
    crack_->move_surfaces(grid_, dt_);
  lap(1);
  time_ += dt_;
  ++steps_;
  if (probing) {
    probe_time_[phase >= probe_steps] +=
        phase_seconds_[0] + phase_seconds_[1] + phase_seconds_[2] - before;
    if (phase == 2 * probe_steps - 1) {
      team_->set_parallel(probe_time_[1] < probe_time_[0]);
      probe_time_[0] = probe_time_[1] = 0;
    }
  }
  // A full scan costs about one tenth of a step; every 50 steps an instability is still caught
  // long before it can reach the outputs.
  if (steps_ % 50 == 0)
    check_state();
}

long ExplicitSolver::compute_weights(long begin, long end) {
  const Particles& P = particles_;
  const double c = grid_.cell();
  // One axis at a time, straight into the arrays (the weights were a quarter of the step as a
  // call per particle; GCC 12 still does not vectorize this loop: "control flow in loop"). The
  // same arithmetic as ugimp_weights: the same weights to the bit.
  auto axis = [&](const double* pos, double origin, double lp, int* first, double* S, double* dS) {
    const UgimpAxis A(c, lp);
    for (long p = begin; p < end; ++p) {
      // floor() of the box's left edge in cells (true division, see ugimp_weights), as a
      // truncation corrected for negative values (no libm call).
      const double q = (pos[p] - A.lp - origin) / A.cell;
      const int t = static_cast<int>(q);
      const int f = t - (q < static_cast<double>(t));
      first[p] = f;
      detail::ugimp(pos[p] - (origin + f * A.cell), A, S[3 * p], dS[3 * p]);
      detail::ugimp(pos[p] - (origin + (f + 1) * A.cell), A, S[3 * p + 1], dS[3 * p + 1]);
      detail::ugimp(pos[p] - (origin + (f + 2) * A.cell), A, S[3 * p + 2], dS[3 * p + 2]);
    }
  };
  axis(P.x.data(), grid_.x_min(), 0.5 * P.spacing_x, i0_.data(), sx_.data(), dsx_.data());
  axis(P.y.data(), grid_.y_min(), 0.5 * P.spacing_y, j0_.data(), sy_.data(), dsy_.data());
  long off = -1;
  for (long p = begin; p < end; ++p)
    if (i0_[p] < 0 || j0_[p] < 0 || i0_[p] + 2 >= grid_.nx() || j0_[p] + 2 >= grid_.ny())
      off = p;
  return off;
}

void ExplicitSolver::particles_to_grid() {
  const Particles& P = particles_;
  const long n = static_cast<long>(P.size());
  // The weights were computed when the particles last moved (update_particles).
  if (!weights_current_) {
    for_particles([&](long b, long e, double*) { return compute_weights(b, e); });
    weights_current_ = true;
  }
  if (off_grid_ >= 0) {
    std::ostringstream s;
    s << "MPM: a particle left the background grid at t = " << time_ << " s (position "
      << P.x[off_grid_] * 1e3 << ", " << P.y[off_grid_] * 1e3
      << " mm); the arms opened farther than the grid allows or the run became unstable";
    throw ComputationError(s.str());
  }
  // Two fields at nodes on the crack (see Crack::splits): a particle joins the field of its own
  // side at the columns on the crack, else the field of the node's side (the continuum ahead of
  // the tip and away from the crack plane).
  for (int i = 0; i < grid_.nx(); ++i)
    split_column_[i] = crack_ && crack_->splits(above, grid_.x(i), below);
  grid_.reset();

  // The scatter to the nodes. Particles keep their lattice order, so a block of consecutive
  // particles touches a band of node columns. The blocks are coloured alternately; blocks of one
  // colour touch disjoint columns (checked every step: the arms swing, particles drift) and are
  // scattered in parallel, one colour after the other. If two blocks of a colour would meet,
  // the scatter runs serially: never a race. The same eight blocks for any number of threads:
  // the order of the sums at a node, and so the results, do not depend on the threads.
  const int n_blocks = 8;
  std::vector<std::pair<long, long>> blocks(n_blocks);
  std::vector<std::pair<int, int>> columns(blocks.size());
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    blocks[k] = {n * k / n_blocks, n * (k + 1) / n_blocks};
    int lo = grid_.nx(), hi = -1;
    for (long p = blocks[k].first; p < blocks[k].second; ++p) {
      lo = std::min(lo, i0_[p]);
      hi = std::max(hi, i0_[p] + 2);
    }
    columns[k] = {lo, hi};
  }
  bool disjoint = true;
  for (std::size_t k = 0; k < blocks.size() && disjoint; ++k)
    for (std::size_t l = k + 2; l < blocks.size(); l += 2)
      if (!(columns[k].second < columns[l].first || columns[l].second < columns[k].first))
        disjoint = false;
  if (disjoint) {
    for (int colour = 0; colour < 2; ++colour)
      team_->run(n_blocks / 2, [&](int k) {
        const auto& b = blocks[2 * k + colour];
        scatter(b.first, b.second);
      });
  } else {
    scatter(0, n);
  }

  for (const ParticleForce& pf : particle_forces_)
    for_links(pf.particle, [&](int k, double S, double, double) {
      if (S == 0)
        return;
      NodeField& f = grid_.fields()[k];
      f.fx += pf.fx * S;
      f.fy += pf.fy * S;
    });
}

void ExplicitSolver::scatter(long begin, long end) {
  const Particles& P = particles_;
  NodeField* fields = grid_.fields().data();
  for (long p = begin; p < end; ++p) {
    const double m = P.mass[p];
    const double V = P.volume[p] * (P.F[p][0] * P.F[p][3] - P.F[p][1] * P.F[p][2]);
    const auto& sig = P.stress[p];
    const double ux = P.x[p] - P.X[p], uy = P.y[p] - P.Y[p];
    const double mvx = m * P.vx[p], mvy = m * P.vy[p];
    // A link of zero weight and gradient adds zeros: no test needed (the sums are unchanged).
    for_links(p, [&](int k, double S, double gx, double gy) {
      NodeField& f = fields[k];
      f.mass += m * S;
      f.px += mvx * S;
      f.py += mvy * S;
      f.mux += m * ux * S;
      f.muy += m * uy * S;
      f.fx -= V * (sig[0] * gx + sig[2] * gy);
      f.fy -= V * (sig[2] * gx + sig[1] * gy);
    });
  }
}

void ExplicitSolver::update_grid() {
  for (NodeField& f : grid_.fields()) {
    if (f.mass <= 0)
      continue;
    f.vx = f.px / f.mass;
    f.vy = f.py / f.mass;
    f.vx_new = f.vx + f.fx / f.mass * dt_;
    f.vy_new = f.vy + f.fy / f.mass * dt_;
  }
}

void ExplicitSolver::contact() {
  // Frictionless contact of the two crack faces (the DCB crack plane has normal +y): where both
  // fields meet at a node, have closed (relative normal displacement <= 0) and approach, they
  // exchange normal momentum so that both move with their centre-of-mass normal velocity;
  // tangential motion is free.
  for (int n = 0; n < grid_.n_nodes(); ++n) {
    NodeField& a = grid_.field(n, above);
    NodeField& b = grid_.field(n, below);
    if (a.mass <= 0 || b.mass <= 0)
      continue;
    const double gap = a.muy / a.mass - b.muy / b.mass;
    if (gap > 0 || a.vy_new - b.vy_new >= 0)
      continue;
    const double v = (a.mass * a.vy_new + b.mass * b.vy_new) / (a.mass + b.mass);
    a.vy_new = v;
    b.vy_new = v;
  }
}

void ExplicitSolver::apply_constraints() {
  for (VelocityConstraint& c : constraints_) {
    c.reaction = 0;
    for (const auto& [node, side] : c.fields) {
      NodeField& f = grid_.field(node, side);
      if (f.mass <= 0)
        continue;
      double& v = c.component == 0 ? f.vx_new : f.vy_new;
      c.reaction += f.mass * (c.velocity - v) / dt_;
      v = c.velocity;
    }
    // Power of the reaction on nodes that move with the prescribed velocity. (Not the nodes'
    // kinetic-energy change m (v_set^2 - v^2)/2: the trial velocity v of a light node is never
    // seen by the particles, and counting it lost a third of the work on the DCB.)
    external_work_ += c.reaction * c.velocity * dt_;
  }
}

void ExplicitSolver::grid_to_particles() {
  // Numerical loss of the explicit update (numerical_loss()): per step, with dv_I the velocity
  // increment of a node field and dv_p = sum_I S_Ip dv_I that of a particle's FLIP update,
  //   loss = 2 sum_I m_I |dv_I|^2 / 2 - sum_p m_p |dv_p|^2 / 2 - sum_p V_p de:C:de / 2.
  // The first two terms: the particles gain less kinetic energy than the grid (lumped nodal mass
  // against the particles' own), and the stress of the step does work with the end-of-step
  // velocity while the grid's kinetic energy grows with the mid-step one. The third: the strain
  // energy's second-order part. Contact and the velocity constraints drop out (contact exchanges
  // momentum at a common velocity; the constraint's work is counted at its velocity). Derived
  // for the USL step here; measured: it closes the DCB energy balance to 2e-4 of the work.
  double grid_gain = 0;
  for (const NodeField& f : grid_.fields())
    if (f.mass > 0) {
      const double ax = f.vx_new - f.vx, ay = f.vy_new - f.vy;
      grid_gain += 0.5 * f.mass * (ax * ax + ay * ay);
    }
  // Work of particle forces: they act on the grid, so their power is force times the nodal
  // velocity (mean of before and after the step). The particle's own FLIP velocity carries
  // noise the grid never sees; with it the work came out 3 % high on the cantilever test.
  for (const ParticleForce& pf : particle_forces_)
    for_links(pf.particle, [&](int k, double S, double, double) {
      if (S == 0)
        return;
      const NodeField& f = grid_.fields()[k];
      external_work_ += 0.5 * S * (pf.fx * (f.vx + f.vx_new) + pf.fy * (f.vy + f.vy_new)) * dt_;
    });

  for_particles([&](long b, long e, double* sums) { return update_particles(b, e, sums); });
  double loss = 0, flip_gain = 0, stiff_gain = 0;
  for (std::size_t k = 0; k < chunk_sums_.size(); k += 3) {
    loss += chunk_sums_[k];
    flip_gain += chunk_sums_[k + 1];
    stiff_gain += chunk_sums_[k + 2];
  }
  damping_loss_ += loss;
  numerical_loss_ += 2 * grid_gain - flip_gain - stiff_gain;
}

long ExplicitSolver::update_particles(long begin, long end, double sums[3]) {
  Particles& P = particles_;
  const NodeField* fields = grid_.fields().data();
  double loss = 0, flip_gain = 0, stiff_gain = 0;
  for (long p = begin; p < end; ++p) {
    double vpic_x = 0, vpic_y = 0, dvx = 0, dvy = 0;
    double L11 = 0, L12 = 0, L21 = 0, L22 = 0;
    for_links(p, [&](int k, double S, double gx, double gy) {
      const NodeField& f = fields[k];
      vpic_x += S * f.vx_new;
      vpic_y += S * f.vy_new;
      dvx += S * (f.vx_new - f.vx);
      dvy += S * (f.vy_new - f.vy);
      L11 += f.vx_new * gx;
      L12 += f.vx_new * gy;
      L21 += f.vy_new * gx;
      L22 += f.vy_new * gy;
    });
    // Velocity: PIC damping blends the FLIP update (energy conserving, keeps the noise that
    // crack growth releases) with the PIC velocity (dissipative); the kinetic energy removed is
    // the damping loss.
    const double fx = P.vx[p] + dvx, fy = P.vy[p] + dvy;
    const double bx = (1 - beta_) * fx + beta_ * vpic_x;
    const double by = (1 - beta_) * fy + beta_ * vpic_y;
    loss += 0.5 * P.mass[p] * (fx * fx + fy * fy - bx * bx - by * by);
    flip_gain += 0.5 * P.mass[p] * (dvx * dvx + dvy * dvy);
    P.vx[p] = bx;
    P.vy[p] = by;

    // Update-stress-last: position, deformation gradient and stress from the new grid
    // velocities.
    P.x[p] += vpic_x * dt_;
    P.y[p] += vpic_y * dt_;
    // F <- (I + L dt) F, then the corotational small-strain update: F = R U, strain U - I in the
    // material frame (which turns with the arm), Cauchy stress R S R^T.
    auto& F = P.F[p];
    const double a11 = 1 + L11 * dt_, a12 = L12 * dt_, a21 = L21 * dt_, a22 = 1 + L22 * dt_;
    const double F11 = a11 * F[0] + a12 * F[2], F12 = a11 * F[1] + a12 * F[3];
    const double F21 = a21 * F[0] + a22 * F[2], F22 = a21 * F[1] + a22 * F[3];
    F = {F11, F12, F21, F22};
    // Polar rotation angle th with tan th = (F21 - F12)/(F11 + F22), as cosine and sine
    // directly (no trigonometric calls in the hot loop; F11 + F22 stays near 2, so the plain
    // square root needs none of hypot's overflow care).
    const double rn = 1 / std::sqrt((F11 + F22) * (F11 + F22) + (F21 - F12) * (F21 - F12));
    const double c = (F11 + F22) * rn, s = (F21 - F12) * rn;
    const double U11 = c * F11 + s * F21, U22 = -s * F12 + c * F22;
    const double U12 = c * F12 + s * F22, U21 = -s * F11 + c * F21;
    double eps[3] = {U11 - 1, U22 - 1, 0.5 * (U12 + U21)};
    double S[3];
    material_.stress(eps, S);
    const double de[3] = {eps[0] - P.strain[p][0], eps[1] - P.strain[p][1],
                          eps[2] - P.strain[p][2]};
    stiff_gain += material_.energy_density(de) * P.volume[p];
    P.strain[p] = {eps[0], eps[1], eps[2]};
    P.stress[p] = {c * c * S[0] - 2 * c * s * S[2] + s * s * S[1],
                   s * s * S[0] + 2 * c * s * S[2] + c * c * S[1],
                   c * s * (S[0] - S[1]) + (c * c - s * s) * S[2]};
  }
  sums[0] += loss;
  sums[1] += flip_gain;
  sums[2] += stiff_gain;
  // The weights of the next step, at the new positions.
  return compute_weights(begin, end);
}

void ExplicitSolver::check_state() const {
  const Particles& P = particles_;
  for (std::size_t p = 0; p < P.size(); ++p) {
    const double v2 = P.vx[p] * P.vx[p] + P.vy[p] * P.vy[p];
    const bool finite = std::isfinite(v2) && std::isfinite(P.stress[p][0]) &&
                        std::isfinite(P.stress[p][1]) && std::isfinite(P.stress[p][2]);
    // Quasi-static loading moves material at a tiny fraction of the wave speed; a particle at the
    // wave speed means the explicit update has lost stability.
    if (!finite || v2 > wave_speed_ * wave_speed_) {
      std::ostringstream s;
      s << "MPM became unstable at t = " << time_ << " s (step " << steps_ << "): particle at ("
        << P.x[p] * 1e3 << ", " << P.y[p] * 1e3 << ") mm has "
        << (finite ? "a velocity above the wave speed " : "a non-finite velocity or stress; ")
        << (finite ? std::to_string(wave_speed_) + " m/s; " : "") << "time step " << dt_
        << " s; reduce the CFL factor or the loading rate, or raise the "
        << "PIC damping fraction";
      throw ComputationError(s.str());
    }
  }
}

double ExplicitSolver::kinetic_energy() const {
  double e = 0;
  for (std::size_t p = 0; p < particles_.size(); ++p)
    e += 0.5 * particles_.mass[p] *
         (particles_.vx[p] * particles_.vx[p] + particles_.vy[p] * particles_.vy[p]);
  return e;
}

double ExplicitSolver::energy_density(int p) const {
  const auto& e = particles_.strain[p];
  const double eps[3] = {e[0], e[1], e[2]};
  return material_.energy_density(eps);
}

double ExplicitSolver::strain_energy() const {
  double e = 0;
  for (std::size_t p = 0; p < particles_.size(); ++p)
    e += energy_density(static_cast<int>(p)) * particles_.volume[p];
  return e;
}

bool ExplicitSolver::field_velocity(int side, double x, double y, double& vx, double& vy) const {
  return interpolate_field_velocity(grid_, side, x, y, vx, vy);
}

void ExplicitSolver::material_displacement(double x, double y, double& ux, double& uy) const {
  const AxisWeights wx = linear_weights(x, grid_.x_min(), grid_.cell());
  const AxisWeights wy = linear_weights(y, grid_.y_min(), grid_.cell());
  double sum = 0, sx = 0, sy = 0;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const int i = wx.first + a, j = wy.first + b;
      if (i < 0 || j < 0 || i >= grid_.nx() || j >= grid_.ny())
        continue;
      const NodeField& f = grid_.field(grid_.node(i, j), grid_.side_of(j));
      if (f.mass <= 0)
        continue;
      const double S = wx.S[a] * wy.S[b];
      sum += S;
      sx += S * f.mux / f.mass;
      sy += S * f.muy / f.mass;
    }
  ux = sum > 0 ? sx / sum : 0;
  uy = sum > 0 ? sy / sum : 0;
}

void ExplicitSolver::save_state(BinaryWriter& out) const {
  const Particles& P = particles_;
  out.put(static_cast<std::uint64_t>(P.size()));
  for (const auto* v : {&P.X, &P.Y, &P.x, &P.y, &P.vx, &P.vy, &P.mass, &P.volume})
    out.put(*v);
  out.put(P.F);
  out.put(P.strain);
  out.put(P.stress);
  out.put(time_);
  out.put(steps_);
  out.put(external_work_);
  out.put(damping_loss_);
  out.put(numerical_loss_);
  // Statistics (the performance note): carried on so that a resumed run reports the whole run.
  out.put(parallel_steps_);
  out.put(phase_seconds_);
  out.put(probe_time_);
  out.put(team_->parallel());
}

void ExplicitSolver::load_state(BinaryReader& in) {
  Particles& P = particles_;
  const auto n = in.get<std::uint64_t>();
  if (n != P.size())
    throw InputError(in.source() + ": the checkpoint holds " + std::to_string(n) +
                     " particles, the scene's body " + std::to_string(P.size()));
  for (auto* v : {&P.X, &P.Y, &P.x, &P.y, &P.vx, &P.vy, &P.mass, &P.volume}) {
    in.get(*v);
    if (v->size() != n)
      throw InputError(in.source() + ": a particle array has " + std::to_string(v->size()) +
                       " entries instead of " + std::to_string(n));
  }
  in.get(P.F);
  in.get(P.strain);
  in.get(P.stress);
  if (P.F.size() != n || P.strain.size() != n || P.stress.size() != n)
    throw InputError(in.source() + ": a particle tensor array does not hold " + std::to_string(n) +
                     " entries");
  in.get(time_);
  in.get(steps_);
  in.get(external_work_);
  in.get(damping_loss_);
  in.get(numerical_loss_);
  in.get(parallel_steps_);
  in.get(phase_seconds_);
  in.get(probe_time_);
  team_->set_parallel(in.get<bool>());
  // The weights of the next step: the same arithmetic as at the end of the saved step.
  weights_current_ = false;
  off_grid_ = -1;
}

} // namespace fiberbridge::mpm
