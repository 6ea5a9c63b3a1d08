#pragma once
// The measuring chain's bias, removed by simulating the test it measured (docs/design.md section 6,
// "The chain corrected by simulation"; docs/verification.md, "Where sigma1's bias comes from").
//
// Seed Eq. 5/6 inverts R(delta_root) as seed Eq. 2 writes it, with the zone's recoverable energy
// delta_root sigma(delta_root)/2. What a test measures is the rate of the energy dissipated over
// the whole zone. In a DCB whose zone is long next to the arms the two differ while the zone
// develops: on the PRF law the FEM's and the beam's exact dissipation rates rise 6 % faster than
// Eq. 2 between 0.1 and 0.9 mm, and the law extracted from them has sigma1 and sigma2 3-5 % high.
// The records' windows add their own part. The correction runs the same chain on simulated
// records: a candidate law p is simulated (the beam, with the records' openings and crack
// reading rows), the chain gives C(p), and p is moved by what the chain added,
//   p_{k+1} = p_k + (C_measured - C(p_k)),
// until C(p) reproduces what the chain gave on the records (indirect inference with the chain
// as its own statistic). The fixed point is the law whose measured image is the measurement.
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/identify/forward_model.h"
#include "fiberbridge/law/piecewise_linear_law.h"
#include "fiberbridge/specimen/specimen.h"

#include <functional>
#include <string>
#include <vector>

namespace fiberbridge::identify {

/// What the chain gives and the correction moves: the trilinear law and J_tip (SI).
struct ChainEstimate {
  law::TrilinearParameters law;
  double j_tip = 0;
};

/// The measuring chain from records on: reduce, R(delta_root), Eq. 6, the trilinear fit, with the
/// scene's own settings. May throw (a simulated record without a steady state, a fit that fails).
using MeasuringChain = std::function<ChainEstimate(const std::vector<analysis::TestRecord>&)>;

struct ChainCorrectionSettings {
  int max_iterations = 8;
  /// Converged when C(p) matches the measured estimate within this fraction of each parameter
  /// (J_tip of itself, stresses of the larger stress, openings of delta_c). 1 %: the chain's
  /// automatic windows, hinge and delta_c move its estimate in steps as the law changes, and on
  /// the chain study the iterates settle 0.4-0.9 % from the records' estimate (3 % where delta_c
  /// flips between two plateau choices); a tenth of the 10-12 % the recovery is held to.
  double tolerance = 1e-2;
};

struct ChainCorrection {
  ChainEstimate measured;  ///< the chain on the records
  ChainEstimate corrected; ///< the fixed point (valid when converged)
  struct Step {
    ChainEstimate simulated; ///< the law simulated
    ChainEstimate measured;  ///< the chain on its simulated records
    double mismatch = 0;     ///< largest relative difference from the measured estimate
  };
  std::vector<Step> steps;
  bool converged = false;
  std::vector<std::string> notes;
  int forward_runs = 0;
  double forward_time_s = 0;
  std::string forward_model = "beam"; ///< the ForwardModel's name: what simulated the records
};

/// The records a test of `sim` would have written, row by row at `measured`'s openings (and
/// times): load, crack length (only on the rows where `measured` has a reading; at the largest
/// opening so far, as a crack does not heal), delta_root (where
/// `measured` has it), each linear in the opening between the simulation's states. The machine
/// never unloads: through a snap-back it holds the largest opening while the load drops to the
/// returning branch's state at that opening. Before the first critical state the specimen is
/// elastic: load and opening from the origin. Rows past the simulation's last opening are dropped
/// (a note says how many). Throws ComputationError when the simulation has no critical state.
analysis::TestRecord simulated_record(const analysis::TestRecord& measured,
                                      const result::SimulationResult& sim,
                                      std::vector<std::string>& notes);

/// The fixed point above. `specimens` (one per record) and `material` are the tests'; each
/// record's a0 is its first crack reading where it has one. Never throws for a simulation or a
/// chain that fails on a candidate: the correction then stops, says why in `notes`, and
/// `converged` is false.
ChainCorrection correct_chain(const std::vector<analysis::TestRecord>& records,
                              const std::vector<specimen::Specimen>& specimens,
                              const specimen::Material& material, const ChainEstimate& measured,
                              const MeasuringChain& chain, const ForwardModel& model,
                              const ChainCorrectionSettings& settings = {});

} // namespace fiberbridge::identify
