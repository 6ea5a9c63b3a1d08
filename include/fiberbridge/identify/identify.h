#pragma once
// The bridging law identified from test records without a measured notch-root opening (the
// seed's "second approach", docs/verification.md, "Identify"): the trilinear law (d1, s1, d2, s2,
// delta_c) and J_tip for which the beam model of the specimen reproduces the measured
// load-opening and crack-length-opening curves. The optimizer is NLopt's bounded derivative-free
// BOBYQA (or SBPLX); the uncertainties come from the finite-difference Jacobian of the weighted
// residuals at the optimum.
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/beam/dcb_beam.h"
#include "fiberbridge/identify/forward_model.h"
#include "fiberbridge/law/piecewise_linear_law.h"
#include "fiberbridge/specimen/specimen.h"

#include <functional>
#include <string>
#include <vector>

namespace fiberbridge::identify {

struct IdentifySettings {
  /// Bounds of the search [m], [Pa], [J/m^2].
  double delta_c_min = 0.2e-3, delta_c_max = 40e-3;
  double stress_max = 20e6;
  double j_tip_min = 20, j_tip_max = 3000;
  /// Expected scatter of the measurements: the residuals are divided by it, so that the misfit
  /// is a chi^2 and the Jacobian gives parameter uncertainties. Load: relative to the record's
  /// peak load; crack readings: [m].
  double load_scatter = 0.02;
  double crack_scatter = 1e-3;
  /// Calibrate the arm modulus E_L from each record's initial compliance (else the quoted one).
  bool calibrate_modulus = true;
  /// The initial compliance is the slope over the rows before the crack grows (readings within
  /// 3 crack_scatter of a0) whose load lies between these fractions of the record's peak load.
  double compliance_low = 0.1, compliance_high = 0.5;
  /// Map the beam's small-rotation states onto arms that rotate far with ISO 15024's F and N
  /// (with_large_displacements below; l1 = half the arm thickness: hinges).
  bool large_displacement = true;
  /// NLopt: "bobyqa" or "sbplx"; evaluations per start; starts (different delta_c guesses).
  std::string algorithm = "bobyqa";
  int max_evaluations = 300;
  int starts = 2;
  double relative_tolerance = 1e-4; ///< on the objective, per start
  /// Forward model settings (coarser than the Beam section's defaults: the misfit is
  /// smooth enough at 1 mm steps, see docs/verification.md).
  beam::BeamParameters beam = [] {
    beam::BeamParameters b;
    b.n_elements = 160;
    b.tip_advance = 1e-3;
    return b;
  }();
  /// Start the optimizer from this law and J_tip (one start, a small first step) instead of the
  /// starts from the records' corrected-beam-theory estimates: for a costly forward model started
  /// at the beam's identification (docs/design.md section 6, "Forward model of identify").
  /// start_j_tip 0: not set.
  law::TrilinearParameters start_law{};
  double start_j_tip = 0;
  /// Throws InputError naming `context`/<key> for an unusable value.
  void validate(const std::string& context = "Identify") const;
};

/// One record as the identified model reproduces it.
struct RecordFit {
  std::string name;
  double initial_crack = 0;      ///< a0 [m]
  double initial_compliance = 0; ///< measured [m/N]
  double E_L = 0;                ///< modulus used for this record (calibrated or quoted) [Pa]
  double peak_load = 0;          ///< [N]
  double load_rms_rel = 0;       ///< RMS of (P_model - P) over the rows, / peak load
  double crack_rms = 0;          ///< RMS of (a_model - a) over the crack-reading rows [m]
  double max_opening_over_a = 0; ///< largest delta/a of the record (large-rotation measure)
  double min_F = 1;              ///< smallest ISO 15024 F over the rows
  std::vector<double> opening, load, crack_length;    ///< the record's rows
  std::vector<double> model_load, model_crack_length; ///< the model at those openings
};

struct ParameterEstimate {
  std::string name; ///< d1_mm, sigma1_kPa, d2_mm, sigma2_kPa, delta_c_mm, J_tip_J_m2
  double value = 0; ///< in the unit of its name
  double std_error = 0;
};

struct Identification {
  law::TrilinearParameters law; ///< SI
  double j_tip = 0;             ///< [J/m^2]
  double g_ss = 0;              ///< J_tip + area of the law [J/m^2]
  double j_c_std_error = 0;     ///< [J/m^2]
  std::vector<RecordFit> records;
  double load_rms_rel = 0; ///< over all rows of all records
  double crack_rms = 0;    ///< [m], over all crack readings
  double chi2 = 0;         ///< sum of squared weighted residuals at the optimum
  std::size_t n_residuals = 0;
  int evaluations = 0;       ///< forward evaluations of the misfit (each runs every record)
  int forward_runs = 0;      ///< beam runs, including the Jacobian's
  double forward_time_s = 0; ///< time inside the beam model
  double wall_time_s = 0;
  std::vector<ParameterEstimate> parameters;
  std::vector<std::vector<double>> correlation;
  std::vector<std::string> notes; ///< unidentifiable combinations, optimizer stops, ...
  /// The law with its one-standard-error band on a grid [m], [Pa].
  std::vector<double> band_delta, band_sigma, band_lo, band_hi;
};

/// The initial compliance of a record (slope of opening over load on the initial linear rows,
/// see IdentifySettings) [m/N]. Throws InputError naming the record if too few rows qualify.
double initial_compliance(const analysis::TestRecord& record, const IdentifySettings& settings);

/// The E_L for which corrected beam theory (which the beam model reproduces) has compliance C at
/// crack length a (other constants as in `material`).
double modulus_for_compliance(const specimen::Specimen& specimen,
                              const specimen::Material& material, double compliance);

/// A beam run mapped onto openings as a displacement-controlled test sees it: before the first
/// state the linear compliance at a0, then the states whose load-point opening exceeds every
/// earlier one (a snap-back is passed in a jump), linear in between, the last state beyond.
void model_at_openings(const result::SimulationResult& run, const std::vector<double>& opening,
                       std::vector<double>& load, std::vector<double>& crack_length);

/// Maps a geometrically linear run onto arms that rotate far, in place, with ISO 15024's F and N
/// (l1 = arm thickness / 2, no end blocks): at each state's crack length a the energy release
/// rate is G = 3 P delta F / (2 B a N) and the compliance (2 a^3/(3 EI)) N (both checked against
/// the exact elastica, tests/analysis/record_reduction_tests.cc), so the state that releases the
/// same G at the same a carries P / sqrt(F) at the opening delta N / sqrt(F). Returns the
/// smallest F.
double with_large_displacements(result::SimulationResult& run, double arm_thickness);

/// A job of an identification: one independent piece of forward runs (an optimizer start, a
/// polish round, a Jacobian column's perturbed run), its result serialized to bytes.
using IdentifyJob = std::function<std::string(std::size_t)>;

/// How an identification runs its independent jobs: job(i) for every i in [0, n), the results
/// returned in job order. `what` names the batch ("starts", "polish", "jacobian") for a log.
/// The jobs only read shared state, so a runner may run them in any order, on any process that
/// called identify_law with the same arguments (the app spreads them over MPI ranks,
/// app/run/task_distributor.h); every caller must get every result. Collective when the runner is.
/// An empty runner runs them one after the other, in order (serial_jobs).
using IdentifyJobRunner = std::function<std::vector<std::string>(
    const std::string& what, std::size_t n, const IdentifyJob& job)>;

/// The default runner: job(0), job(1), ... in this process.
std::vector<std::string> serial_jobs(const std::string& what, std::size_t n,
                                     const IdentifyJob& job);

/// Identifies one law and J_tip from the records jointly. `specimen` gives width, height and
/// length; each record's a0 is its first crack reading. A record without crack readings
/// (crack_length empty) is fitted on load and opening alone, with `specimen`'s initial crack as
/// its a0 (docs/design.md section 6, "R without crack readings"). `progress` gets occasional lines.
/// `run_jobs` runs the independent forward runs (the optimizer starts, each polish round, the
/// Jacobian's perturbed runs); the result is the same, bit for bit, whatever runner runs them
/// where (each job's result crosses as raw bytes and the merge follows the serial order).
/// `forward` runs each trial law (forward_model.h); empty (no `run`): the beam with
/// settings.beam.
Identification identify_law(const std::vector<analysis::TestRecord>& records,
                            const specimen::Specimen& specimen, const specimen::Material& quoted,
                            const IdentifySettings& settings,
                            const std::function<void(const std::string&)>& progress = {},
                            const IdentifyJobRunner& run_jobs = {},
                            const ForwardModel& forward = {});

} // namespace fiberbridge::identify
