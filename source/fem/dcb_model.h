#pragma once
// The FEM model of the DCB (distributed_dcb.h, dcb_simulation.h): one dim-templated engine on a
// parallel::distributed::Triangulation with Trilinos MPI matrices and vectors; on one rank
// (MPI_COMM_SELF) it is the serial program, as in deal.II's step-40 (docs/design.md section 2,
// "One engine"). Definitions in dcb_model.templates.h, instantiated in dcb_model_2d.cc and
// dcb_model_3d.cc. The pieces it drives have files of their own: dcb_geometry.h (the slit
// mesh), crack_plane.h (ties, release, the interface), jacobian_solver.h (the linear solver
// strategy), equilibrium_problem.h (Newton and KINSOL), j_integrals.h, field_output.h.
#include "condensed_solver.h"
#include "crack_plane.h"
#include "dcb_geometry.h"
#include "equilibrium_problem.h"
#include "field_output.h"
#include "j_integrals.h"
#include "jacobian_solver.h"
#include "virtual_dic.h"

#include "fiberbridge/fem/dcb_common.h"
#include "fiberbridge/fem/distributed_dcb.h"

#include <deal.II/base/index_set.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <functional>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace fiberbridge::fem {

template <int dim>
class DcbModel : private EquilibriumProblem, private JacobianSystem {
public:
  DcbModel(const specimen::Specimen& specimen, const specimen::Material& material,
           const law::TractionLaw& law, double j_tip, const FemParameters& parameters,
           const std::string& output_dir, const std::function<void(const std::string&)>& progress,
           MPI_Comm comm);
  /// The algorithm: set up, then load to critical, record, release, re-equilibrate until
  /// steady state or the end of the ligament.
  result::SimulationResult run();
  const DistributedRunInfo& info() const { return info_; }
  const FemRunDetails& details() const { return details_; }

private:
  // Setup.
  void setup_dofs();
  void assemble_bulk();
  void make_constraints(double opening, dealii::AffineConstraints<double>& c) const {
    crack_.make_constraints(opening, relevant_, c);
  }
  // EquilibriumProblem.
  /// Zero, on u_'s layout (its Epetra map is shared, not built again from owned_: Newton asks
  /// for five vectors per solve).
  void reinit_vector(Vec& v) const override { v.reinit(u_, false); }
  MPI_Comm communicator() const override { return comm_; }
  double n_dofs() const override { return double(dof_handler_.n_dofs()); }
  void residual(const Vec& u, Vec& r, Vec& r_full) override;
  double reaction_norm(const Vec& r_full) const override;
  double norm(const Vec& v) const override { return broadcast_norm(v, comm_); }
  void setup_jacobian(const Vec& u) override;
  void note_contraction(double ratio) override { last_contraction_ = ratio; }
  void solve_jacobian(const Vec& rhs, Vec& x) override;
  double roundoff_floor(const Vec& u) const override;
  std::string contact_summary() override;
  // JacobianSystem.
  void assemble_jacobian(const std::vector<double>& tangents,
                         dealii::TrilinosWrappers::SparseMatrix& jacobian) override;
  void opening_operator(unsigned p, Vec& c) override;
  const dealii::IndexSet& owned_dofs() const override { return owned_; }
  /// What FEM/Linear solver = condensed reads (condensed_solver.h).
  CondensedArms condensed_arms() const;
  // Algebra.
  double gsum(double local) const { return broadcast_sum(local, comm_); }
  void condense(const Vec& full, Vec& out);
  void predict(double opening);
  void solve_at(double target);
  /// FEM/Linear solver = condensed: Newton on the crack-plane unknowns from u_
  /// (condensed_solver.h). Returns the settings newton_solve() then checks u_ with and, where the
  /// crack-plane Newton stopped short, goes on with (what is left of the budget).
  NonlinearSettings crack_plane_step(const NonlinearSettings& settings);
  void sync() { u_ghost_ = u_; }
  // Growth.
  bool load_to_critical();
  bool load_to_critical_by_opening();
  void release_tip();
  /// Re-equilibrates after a release at fixed load-point opening; where that fails, switches
  /// to the crack-tip opening control (docs/design.md section 2, "Crack-tip opening control").
  void re_equilibrate(double stored_before, const Vec& u_before, double load_before);
  // Crack-tip opening control: the opening of the node next behind the tip is prescribed and
  // the load-point opening is an unknown (a bordered Newton).
  void switch_to_tip_control(const std::string& failure);
  [[noreturn]] void fail_under_tip_control(const std::string& what) const;
  unsigned control_station() const { return crack_.tip_station() - 1; }
  double control_opening();
  bool load_to_critical_at_tip();
  void solve_at_tip_opening(double eta);
  bool bordered_newton(const Vec& c, const Vec& e, double eta, std::string& diagnosis);
  void account_release();
  void note_snap_back();
  // Measurements (on u_ghost_).
  std::vector<double> openings() const { return crack_.openings(u_ghost_); }
  double domain_j(const Ramp& q, bool crack_face_term) const;
  double crack_face_j(const Ramp* ramp) const {
    return crack_.crack_face_integral(ramp, u_ghost_) / width_;
  }
  double tip_j() const;
  /// tip_j() in the "J integrals" section.
  double timed_tip_j() {
    const dealii::TimerOutput::Scope timed(timer_, "J integrals");
    return tip_j();
  }
  double far_field_j() const;
  double bulk_energy() const; ///< per width [J/m]
  /// FEM/Kinematics = finite: adds the internal forces at u_ghost to `forces` and the cell
  /// tangents to `jacobian` (condensed with hom_) where given; returns this rank's strain energy.
  double finite_bulk(const Vec& u_ghost, Vec* forces,
                     dealii::TrilinosWrappers::SparseMatrix* jacobian) const;
  double stored_energy() const;
  double load_per_width();
  result::RCurvePoint record_advance();
  /// The shared rule (result::find_steady_state) on the advances so far: the run stops once it
  /// holds. The rule is reported by result::finish_rcurve at the end of run().
  bool reached_steady_state() const;
  void output_fields(unsigned advance);
  /// The run's closing notes, method lines and figures.
  void summarize(Clock::time_point start);
  void report(const std::string& line) const {
    if (progress_ && rank_ == 0)
      progress_(line);
  }

