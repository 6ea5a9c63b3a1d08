#pragma once
// One explicit MPM time step, update-stress-last (USL): particle-to-grid, grid momentum update
// with crack tractions, crack contact and velocity constraints, grid-to-particle with PIC damping,
// then the stress from the new grid velocities. USL is chosen because with PIC damping it is
// stable without the second grid projection of MUSL, and the stress it leaves is the one the
// J integrals read at the same instant as the particle positions.
#include "fiberbridge/mpm/crack.h"
#include "fiberbridge/mpm/grid.h"
#include "fiberbridge/mpm/orthotropic_elastic.h"
#include "fiberbridge/mpm/particles.h"
#include "fiberbridge/mpm/thread_tuner.h"
#include "fiberbridge/mpm/work_team.h"

namespace fiberbridge {
class BinaryWriter;
class BinaryReader;
} // namespace fiberbridge

#include <memory>
#include <vector>

namespace fiberbridge::mpm {

/// Prescribed velocity of one component on a set of node fields (a loading block or a clamp).
/// The solver returns the force it had to apply in `reaction` [N] (sum over the set, last step).
struct VelocityConstraint {
  std::vector<std::pair<int, int>> fields; ///< (node, side)
  int component = 1;                       ///< 0 = x, 1 = y
  double velocity = 0;                     ///< [m/s]
  double reaction = 0;                     ///< output [N]
};

/// A force applied to one particle [N] (external loads in tests).
struct ParticleForce {
  int particle = 0;
  double fx = 0, fy = 0;
};

class ExplicitSolver {
public:
  /// `thickness` is the out-of-plane width B: forces are for the whole width.
  ExplicitSolver(Grid grid, Particles particles, const OrthotropicElastic& material, double dt,
                 double pic_fraction, double thickness);
  ~ExplicitSolver();

  /// Optional explicit crack (not owned; must outlive the solver's steps).
  void set_crack(Crack* crack) { crack_ = crack; }
  std::vector<VelocityConstraint>& constraints() { return constraints_; }
  std::vector<ParticleForce>& particle_forces() { return particle_forces_; }
  /// Threads of the particle loops (1 = serial). More threads change only the order of sums:
  /// the scatter runs in coloured blocks and the energy terms are summed per chunk.
  void set_threads(int n);
  /// Changes the PIC damping fraction (tests switch damping off to watch free vibration).
  void set_pic_fraction(double beta) { beta_ = beta; }

  /// Advances by dt. Throws ComputationError with a diagnosis when the state stops being
  /// trustworthy (a particle leaves the grid, a non-finite value, a velocity above the wave speed).
  void step();

  double time() const { return time_; }
  double dt() const { return dt_; }
  long steps() const { return steps_; }
  /// Steps run with the helper threads (with Threads > 1 the solver times both ways now and
  /// then and keeps the faster: on cores busy with other work one thread wins).
  long parallel_steps() const { return parallel_steps_; }
  /// Wall time spent so far [s] in: 0 the weights' use in the scatter to the grid (with the grid
  /// reset), 1 the grid update with crack tractions, contact, constraints and crack surfaces,
  /// 2 grid to particles with the stress update and the next step's weights.
  const double* phase_seconds() const { return phase_seconds_; }
  const Particles& particles() const { return particles_; }
  const Grid& grid() const { return grid_; }
  const OrthotropicElastic& material() const { return material_; }
  double thickness() const { return thickness_; }

  /// Energy bookkeeping [J]: work of constraints and particle forces, damping loss of the PIC
  /// blend (kinetic energy of the FLIP update minus that of the blended velocity).
  double external_work() const { return external_work_; }
  double damping_loss() const { return damping_loss_; }
  /// Energy the explicit update itself loses (derivation in grid_to_particles): small while the
  /// fields are smooth, large right after a tip advance, where an MPM tip releases its energy.
  double numerical_loss() const { return numerical_loss_; }
  double kinetic_energy() const;
  double strain_energy() const;
  /// Strain energy density of particle p [J/m^3].
  double energy_density(int p) const;

  /// Velocity of one side's field interpolated at (x, y) with linear weights over the nodes where
  /// that field has mass (renormalized); false when no such node exists.
  bool field_velocity(int side, double x, double y, double& vx, double& vy) const;
  /// Displacement interpolated from the particles of the field the point belongs to (used to
  /// place a new crack tip on the material).
  void material_displacement(double x, double y, double& ux, double& uy) const;

