#pragma once
// Parameters of the explicit MPM model of the DCB specimen (docs/design.md section 2, "MPM").

#include <string>
#include <vector>

namespace fiberbridge::mpm {

struct MpmParameters {
  /// Edge of the square background-grid cells [m].
  double cell_size = 2.5e-3;
  /// Particles per cell along each axis (2 gives 4 particles per cell).
  int particles_per_cell = 2;
  /// Time step as a fraction of the time a dilatational wave needs to cross one cell.
  double cfl = 0.5;
  /// PIC damping beta: v_p <- (1 - beta) v_FLIP + beta v_PIC. A tip advance of a whole cell
  /// releases its energy at once; with 0.1 the arms still rang at the next growth checks, the tip
  /// grew on the peaks of the ringing and the released energy per area came out 10 % low (LEFM
  /// verification run); 0.5 removes it within the J window (measured: R_energy at the value a
  /// one-cell step releases quasi-statically).
  double pic_fraction = 0.5;
  /// Quasi-static loading: the load line reaches the LEFM initiation opening of corrected beam
  /// theory after this many first-mode vibration periods of an arm of length a0.
  double loading_periods = 8;
  /// The opening rate rises smoothly from zero over this many vibration periods (no shock).
  double ramp_periods = 2;
  /// Tip growth step in whole cells (MPM/Tip advance in mm, rounded; the old MPM/Growth step
  /// counted cells): the tip moves from node column to node column, because the velocity fields
  /// split per node (Crack::splits); a step shorter than a cell would change nothing the grid
  /// sees. The released segment gets crack particles every half cell.
  int growth_step_cells = 1;
  /// The growth criterion compares the tip J averaged over this many periods of the arm at the
  /// current crack length with J_tip; the window restarts at each advance, so the tip grows at
  /// most one step per window, and DcbModel shortens it to 0.7 of the time the loading needs to
  /// drive the tip one step (beam theory) so that the tip keeps up. Why 0.25 and the cap of 0.7,
  /// against a window fixed at the a0 period (the earlier rule, which averaged less and less of
  /// the ringing as the crack grew): docs/verification.md, "MPM growth window".
  double j_window_periods = 0.25;
  /// The tip J domain: q = 1 within this many cells of the tip, falling to 0 two cells farther.
  double tip_j_cells = 2;
  /// Notes for the run on deprecated keys met by the scene reader (MPM/Rigid law rise fraction:
  /// rigid laws are inserted extrinsically in every model, law/rigid_law.h; the old names
  /// MPM/Growth step and MPM/End ligament).
  std::vector<std::string> deprecation_notes;
  /// Stop once the uncracked ligament is shorter than this [m] (MPM/Minimum ligament, formerly
  /// MPM/End ligament); 0 selects the specimen height (a shorter ligament no longer behaves like a
  /// DCB and its J is no longer Eq. 1's).
  double end_ligament = 0;
  /// Steady state (the shared rule, result::find_steady_state, evaluated on the whole run): after
  /// the root moved, R_J stays within `plateau_tolerance` over at least this much growth [m].
  double steady_state_window = 10e-3;
  /// Relative spread (max - min over mean) of R_J accepted as a plateau. Wider than the FEM's
  /// 1 %: the MPM's R_J scatters with the arm's ringing (+-1 %) and drifts by a percent as the
  /// tip nears the end ligament; the linear-softening verification run (tests/mpm) spreads
  /// 2.4 % over its 45 mm after the root moved.
  double plateau_tolerance = 0.03;
  /// Stop after the notch root has moved this far (m) in steady state; 0 = run to the end.
  double steady_growth = 0;
  /// Safety bound on the number of time steps.
  long max_steps = 20'000'000;
  /// Threads of the particle loops (the solver's own team, work_team.h). Two by default: the
  /// solver times steps with and without the helper and keeps the faster (on cores busy with
  /// other processes one thread wins), and the results are the same for any number of threads.
  int threads = 2;
  /// Write a particle VTU every this many tip advances (0 = none).
  int vtu_every_advances = 20;

  // Run control (no effect on the result): checkpoints that `fiberbridge run --resume` continues
  // from (mpm/checkpoint.h).
  /// Wall time between checkpoints of the whole state into the output directory [s]; 0 = none.
  /// A checkpoint of the 2.5 mm seed DCB is a few MB and takes milliseconds to write.
  double checkpoint_interval = 60;
  /// Continue from the output directory's checkpoint when there is one (else start afresh);
  /// without it a run removes any checkpoint it finds there.
  bool resume = false;

  /// Throws InputError naming the "MPM/<entry>" that is out of range.
  void validate() const;
};

} // namespace fiberbridge::mpm
