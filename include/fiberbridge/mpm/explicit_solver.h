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

  /// Optional explicit crack (not owned; must outlive the solver's steps).
  void set_crack(Crack* crack) { crack_ = crack; }
  std::vector<VelocityConstraint>& constraints() { return constraints_; }
  std::vector<ParticleForce>& particle_forces() { return particle_forces_; }
  /// Threads of the particle loops (OpenMP builds; 1 = serial). Results do not depend on it
  /// beyond the summation order of the PIC damping loss.
  void set_threads(int n) { threads_ = n > 1 ? n : 1; }
  /// Changes the PIC damping fraction (tests switch damping off to watch free vibration).
  void set_pic_fraction(double beta) { beta_ = beta; }

  /// Advances by dt. Throws ComputationError with a diagnosis when the state stops being
  /// trustworthy (a particle leaves the grid, a non-finite value, a velocity above the wave speed).
  void step();

  double time() const { return time_; }
  double dt() const { return dt_; }
  long steps() const { return steps_; }
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

private:
  struct Link { // one particle-node pair of the current step
    int node;
    int side;
    double S, gx, gy;
  };
  void particles_to_grid();
  /// Adds the mass, momentum, mass-weighted displacement and internal force of particles
  /// [begin, end) to their links' fields.
  void scatter(long begin, long end);
  void update_grid();
  void contact();
  void apply_constraints();
  void grid_to_particles();
  void check_state() const;

  Grid grid_;
  Particles particles_;
  OrthotropicElastic material_;
  double dt_, beta_, thickness_;
  Crack* crack_ = nullptr;
  std::vector<VelocityConstraint> constraints_;
  std::vector<ParticleForce> particle_forces_;
  std::vector<Link> links_;       ///< 9 per particle
  std::vector<int> first_column_; ///< lowest node column each particle touches (this step)
  int threads_ = 1;
  double time_ = 0;
  long steps_ = 0;
  double external_work_ = 0, damping_loss_ = 0, numerical_loss_ = 0;
  double wave_speed_;
};

} // namespace fiberbridge::mpm
