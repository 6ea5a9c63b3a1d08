#pragma once
// The explicit crack: a polyline of crack particles on the mid-plane y = 0 from the loaded end to
// the tip. Each crack particle carries the positions of the two crack surfaces (they move with the
// velocity field of their own side); segments between crack particles carry a traction law with
// its damage history (bridged segments, created behind the growing tip) or none (the sawn notch).
//
// The crack plane stays on y = 0: a DCB loaded symmetrically in mode I keeps the mean of the two
// surfaces on its mid-plane, so the field split is decided against that line. The solver
// checks the mean surface position and stops with a diagnosis if the response loses symmetry.
#include "fiberbridge/law/traction_law.h"
#include "fiberbridge/mpm/grid.h"

#include <vector>

namespace fiberbridge {
class BinaryWriter;
class BinaryReader;
} // namespace fiberbridge

namespace fiberbridge::mpm {

struct CrackParticle {
  double X = 0;          ///< reference position along the mid-plane [m]
  double ux[2] = {0, 0}; ///< displacement of the surface below [0] and above [1] [m]
  double uy[2] = {0, 0};
  double opening() const { return uy[above] - uy[below]; }
};

/// A crack segment between crack particles k and k+1.
struct CrackSegment {
  bool bridged = false; ///< carries the traction law (false: sawn notch, or law "none")
  double delta_max = 0; ///< damage history of the law
  double opening = 0;   ///< current normal opening (mean of the two end openings) [m]
  double traction = 0;  ///< current traction (positive pulls the surfaces together) [Pa]
  bool failed = false;  ///< opened past delta_c: traction-free for good
};

class Crack {
public:
  /// Traction-free notch from x_start (outside the body) to x_tip, crack particles about every
  /// `spacing`, fields split at nodes up to `split_offset` behind the tip (splits()); `law` (may
  /// have zero area: the no-bridging law) acts on segments added by advance(). The law must outlive
  /// the crack.
  Crack(double x_start, double x_tip, double spacing, const law::TractionLaw& law,
        double split_offset = 0);

  double tip() const { return particles_.back().X; }
  const std::vector<CrackParticle>& particles() const { return particles_; }
  const std::vector<CrackSegment>& segments() const { return segments_; }
  const law::TractionLaw& law() const { return law_; }

  /// Field split at the nodes (CRAMP with the split decided per node): does a node on side
  /// `node_side` of the crack plane, at x = xn, carry a separate velocity field for a particle of
  /// side `particle_side`? Yes when the two sides differ and the node's column lies on the crack,
  /// from its start up to the last split column, `split_offset` behind the tip (the DCB model
  /// puts the tip on a node column and the last split column one cell behind it).
  ///
  /// Why per node and not per particle-node line (Nairn's CRAMP test): with the line test a node
  /// column at the tip gets a separate field from the face particles behind the tip only, while
  /// the face particles ahead of the tip share the node's other field. That field is then an end
  /// of the face layer with nothing ahead of it, so the face layer's stress parallel to the crack
  /// (bending sigma_xx, which a cut along x must not release) pulls it back at every advance. The
  /// recoil leaves a strain in the face particles that no later velocity gradient undoes (their F
  /// no longer matches their displacements): the face row stopped carrying bending, the arms
  /// became too compliant and the released energy 15-20 % too low. With the split per node, the
  /// separate field at a split column takes the face particles on both sides of it, so the face
  /// layer stays continuous and a cut releases only sigma_yy and sigma_xy.
  ///
  /// Why one cell behind the tip: the cell ahead of the last split column is partly separated
  /// (its particles share the split fields of its rear column). With the tip at the split column
  /// that cell opened before any crack segment covered it, a new bridging segment started its law
  /// from zero when the material there was already open by a quarter of delta_c (linear-softening
  /// verification run) and the zone did a fifth less work. With the tip one cell ahead, the
  /// segments cover that cell before it opens; the crack's end (where J is taken) then also lies
  /// where the material separates (stationary compliance within 3.5 % of beam theory).
  bool splits(int particle_side, double xn, int node_side) const {
    return particle_side != node_side && xn <= tip() - split_offset_ + tolerance_ &&
           xn > particles_.front().X;
  }
  /// Adds a crack particle at x_new (> tip) and a fresh bridged segment (delta_max = 0) between it
  /// and the old tip. The new particle's surfaces start at the material displacement there
  /// (ux, uy): zero opening. The DCB model moves the tip from node column to node column and
  /// adds a crack particle every half cell on the way.
  void advance(double x_new, double ux, double uy);

  /// Openings of all segments from the surfaces, then the law with history (explicit: the
  /// traction of this step acts on the next one). Contact in closing is handled at the nodes,
  /// so the law's contact penalty is not used here.
  void update_tractions();
  /// Adds the traction of every bridged segment to the grid: half of sigma * length * thickness
  /// at each end, pulling the above surface down and the below surface up, spread with linear
  /// weights over the nodes where that side's field has mass.
  void add_traction_forces(Grid& grid, double thickness) const;
  /// Moves each surface with its own side's new nodal velocity.
  void move_surfaces(const Grid& grid, double dt);

  /// Index of the trailing (root-most) bridged segment that has not failed, or -1.
  int root_segment() const;
  /// Energies of the zone per unit width times `thickness` [J]: elastic part sum sigma delta/2
  /// (recovered on unloading to the origin) and the dissipated remainder of the law's area.
  double zone_recoverable(double thickness) const;
  double zone_dissipated(double thickness) const;
  /// Work done by the explicit tractions on the opening, sum of sigma_n (delta_n+1 - delta_n)
  /// over steps and segments, per unit width [J/m]. Below the law's energy (zone_recoverable +
  /// zone_dissipated) by the law's work from zero to the opening a segment reads at its birth
  /// (half the tip particle's, see advance()), which no traction paid: measured 4 % of the zone
  /// energy in the linear-softening verification run; the explicit lag adds 0.2 %.
  double traction_work() const { return traction_work_; }
  /// Largest |mean surface y| over the crack [m] (symmetry diagnosis).
  double max_plane_offset() const;

  /// Crack particles, segments with their history, and the traction work, bit for bit
  /// (checkpoints, mpm/checkpoint.h).
  void save_state(BinaryWriter& out) const;
  void load_state(BinaryReader& in);

private:
  std::vector<CrackParticle> particles_;
  std::vector<CrackSegment> segments_;
  const law::TractionLaw& law_;
  bool law_bridges_;
  double tolerance_;    ///< position tolerance of the node-column test [m]
  double split_offset_; ///< distance from the tip back to the last split node column [m]
  double traction_work_ = 0;
};

} // namespace fiberbridge::mpm
