#include "fiberbridge/mpm/explicit_solver.h"

#include "fiberbridge/core/binary_archive.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/mpm/shape_function.h"
#include "simd_lanes.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <functional>
#include <sstream>
#include <utility>

namespace fiberbridge::mpm {

// The SIMD lanes (simd_lanes.h): pairs of doubles in the scatter and the gather, the weight kernel
// and the particle update.
using lanes::load2;
using lanes::store2;
using lanes::v2d;

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
  n_links_x_.resize(n);
  n_links_y_.resize(n);
  gathered_.resize(11 * n);
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
  // The first step clears the whole grid it was given.
  box_i_[1] = grid_.nx();
  box_j_[1] = grid_.ny();
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
  // With helper threads, the tuner times both ways now and then and keeps the faster
  // (thread_tuner.h).
  const long step_index = steps_;
  const bool timed = tuner_.begin_step(*team_, step_index);
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
  apply_constraints();
  lap(1);
  grid_to_particles();
  lap(2);
  if (crack_)
    crack_->move_surfaces(grid_, dt_);
  lap(1);
  time_ += dt_;
  ++steps_;
  if (timed)
    tuner_.end_step(*team_, step_index,
                    phase_seconds_[0] + phase_seconds_[1] + phase_seconds_[2] - before);
  // A full scan costs about one tenth of a step; every 50 steps an instability is still caught
  // long before it can reach the outputs.
  if (steps_ % 50 == 0)
    check_state();
}

long ExplicitSolver::compute_weights(long begin, long end) {
  const Particles& P = particles_;
  const double c = grid_.cell();
  // One axis at a time, straight into the arrays, several particles per instruction
  // (weights_axis; the weights were a quarter of the step as a call per particle).
  const long n = static_cast<long>(P.size());
  lanes::weights_axis(P.x.data(), begin, end, n, grid_.x_min(), UgimpAxis(c, 0.5 * P.spacing_x),
                      i0_.data(), sx_.data(), dsx_.data(), n_links_x_.data());
  lanes::weights_axis(P.y.data(), begin, end, n, grid_.y_min(), UgimpAxis(c, 0.5 * P.spacing_y),
                      j0_.data(), sy_.data(), dsy_.data(), n_links_y_.data());
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
  // Only the nodes of the last step's box hold anything (every write to the grid goes to a node
  // with mass): clearing them clears the grid. The grid is sized for the final opening, so
  // early in a run the particles reach about a third of its rows.
  // On the team: a serial clear of the box outlasted a helper's idle spin (it then slept and
  // had to be woken for the scatter).
  for_box_columns([this](int begin, int end) {
    NodeField* fields = grid_.fields().data();
    const int ny = grid_.ny();
    for (int i = begin; i < end; ++i)
      std::fill(fields + 2 * (i * ny + box_j_[0]), fields + 2 * (i * ny + box_j_[1]), NodeField{});
  });

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
  box_i_[0] = grid_.nx();
  box_i_[1] = 0;
  for (const auto& [lo, hi] : columns) {
    box_i_[0] = std::min(box_i_[0], lo);
    box_i_[1] = std::max(box_i_[1], hi + 1);
  }
  const auto [j_lo, j_hi] = std::minmax_element(j0_.begin(), j0_.end());
  box_j_[0] = n > 0 ? *j_lo : 0;
  box_j_[1] = n > 0 ? *j_hi + 3 : 0;
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
    // What a link adds, in the pairs of NodeField: (mass, unused) m S, momentum m v S,
    // mass-weighted displacement m u S, and the force -V sigma grad S.
    const v2d m0 = {m, 0.0}, mv = {m * P.vx[p], m * P.vy[p]}, mu = {m * ux, m * uy};
    const v2d sig_x = {sig[0], sig[2]}, sig_y = {sig[2], sig[1]};
    // for_links leaves out the links of zero weight and gradient (which would add exact zeros).
    for_links(p, [&](int k, double S, double gx, double gy) {
      double* f = reinterpret_cast<double*>(fields + k);
      store2(f, load2(f) + m0 * S);
      store2(f + 2, load2(f + 2) + mv * S);
      store2(f + 4, load2(f + 4) + mu * S);
      store2(f + 6, load2(f + 6) - V * (sig_x * gx + sig_y * gy));
    });
  }
}

template <class Body>
void ExplicitSolver::for_box_columns(Body&& body) {
  // Chunks of at least 8 columns, at most 8 chunks: the same for any number of threads.
  const int n_cols = box_i_[1] - box_i_[0];
  const int n_chunks = std::min(8, std::max(1, n_cols / 8));
  team_->run(n_chunks, [&](int k) {
    body(box_i_[0] + n_cols * k / n_chunks, box_i_[0] + n_cols * (k + 1) / n_chunks);
  });
}

template <class F>
void ExplicitSolver::for_box(F&& f) {
  NodeField* fields = grid_.fields().data();
  const int ny = grid_.ny();
  for (int i = box_i_[0]; i < box_i_[1]; ++i)
    for (int k = 2 * (i * ny + box_j_[0]); k < 2 * (i * ny + box_j_[1]); ++k)
      f(fields[k]);
}