  const specimen::Specimen specimen_;
  const specimen::Material material_;
  const law::TractionLaw* law_ = nullptr;
  const double j_tip_;
  const FemParameters prm_;
  const std::string output_dir_;
  const std::function<void(const std::string&)> progress_;
  const MPI_Comm comm_;
  const unsigned rank_, n_ranks_;
  const dealii::SymmetricTensor<4, dim> C_;
  const bool finite_; ///< FEM/Kinematics = finite
  /// Width over which the 3D fields are integrated (1 m in 2D: the 2D fields are per width).
  double width_ = 1;

  dealii::parallel::distributed::Triangulation<dim> triangulation_;
  dealii::FESystem<dim> fe_;
  dealii::DoFHandler<dim> dof_handler_;
  dealii::MappingQ1<dim> mapping_;
  DcbGeometry geometry_;

  dealii::IndexSet owned_, relevant_;
  CrackPlane<dim> crack_;
  /// Component and support point of each locally owned dof (by index within owned_), for the
  /// predictor and the rigid-body modes of the AMG near null space.
  std::vector<std::array<double, 4>> owned_support_;
  std::vector<double> owned_arm_; ///< +1 top arm, -1 bottom arm, by index within owned_

  /// Bulk cell matrices: the mesh has few distinct cell shapes (a size per layer), so one
  /// matrix per shape instead of one per cell or a reassembly per Newton step.
  std::vector<dealii::FullMatrix<double>> shape_matrices_;
  std::vector<unsigned> cell_shape_; ///< by active_cell_index, for locally owned cells
  /// The bulk stiffness K, unconstrained (the residual is K u plus the interface forces,
  /// condensed afterwards).
  dealii::TrilinosWrappers::SparseMatrix bulk_;
  /// The homogeneous constraints of the current tie set; epoch_ counts the tie sets.
  dealii::AffineConstraints<double> hom_;
  unsigned epoch_ = 0, pattern_epoch_ = ~0u;
  /// What the Jacobian solver is told: a new value whenever the Jacobian changed beyond its
  /// interface tangents (a new tie set; with finite kinematics every linearization).
  unsigned solver_epoch_ = 0, solver_ties_epoch_ = ~0u;
  /// Finite kinematics: Newton's last contraction (1: none reported) and the linearizations
  /// since the bulk tangent was last assembled (chord steps reuse it, setup_jacobian()).
  double last_contraction_ = 1;
  unsigned chord_steps_ = 0;
  std::unique_ptr<JacobianSolver> solver_;
  /// solver_ where it is the condensed strategy (its crack-plane Newton, crack_plane_step()).
  CondensedSolver* condensed_ = nullptr;
  /// The last predict() started from the undeformed state (the hinge guess, whose interior is
  /// not in equilibrium: the crack-plane Newton does not apply).
  bool hinge_predictor_ = false;
  /// FEM/Linear solver with auto resolved (the constructor).
  FemParameters::Linear::Solver linear_solver_ = FemParameters::Linear::Solver::klu;

  Vec u_, u_ghost_, scratch_ghost_, residual_ghost_;
  double opening_ = 0;
  double work_ = 0; ///< external work per width [J/m]
  /// Equilibrium states since the last release: the control parameter (the load-point opening,
  /// or the controlled tip opening under the crack-tip control), the opening and the load.
  struct PathState {
    double param, opening, load;
    bool operator<(const PathState& o) const {
      return std::tie(param, opening, load) < std::tie(o.param, o.opening, o.load);
    }
  };
  std::vector<PathState> path_;
  /// Crack-tip opening control (switched on for good where the load-point opening failed).
  bool tip_control_ = false;
  std::string tip_control_reason_;  ///< where and why the run switched
  double last_control_opening_ = 0; ///< the controlled station's opening at the last record
  /// A release under the crack-tip control whose energy drop is not yet accounted.
  bool release_pending_ = false;
  double release_stored_ = 0, release_opening_ = 0, release_load_ = 0;
  double min_opening_since_record_ = 0;
  unsigned n_turned_back_ = 0; ///< advances whose traced path went below the last critical opening

  result::SimulationResult result_;
  /// Wall time per section (setup, assembly, factorize, solve, J integrals, output) of this
  /// rank, read back by summarize(); prints nothing. On MPI_COMM_SELF: a TimerOutput on the
  /// model's communicator would reduce over the ranks at every section stop.
  dealii::TimerOutput timer_;
  DistributedRunInfo info_;
  double max_opening_behind_tip_ = 0;
  double tip_dissipated_ = 0;                      ///< energy released by the releases [J/m]
  double j_after_release_ = result::not_available; ///< tip J right after the last release
  FemRunDetails details_;
  unsigned n_trials_ = 0, n_unstable_ = 0;
  unsigned n_crack_plane_fallbacks_ = 0; ///< crack-plane Newton runs left to the full Newton
  FieldOutput<dim> output_;
  mutable DomainJIntegral<dim> j_domain_; ///< domain_j()'s cell data, built on its first call
  /// FEM/Virtual DIC: samples every recorded state, writes the virtual test at the end.
  std::unique_ptr<VirtualTestRecorder<dim>> virtual_test_;
};

} // namespace fiberbridge::fem
