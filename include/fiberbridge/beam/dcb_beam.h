#pragma once
// The fast beam model of the DCB with a bridging zone (docs/design.md section 2, "Beam model").
//
// One arm by symmetry (the crack plane is the symmetry line, opening delta = 2 w): a Timoshenko
// beam from the load line x = 0 to the far end x = L. The sawn notch [0, a0] is free; behind the
// tip the arm carries the bridging traction sigma(delta - delta_0) with damage history
// (TractionLaw::respond); ahead of the tip the intact ligament is a Winkler foundation of modulus
// k (calibrated to corrected beam theory, see arm_on_foundation.h).
//
// Tip criterion: the tip advances when its J reaches J_tip. In the continuum model that J is the
// foundation energy per area at the tip, k delta_tip^2/2 (removing a Winkler spring at fixed
// grip releases its energy; Kanninen's G), so the intact ligament at the tip has opened
// delta_0 = sqrt(2 J_tip/k) elastically, and the crack opening the bridging law sees is what opens
// beyond that, delta - delta_0: the law starts from zero opening at the tip, as in the continuum,
// and Eq. 1 holds exactly for the model. In the discrete model the criterion is evaluated as the
// section J (energy-momentum invariant) of the element just behind the tip, less the bridging
// potential there: that is the energy the discrete model releases (its energy balance closes to
// 1e-5), whereas k delta_tip^2/2 at the tip node carries the O(h_e^2) lumping error of the
// foundation (0.23 % at 400 elements); it is reported in the J_tip column as the second measure.
//
// The path is traced under crack-length control: for each tip position the load-point opening is
// an unknown and the tip J is held at J_tip, so every recorded state is an equilibrium at the
// propagation criterion, including snap-back. Where the load-point opening decreases between
// advances a displacement-controlled test would grow the crack unstably over those advances
// (several advances in one load step); the result notes where.
#include "fiberbridge/law/traction_law.h"
#include "fiberbridge/result/rcurve.h"
#include "fiberbridge/specimen/specimen.h"

#include <functional>
#include <string>
#include <vector>

namespace fiberbridge::beam {

struct BeamParameters {
  /// Elements along the ligament [a0, L] (the free notch is one exact element).
  int n_elements = 400;
  /// Crack growth between recorded states [m]; rounded to a whole number of elements (>= 1).
  double tip_advance = 0.5e-3;
  /// Foundation modulus on the opening [Pa/m]; 0 = calibrated to corrected beam theory.
  double foundation_modulus = 0;
  /// Timoshenko shear coefficient of the rectangular arm.
  double shear_coefficient = 5.0 / 6.0;
  /// Stop when the ligament ahead of the tip is shorter than this [m]; 0 = the specimen height
  /// (the beam-on-foundation picture needs a ligament longer than the section it bends).
  double minimum_ligament = 0;
  /// Steady state (the shared rule, result::find_steady_state): after the root moved, R_J stays
  /// within `plateau_tolerance` over at least this much tip growth [m]; G_ss is its mean there.
  double steady_state_window = 10e-3;
  /// Relative spread (max - min over mean) of R_J accepted as a plateau.
  double plateau_tolerance = 0.005;
  /// Newton: converged when the residual force is below this times the initiation load (or at
  /// its round-off floor) and the tip condition holds to this relative tolerance.
  double newton_tolerance = 1e-10;
  int max_newton_iterations = 40;
  /// Notes for the run on deprecated keys met by the scene reader (Beam/Newton iterations, the
  /// old name of Beam/Maximum Newton iterations).
  std::vector<std::string> deprecation_notes;
  /// Run on to this crack length [m] instead of stopping at steady state (0 = stop at steady
  /// state): a test record goes on growing the crack past the plateau, and a model compared with
  /// it must too. Steady state is still detected and G_ss reported.
  double final_crack_length = 0;
  /// Stop after this many recorded advances even if the ligament is long (safety net).
  int max_advances = 100000;
  /// Finite rotations of the free arm (Beam/Kinematics = finite): the load and the load-point
  /// opening of each state come from the elastica of the arm between load line and tip
  /// (elastica.h) under the small-rotation state's bridging forces, with the load that keeps the
  /// ligament's tip deflection (so the tip J) through its semi-infinite end flexibility. The
  /// ligament, the bridging openings, R_J and J_ff stay those of the small-rotation state.
  bool finite_rotations = false;

  void validate(const std::string& context = "Beam") const;
};

/// The checks simulate_dcb makes before it solves anything (specimen, material, parameters, a
/// ligament longer than the minimum ligament), so that a scene can make them before its first item
/// runs. Throws InputError naming the section and key.
void check_dcb_inputs(const specimen::Specimen& specimen, const specimen::Material& material,
                      const BeamParameters& parameters);

/// Runs the crack from the notch (tip and root at a0) until steady state or the ligament runs
/// out. Steady state: the shared rule (result::find_steady_state): after the root moved, R_J flat
/// within `plateau_tolerance` over `steady_state_window` of growth; G_ss is then its mean. If the
/// ligament runs out first the notes say so; G_ss is then the mean R_J after the root moved (flag
/// false), or NaN if the root never moved (zone longer than the ligament allows) or the zone is
/// shorter than four tip advances (unresolved: the note says how far to refine). One RCurvePoint
/// per recorded advance with every field except kinetic energy and time (static model). `progress`
/// gets occasional one-line messages. n_dofs_or_particles is the number of beam elements. Throws
/// InputError for unusable input, ComputationError if not even the initiation state can be solved
/// (a later Newton failure ends the curve there with a note).
///
/// Accuracy (seed specimen, 400 elements): second order in the element size throughout; LEFM load
/// within 0.006 % of CBT, R_J within 0.06 J/m^2 of Eq. 2 for the PVA law, energy balance 3e-5.
result::SimulationResult simulate_dcb(const specimen::Specimen& specimen,
                                      const specimen::Material& material,
                                      const law::TractionLaw& law, double j_tip,
                                      const BeamParameters& parameters,
                                      const std::function<void(const std::string&)>& progress = {});

} // namespace fiberbridge::beam