  /// The state that carries from one step to the next (particles, time, step count, energy
  /// ledger, timing statistics), bit for bit, for checkpoints (mpm/checkpoint.h). The grid is
  /// not part of it: every step rebuilds it from the particles. load_state() needs a solver built
  /// for the same body (InputError naming the checkpoint otherwise); the shape weights are then
  /// recomputed with the same arithmetic, so the next step is the one the saved run would take.
  void save_state(BinaryWriter& out) const;
  void load_state(BinaryReader& in);

private:
  void particles_to_grid();
  /// uGIMP weights of particles [begin, end) at their current positions; returns a particle whose
  /// nodes leave the grid, or -1.
  long compute_weights(long begin, long end);
  /// Adds the mass, momentum, mass-weighted displacement and internal force of particles
  /// [begin, end) to their nodes' fields.
  void scatter(long begin, long end);
  /// Nodal velocities from momentum and force, then (with a crack) contact of the two fields.
  void update_grid();
  static void contact(NodeField& above_field, NodeField& below_field);
  void apply_constraints();
  void grid_to_particles();
  /// Velocity, position, deformation and stress of particles [begin, end) from the new grid
  /// velocities, then their weights at the new positions; adds the chunk's energy terms to
  /// sums (damping loss, FLIP kinetic-energy gain, strain energy of the increments) and returns
  /// a particle that left the grid, or -1.
  long update_particles(long begin, long end, double sums[3]);
  /// Calls f(field index, S, dS/dx, dS/dy) for the links of particle p, a (x) outer: the 3 x 3
  /// nodes around it, less the third column (row) where the particle's x (y) weight and its
  /// derivative are both zero, so that the link adds exact zeros (n_links_x_, n_links_y_; a
  /// particle of the undeformed lattice has 2 x 2 links: its box ends on a node line).
  /// The field index of node (i0 + a, j0 + b) is 2 (i ny + j) + side: on a node column the crack
  /// splits, the side of the particle's own material; elsewhere the side of the node's row. The
  /// column and row lookups are made once per particle, not once per link (this is the hot loop
  /// of scatter and grid-to-particles, issue 16).
  template <class F>
  void for_links(long p, F&& f) const {
    // The trip counts as constants (fully unrolled loops), one branch per particle.
    switch (2 * n_links_x_[p] + n_links_y_[p]) {
    case 6:
      links<2, 2>(p, f);
      break;
    case 7:
      links<2, 3>(p, f);
      break;
    case 8:
      links<3, 2>(p, f);
      break;
    default:
      links<3, 3>(p, f);
    }
  }
  template <int NA, int NB, class F>
  void links(long p, F& f) const {
    // Weight k of particle p at [k n + p].
    const long n = static_cast<long>(i0_.size());
    const double sx[3] = {sx_[p], sx_[n + p], sx_[2 * n + p]};
    const double sy[3] = {sy_[p], sy_[n + p], sy_[2 * n + p]};
    const double dsx[3] = {dsx_[p], dsx_[n + p], dsx_[2 * n + p]};
    const double dsy[3] = {dsy_[p], dsy_[n + p], dsy_[2 * n + p]};
    const int i0 = i0_[p], j0 = j0_[p], ny = grid_.ny(), own = own_side_[p];
    const int rows[3] = {row_side_[j0], row_side_[j0 + 1], row_side_[j0 + 2]};
    for (int a = 0; a < NA; ++a) {
      const int base = 2 * ((i0 + a) * ny + j0);
      const bool split = split_column_[i0 + a];
      for (int b = 0; b < NB; ++b)
        f(base + 2 * b + (split ? own : rows[b]), sx[a] * sy[b], dsx[a] * sy[b], sx[a] * dsy[b]);
    }
  }
  /// Runs f(field) over both fields of every node in the box the particles reached.
  template <class F>
  void for_box(F&& f);
  /// Runs body(i_begin, i_end) over the box's node columns in chunks, on the team's threads.
  template <class Body>
  void for_box_columns(Body&& body);
  /// Runs body(begin, end) over the particles in chunks, on the team's threads.
  template <class Body>
  void for_particles(Body&& body);
  void check_state() const;
  Grid grid_;
  Particles particles_;
  OrthotropicElastic material_;
  double dt_, beta_, thickness_;
  Crack* crack_ = nullptr;
  std::vector<VelocityConstraint> constraints_;
  std::vector<ParticleForce> particle_forces_;
  // Shape weights at the current positions, structure of arrays: per particle the lowest node
  // column and row it touches and three uGIMP weights and derivatives per axis (node by node,
  // so that the weight kernel stores whole vectors); the 3 x 3 link
  // weights are their products, formed where they are used. Computed at the end of each step,
  // right after the particle moved, for the next one.
  std::vector<int> i0_, j0_;
  std::vector<double> sx_, dsx_, sy_, dsy_; ///< 3 per particle: weight k of particle p at [k n + p]
  /// Per particle 3, or 2 when the third node's weight and derivative along that axis are zero.
  std::vector<unsigned char> n_links_x_, n_links_y_;
  bool weights_current_ = false;
  long off_grid_ = -1; ///< a particle whose weights leave the grid, or -1
  /// Per particle, structure of arrays (11 n): what the links gave (PIC velocity, FLIP
  /// increment, velocity gradient) and the energy terms, between the passes of update_particles.
  std::vector<double> gathered_;
  std::vector<unsigned char> own_side_;     ///< side of the crack plane of each particle
  std::vector<unsigned char> row_side_;     ///< side of each node row
  std::vector<unsigned char> split_column_; ///< node columns on the crack (this step)
  int threads_ = 1;
  std::unique_ptr<WorkTeam> team_;
  std::vector<double> chunk_sums_; ///< energy terms per particle chunk (summed in chunk order)
  long parallel_steps_ = 0;
  double phase_seconds_[3] = {0, 0, 0};
  /// Whether the helper threads run a step (step(); thread_tuner.h).
  ThreadTuner tuner_;
  /// Node columns and rows the particles reached in the last scatter ([lo, hi), empty at first):
  /// every node outside holds an empty field, so the grid loops run over this box only.
  int box_i_[2] = {0, 0}, box_j_[2] = {0, 0};
  double time_ = 0;
  long steps_ = 0;
  double external_work_ = 0, damping_loss_ = 0, numerical_loss_ = 0;
  double wave_speed_;
};

} // namespace fiberbridge::mpm
