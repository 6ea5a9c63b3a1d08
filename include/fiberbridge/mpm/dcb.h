#pragma once
// The DCB specimen in explicit MPM: two arms joined ahead of an explicit mid-plane crack, opened by
// a slow prescribed velocity at the load line; the tip grows by a fixed step whenever its J
// reaches J_tip and leaves a fresh bridging segment behind (docs/design.md section 2, "MPM").
#include "fiberbridge/law/traction_law.h"
#include "fiberbridge/mpm/crack.h"
#include "fiberbridge/mpm/explicit_solver.h"
#include "fiberbridge/mpm/growth_criterion.h"
#include "fiberbridge/mpm/orthotropic_elastic.h"
#include "fiberbridge/mpm/parameters.h"
#include "fiberbridge/mpm/vtu_writer.h"
#include "fiberbridge/result/rcurve.h"
#include "fiberbridge/specimen/specimen.h"

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace fiberbridge::mpm {

/// The checks DcbModel makes before it builds anything (parameters, specimen, material, at least
/// two cells through an arm, room for the tip to grow before the end ligament, and with `law`
/// given the elastic rise of a rigid law), so that a scene can make them before its first item
/// runs. Throws InputError naming the section and key.
void check_dcb_inputs(const specimen::Specimen& specimen, const specimen::Material& material,
                      const MpmParameters& params, const law::TractionLaw* law);

/// The specimen model: body, crack, loading block and tip criterion. run() is simulate_dcb;
/// step() lets tests load the specimen without growth and read its fields.
class DcbModel {
public:
  DcbModel(const specimen::Specimen& specimen, const specimen::Material& material,
           const law::TractionLaw& law, double j_tip, const MpmParameters& params,
           const std::string& output_dir = "",
           const std::function<void(const std::string&)>& progress = {});

  /// Load, step and grow until a stop condition; then the R curve and its summary.
  result::SimulationResult run();
  /// One time step of the loading; with `grow` the tip is checked (every few steps) and
  /// advanced. False once a stop condition holds (reason in stop_reason()).
  bool step(bool grow);

  /// Load for the whole width [N] (moving average of the load-block reaction).
  double load() const { return load_; }
  /// Total opening of the load line [m].
  double load_point_opening() const { return opening_; }
  double tip_j() const;
  /// Far-field J around the whole zone [J/m^2] (seed Eq. 1's left side); NaN when the strips do
  /// not fit in the specimen.
  double far_field_j() const;
  /// First-mode period of an arm of length a0 and the opening rate the loading uses.
  double vibration_period() const { return t_vib0_; }
  double opening_rate() const { return rate_; }
  const ExplicitSolver& solver() const;
  const Crack& crack() const;
  const std::string& stop_reason() const { return stop_reason_; }

  /// Checkpoints (mpm/checkpoint.h, docs/design.md section 5): writes the whole state that
  /// carries from one step to the next to checkpoint_path(output_dir) atomically. run() calls it
  /// every MpmParameters::checkpoint_interval seconds; tests call it between steps.
  void write_checkpoint() const;
  /// Continues from the checkpoint in the output directory, if there is one: true when the state
  /// was restored. Throws InputError naming the file when it cannot be used, and naming the
  /// input (e.g. "MPM/Cell size") when the checkpoint was written for other inputs. run() calls
  /// it at its start when MpmParameters::resume is set.
  bool resume_from_checkpoint();
  /// The inputs the result depends on, as (scene key, value) pairs; a checkpoint is tied to them.
  std::vector<std::pair<std::string, std::string>> inputs() const;

private:
  void choose_law();
  void setup_body();
  void setup_loading();
  double opening_rate(double t) const;
  void advance_tip(double j_measured);
  void set_growth_window();
  /// The method lines, the run's diagnoses and the shared post-processing (dcb_report.cc).
  void finish(result::SimulationResult& r) const;

  specimen::Specimen spec_;
  specimen::Material mat_;
  const law::TractionLaw& user_law_;
  double j_tip_;
  MpmParameters prm_;
  std::string out_dir_;
  std::function<void(const std::string&)> progress_;
  OrthotropicElastic elastic_;

  const law::TractionLaw* law_ = nullptr; ///< the law the crack segments use
  std::unique_ptr<Crack> crack_;
  std::unique_ptr<ExplicitSolver> solver_;
  std::unique_ptr<ParticleVtuWriter> vtu_;
  double cell_ = 0, step_ = 0, opening_allowance_ = 0, end_tip_ = 0;
  double a0_ = 0; ///< initial tip: the node column nearest to the sawn crack's end [m]
  double rate_ = 0, ramp_time_ = 0, t_vib0_ = 0;
  double opening0_ = 0; ///< LEFM initiation opening of the load line (beam theory) [m]
  int n_check_ = 1;     ///< steps between tip J evaluations
  std::unique_ptr<GrowthCriterion> growth_; ///< when the tip advances
  std::vector<std::string> notes_;
  std::string stop_reason_;

  double opening_ = 0, load_ = 0;
  std::vector<result::RCurvePoint> rcurve_;
  double max_kinetic_ratio_ = 0;

  bool resumed_ = false;            ///< the state came from a checkpoint
  double earlier_wall_seconds_ = 0; ///< wall time of the sessions before the checkpoint [s]
  /// Wall time of this session so far [s] (0 outside run()).
  double session_seconds() const;
  bool running_ = false;
  std::chrono::steady_clock::time_point session_start_;
};

/// Runs the specimen until the ligament ends (or steady growth as set in `params`). One
/// RCurvePoint per accepted tip advance. `output_dir` empty = no files (else particle VTU every
/// params.vtu_every_advances advances, with a .pvd). `progress` receives one line per advance.
/// Throws InputError for unusable parameters and ComputationError with a diagnosis when the
/// run becomes unstable.
result::SimulationResult simulate_dcb(const specimen::Specimen& specimen,
                                      const specimen::Material& material,
                                      const law::TractionLaw& law, double j_tip,
                                      const MpmParameters& params, const std::string& output_dir,
                                      const std::function<void(const std::string&)>& progress = {});

/// First-mode period of a cantilever arm of length a (Euler-Bernoulli, clamped-free):
/// t_vib = 1.787 a^2 sqrt(rho B h / (E_L I)), I = B h^3/12, h the arm thickness [s].
double arm_vibration_period(const specimen::Specimen& specimen, const specimen::Material& material,
                            double a);

} // namespace fiberbridge::mpm