void ExplicitSolver::update_grid() {
  // Node by node, independent of every other node: the columns of the box in chunks on the
  // team (this phase alone outlasted a helper's idle spin, so it slept and was woken every
  // step).
  const bool with_contact = crack_ != nullptr;
  for_box_columns([&](int begin, int end) {
    for (int i = begin; i < end; ++i)
      for (int n = grid_.node(i, box_j_[0]); n < grid_.node(i, box_j_[1]); ++n) {
        for (int side : {0, 1}) {
          NodeField& f = grid_.field(n, side);
          if (f.mass <= 0)
            continue;
          f.vx = f.px / f.mass;
          f.vy = f.py / f.mass;
          f.vx_new = f.vx + f.fx / f.mass * dt_;
          f.vy_new = f.vy + f.fy / f.mass * dt_;
        }
        if (with_contact)
          contact(grid_.field(n, above), grid_.field(n, below));
      }
  });
}

void ExplicitSolver::contact(NodeField& a, NodeField& b) {
  // Frictionless contact of the two crack faces (the DCB crack plane has normal +y): where both
  // fields meet at a node, have closed (relative normal displacement <= 0) and approach, they
  // exchange normal momentum so that both move with their centre-of-mass normal velocity;
  // tangential motion is free.
  if (a.mass <= 0 || b.mass <= 0)
    return;
  const double gap = a.muy / a.mass - b.muy / b.mass;
  if (gap > 0 || a.vy_new - b.vy_new >= 0)
    return;
  const double v = (a.mass * a.vy_new + b.mass * b.vy_new) / (a.mass + b.mass);
  a.vy_new = v;
  b.vy_new = v;
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
  for_box([&grid_gain](const NodeField& f) {
    if (f.mass > 0) {
      const double ax = f.vx_new - f.vx, ay = f.vy_new - f.vy;
      grid_gain += 0.5 * f.mass * (ax * ax + ay * ay);
    }
  });
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
  const long n = static_cast<long>(P.size());
  double* g = gathered_.data();
  // Pass 1, particle by particle: what the links give.
  for (long p = begin; p < end; ++p) {
    // Pairs: PIC velocity, FLIP increment, and the velocity gradient's columns (L11, L21) and
    // (L12, L22), each summed over the links in link order.
    v2d vpic = {0.0, 0.0}, dv = vpic, Lx = vpic, Ly = vpic;
    for_links(p, [&](int k, double S, double gx, double gy) {
      const double* f = reinterpret_cast<const double*>(fields + k);
      const v2d v = load2(f + 10), v_old = load2(f + 8); // (vx_new, vy_new), (vx, vy)
      vpic += S * v;
      dv += S * (v - v_old);
      Lx += v * gx;
      Ly += v * gy;
    });
    g[p] = vpic[0];
    g[n + p] = vpic[1];
    g[2 * n + p] = dv[0];
    g[3 * n + p] = dv[1];
    g[4 * n + p] = Lx[0]; // L11
    g[5 * n + p] = Ly[0]; // L12
    g[6 * n + p] = Lx[1]; // L21
    g[7 * n + p] = Ly[1]; // L22
  }
  // Pass 2, several particles per instruction: velocity, position, deformation and stress.
  double sig1[3], sig2[3], sig3[3];
  const double e1[3] = {1, 0, 0}, e2[3] = {0, 1, 0}, e3[3] = {0, 0, 1};
  material_.stress(e1, sig1);
  material_.stress(e2, sig2);
  material_.stress(e3, sig3);
  const lanes::LaneUpdate u{P.vx.data(),
                            P.vy.data(),
                            P.x.data(),
                            P.y.data(),
                            P.mass.data(),
                            P.volume.data(),
                            P.F.data()->data(),
                            P.strain.data()->data(),
                            P.stress.data()->data(),
                            g,
                            n,
                            dt_,
                            beta_,
                            sig1[0],
                            sig1[1],
                            sig2[1],
                            sig3[2]};
  lanes::update_particles(u, begin, end);
  // Pass 3: the energy terms, summed in particle order.
  double loss = 0, flip_gain = 0, stiff_gain = 0;
  for (long p = begin; p < end; ++p) {
    loss += g[8 * n + p];
    flip_gain += g[9 * n + p];
    stiff_gain += g[10 * n + p];
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
  tuner_.save_state(out);
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
  tuner_.load_state(in);
  team_->set_parallel(in.get<bool>());
  // The weights of the next step: the same arithmetic as at the end of the saved step.
  weights_current_ = false;
  // The grid may hold anything (this solver may have run): the next step clears all of it.
  box_i_[0] = box_j_[0] = 0;
  box_i_[1] = grid_.nx();
  box_j_[1] = grid_.ny();
  off_grid_ = -1;
}

} // namespace fiberbridge::mpm
