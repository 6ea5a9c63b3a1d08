// deal.II model of the DCB with cohesive segments inserted dynamically at the crack tip.
// The algorithm (DcbModel::run) in the paper's words (seed section 2.4): start from the sawn
// notch with no cohesive zone; raise the load-point opening until the crack-tip energy release
// rate reaches J_tip; release the tip node, which turns the segment ahead of the old tip into a
// fresh cohesive segment; repeat. The zone grows behind the tip, its trailing edge (the notch
// root) starts to move when the opening there passes delta_c, and the run stops at steady state.
//
// Choices (see also the header):
// - Crack plane doubled: the two arms are separate meshes on a vertex list of our own, so
//   create_triangulation never merges the crack-plane vertices (docs/design.md section 7).
// - Ahead of the tip the arms are tied by AffineConstraints (u_top = u_bottom per support point
//   pair): exact, no penalty to tune, and release is removing a constraint line.
// - Tip criterion: a domain J integral over a full-height strip around the tip, with the
//   cohesive crack-face term (Moran & Shih). It is degree-independent (VCCT needs different
//   formulas for Q2) and uses the same code as the far-field J, so tip J and J_ff are measured
//   alike and their difference checks Eq. 1 (path independence).
// - The load-point opening at which tip J equals J_tip is found by a secant iteration on
//   sqrt(J) (exact in one step for linear elasticity): every advance happens at J = J_tip within
//   the tolerance, not at whatever an opening increment happened to overshoot. When tip J exceeds
//   J_tip right after a release (unstable growth), the tip advances again at fixed opening.
// - Nonlinear solver (FEM/Nonlinear solver): our own Newton with backtracking line search on the
//   condensed residual (default), or SUNDIALS KINSOL with its line search on the same residual,
//   Jacobian and linear solves. The release-library KINSOL does not report failure
//   (docs/design.md section 7): its result is re-checked against the same convergence test, and a
//   failure becomes the same ComputationError diagnosis as a Newton failure.
// - Linear solves (FEM/Linear solver): Trilinos Amesos KLU (default) or UMFPACK, one
//   factorization per release; between releases the interface points that change branch enter
//   as a low-rank (Woodbury) correction, so the iterations stay exact without refactorizing.
//   KLU (Epetra) needs MPI initialized: the fiberbridge program and fem_tests do that; a program
//   that does not gets an InputError naming umfpack as the alternative.
#include "fiberbridge/fem/dcb_simulation.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/cohesive_interface.h"
#include "fiberbridge/fem/dcb_common.h"
#include "fiberbridge/law/numerical_fault.h"

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/sundials/kinsol.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace fiberbridge::fem {

namespace {

using namespace dealii;
constexpr int dim = 2;

// fmt, orthotropic_stiffness, insertable_law, the mesh lines, the steady-state check, Ramp and
// StressPostprocessor live in dcb_common (shared with the
// distributed engine).

/// Sparse direct solver of the condensed Jacobian (FEM/Linear solver): factorize() once per
/// Jacobian, then any number of solve() calls with that factorization.
class DirectSolver {
public:
  explicit DirectSolver(FemParameters::LinearSolver type) : type_(type) {
    // Epetra objects abort the program when MPI is not initialized: say so in time instead.
    if (type_ == FemParameters::LinearSolver::klu && !Utilities::MPI::job_supports_mpi())
      throw InputError("FEM/Linear solver = klu: Trilinos needs MPI initialized "
                       "(Utilities::MPI::MPI_InitFinalize in main); this program does not "
                       "initialize it, use umfpack");
  }

  void factorize(const SparseMatrix<double>& A) {
    if (type_ == FemParameters::LinearSolver::umfpack) {
      umfpack_.factorize(A);
      return;
    }
    if (!klu_)
      klu_ = std::make_unique<Klu>();
    // The solver refers to the Epetra matrix: destroy it before the matrix changes.
    klu_->solver.reset();
    // Serial Epetra copy on MPI_COMM_SELF with A's pattern. This reinit copies only the entries
    // above the drop tolerance (0: the nonzeros) and leaves the others as they were, so it must
    // start from an empty matrix: into the previous one, the entries that condensation zeroes
    // after a release kept their old values (seen here as a wrong solve). The one-IndexSet
    // overload of this reinit does not compile in deal.II 9.4.
    klu_->matrix.clear();
    const IndexSet all = complete_index_set(A.m());
    klu_->matrix.reinit(all, all, A, MPI_COMM_SELF, 0.0, true);
    klu_->solver = std::make_unique<TrilinosWrappers::SolverDirect>(
        klu_->control, TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Klu"));
    klu_->solver->initialize(klu_->matrix); // symbolic and numeric factorization
    klu_->rhs.reinit(A.m());
    klu_->solution.reinit(A.m());
  }

  /// x <- A^-1 x with the last factorization.
  void solve(Vector<double>& x) {
    if (type_ == FemParameters::LinearSolver::umfpack) {
      umfpack_.solve(x);
      return;
    }
    // SolverDirect reuses the factorization only for Epetra or distributed vectors (its
    // dealii::Vector overload refactorizes): copy through serial distributed vectors.
    std::copy(x.begin(), x.end(), klu_->rhs.begin());
    klu_->solver->solve(klu_->solution, klu_->rhs);
    std::copy(klu_->solution.begin(), klu_->solution.end(), x.begin());
  }

  const char* name() const {
    return type_ == FemParameters::LinearSolver::klu ? "Trilinos Amesos KLU" : "UMFPACK";
  }

private:
  FemParameters::LinearSolver type_;
  SparseDirectUMFPACK umfpack_;
  struct Klu {
    TrilinosWrappers::SparseMatrix matrix;
    SolverControl control;
    std::unique_ptr<TrilinosWrappers::SolverDirect> solver;
    LinearAlgebra::distributed::Vector<double> rhs, solution;
  };
  std::unique_ptr<Klu> klu_; // created on first use: even an empty Epetra matrix needs MPI
};

/// The dofs of one pair of coincident crack-plane support points.
struct CrackPlaneNode {
  double x = 0;
  types::global_dof_index top[dim], bottom[dim];
};

class DcbModel {
public:
  DcbModel(const law::Specimen& specimen, const law::Material& material,
           const law::TractionLaw& law, double j_tip, const FemParameters& parameters,
           const std::string& output_dir, const std::function<void(const std::string&)>& progress);
  law::SimulationResult run();
  const FemRunDetails& details() const { return details_; }

private:
  // Setup.
  void make_grid();
  void setup_system();
  void assemble_bulk_stiffness();
  void make_crack_plane();
  void make_constraints(double opening, AffineConstraints<double>& constraints) const;
  // Equilibrium.
  void solve_at(double opening);
  /// Scales the last state to `opening` (exact for linear elasticity) and imposes the ties and
  /// the prescribed opening exactly: the start of both nonlinear solvers.
  void predict(double opening);
  /// Norm of the load-line reaction in a full (uncondensed) residual: the force scale of the
  /// convergence test (J_tip sets a floor at zero opening).
  double reaction_norm(const Vector<double>& full_residual) const;
  /// true if the residual norm (condensed) passes the convergence test against `reaction`.
  bool converged(double norm, double reaction) const;
  bool newton(double opening, std::string& diagnosis);
  bool kinsol(double opening, std::string& diagnosis);
  void assemble_residual(const Vector<double>& u, Vector<double>& residual) const;
  double condensed_norm(Vector<double>& residual) const;
  /// Makes the Jacobian at u_ available to solve_linear(): the factorization is reused while
  /// the constraints are unchanged, with a low-rank (Woodbury) correction for the interface
  /// points whose tangent changed since; refactorizes after a release or when many changed.
  void update_jacobian();
  /// Solves J du = rhs in place (condensed space) with the factorization and its correction.
  void solve_linear(Vector<double>& rhs);
  // Crack growth.
  bool load_to_critical();
  void release_tip();
  // Measurements.
  std::vector<double> node_openings() const;
  std::vector<double> openings() const; ///< at the interface integration points
  double domain_j(const Ramp& q, bool crack_face_term) const;
  /// int_faces sigma_coh d(delta)/dx q dx over the opened segments (q = 1 if `ramp` is null).
  double crack_face_j(const Ramp* ramp) const;
  double tip_j() const;
  double far_field_j() const;
  double load_per_thickness() const;
  law::RCurvePoint record_advance();
  /// Checks the plateau after the root first moved; sets G_ss and notes it when reached.
  bool reached_steady_state(double first_root_move);
  // Output.
  void output_fields(unsigned int advance);
  void write_interface_csv() const;
  void report(const std::string& line) const;

  const law::Specimen specimen_;
  const law::Material material_;
  const law::TractionLaw& user_law_;
  std::unique_ptr<law::ElasticRiseLaw> regularized_law_;
  const law::TractionLaw* law_ = nullptr; ///< the law simulated (user law or regularized)
  const double j_tip_;
  const FemParameters prm_;
  const std::string output_dir_;
  const std::function<void(const std::string&)> progress_;
  const SymmetricTensor<4, dim> C_;

  Triangulation<dim> triangulation_;
  FESystem<dim> fe_;
  DoFHandler<dim> dof_handler_;
  MappingQ1<dim> mapping_;
  std::vector<double> x_lines_; ///< mesh x coordinates (element boundaries along the crack)
  double dx_ = 0;               ///< element size along the crack (tip advance)

  std::vector<CrackPlaneNode> nodes_;
  std::unique_ptr<CohesiveInterface> interface_;
  /// Interface integration point -> the crack-plane nodes of its segment with the Lagrange
  /// weights (value N and x-derivative dN) that interpolate the nodal openings there.
  struct PointMap {
    std::vector<unsigned> nodes;
    std::vector<double> N, dN;
  };
  std::vector<PointMap> point_map_;
  std::vector<std::vector<unsigned>> segment_nodes_;
  std::vector<unsigned> segment_of_left_node_; ///< segment starting at node a (or ~0u)
  unsigned tip_node_ = 0, notch_node_ = 0;     ///< first tied point; point at a0
  std::vector<types::global_dof_index> load_top_, load_bottom_, right_end_;

  SparsityPattern sparsity_;
  SparseMatrix<double> bulk_stiffness_, system_matrix_;
  DirectSolver direct_solver_;
  AffineConstraints<double> homogeneous_constraints_;
  unsigned constraints_epoch_ = 0, factorized_epoch_ = ~0u;
  std::vector<double> factorized_tangents_;
  /// Woodbury correction: changed point -> (tangent change, condensed interface vector c_p,
  /// A^-1 c_p with the factorized A); the c_p and A^-1 c_p are kept for the factorization.
  struct LowRankTerm {
    double dk = 0;
    Vector<double> c, z;
  };
  std::map<unsigned, LowRankTerm> low_rank_;

  Vector<double> u_;
  double opening_ = 0;                          ///< load-point opening Delta [m]
  double work_2d_ = 0;                          ///< external work per unit thickness [J/m]
  std::vector<std::pair<double, double>> path_; ///< (Delta, P) since the last release

  law::SimulationResult result_;
  FemRunDetails details_;
  std::vector<double> dissipated_2d_;           ///< per record, for R_energy and G_ss
  double max_opening_behind_tip_ = 0;           ///< largest opening one node behind the tip [m]
  double tip_dissipated_2d_ = 0;                ///< energy released by the releases [J/m]
  double j_after_release_ = law::not_available; ///< tip J right after the last release
  double stored_energy_2d() const;              ///< U + U_zone + D_zone per thickness [J/m]
  unsigned n_trials_ = 0, n_unstable_ = 0, n_newton_ = 0, n_factorizations_ = 0, n_solves_ = 0;
  double t_factorize_ = 0, t_solve_ = 0, t_residual_ = 0, t_j_ = 0, t_output_ = 0;
  std::vector<std::pair<double, std::string>> pvd_records_;
};

DcbModel::DcbModel(const law::Specimen& specimen, const law::Material& material,
                   const law::TractionLaw& law, double j_tip, const FemParameters& parameters,
                   const std::string& output_dir,
                   const std::function<void(const std::string&)>& progress)
    : specimen_(specimen), material_(material), user_law_(law), j_tip_(j_tip), prm_(parameters),
      output_dir_(output_dir), progress_(progress),
      C_(orthotropic_stiffness<dim>(material, parameters)), fe_(FE_Q<dim>(parameters.degree), dim),
      dof_handler_(triangulation_), direct_solver_(parameters.linear_solver) {
  specimen_.validate();
  material_.validate();
  prm_.validate();
  if (!(j_tip > 0))
    throw InputError("Cohesive law/J tip: the FEM tip criterion needs J tip > 0");
  law_ = insertable_law(law, material, prm_, regularized_law_, result_.notes);
}

void DcbModel::report(const std::string& line) const {
  if (progress_)
    progress_(line);
}

// ---------------------------------------------------------------------------------------------
// Setup

void DcbModel::make_grid() {
  const DcbMeshLines lines = dcb_mesh_lines(specimen_, prm_);
  dx_ = lines.dx;
  x_lines_ = lines.x;
  const std::vector<double>& y_lines = lines.y;

  const unsigned nx = x_lines_.size() - 1, ny = y_lines.size() - 1;
  std::vector<Point<dim>> vertices;
  vertices.reserve(2 * (nx + 1) * (ny + 1));
  for (int side : {+1, -1}) // top arm first, then the bottom arm with its own crack-plane row
    for (unsigned j = 0; j <= ny; ++j)
      for (unsigned i = 0; i <= nx; ++i)
        vertices.emplace_back(x_lines_[i], side * y_lines[j]);
  auto index = [&](unsigned arm, unsigned i, unsigned j) {
    return arm * (nx + 1) * (ny + 1) + j * (nx + 1) + i;
  };
  std::vector<CellData<dim>> cells;
  for (unsigned arm = 0; arm < 2; ++arm)
    for (unsigned j = 0; j < ny; ++j)
      for (unsigned i = 0; i < nx; ++i) {
        CellData<dim> c;
        // Lexicographic vertex order with y increasing: the bottom arm counts j downwards.
        if (arm == 0)
          c.vertices = {index(0, i, j), index(0, i + 1, j), index(0, i, j + 1),
                        index(0, i + 1, j + 1)};
        else
          c.vertices = {index(1, i, j + 1), index(1, i + 1, j + 1), index(1, i, j),
                        index(1, i + 1, j)};
        c.material_id = arm; // 0 top, 1 bottom
        cells.push_back(c);
      }
  triangulation_.create_triangulation(vertices, cells, SubCellData());
}

void DcbModel::setup_system() {
  dof_handler_.distribute_dofs(fe_);
  // Number the dofs along the beam, both arms together: the mesh graph has two components (the
  // arms share no vertex), so Cuthill-McKee would number one arm after the other and the ties
  // would couple dofs half a matrix apart. Along x, tied pairs are neighbours in the numbering
  // and the matrix is a narrow band (UMFPACK orders for fill itself; this keeps the matrix
  // readable and cache-friendly for the vmults).
  Tensor<1, dim> along_beam;
  along_beam[0] = 1;
  along_beam[1] = 1e-3; // tie-break within a column
  DoFRenumbering::downstream(dof_handler_, along_beam, /*dof_wise_renumbering=*/true);
  make_crack_plane();

  // Load line: the whole end face x = 0 of each arm, y-component; right end: crack-plane point.
  std::vector<Point<dim>> support(dof_handler_.n_dofs());
  DoFTools::map_dofs_to_support_points(mapping_, dof_handler_, support);
  std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
  std::vector<bool> seen(dof_handler_.n_dofs(), false);
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    cell->get_dof_indices(dofs);
    for (unsigned i = 0; i < dofs.size(); ++i) {
      const auto d = dofs[i];
      if (seen[d] || fe_.system_to_component_index(i).first != 1 ||
          std::abs(support[d][0]) > 1e-9 * specimen_.length)
        continue;
      seen[d] = true;
      (cell->material_id() == 0 ? load_top_ : load_bottom_).push_back(d);
    }
  }
  right_end_ = {nodes_.back().bottom[0], nodes_.back().bottom[1]};

  // Sparsity: the couplings of every cell extended by the crack-plane partners of its dofs. The
  // condensed matrix of ANY set of ties then fits: condensation with a tie top -> bottom moves an
  // entry (i, top) to (i, bottom), and rows of released dofs keep their own entries. (The fill of
  // make_sparsity_pattern with constraints covers only the tie set it is given: after a release
  // the mixed entries (released top dof, tied bottom dof) would be missing, and SparseMatrix::add
  // drops missing entries silently in release mode.) The cohesive top-bottom coupling of each
  // interface point is contained too.
  std::vector<types::global_dof_index> partner(dof_handler_.n_dofs(), numbers::invalid_dof_index);
  for (const auto& p : nodes_)
    for (unsigned d = 0; d < dim; ++d) {
      partner[p.top[d]] = p.bottom[d];
      partner[p.bottom[d]] = p.top[d];
    }
  DynamicSparsityPattern dsp(dof_handler_.n_dofs());
  std::vector<types::global_dof_index> extended;
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    cell->get_dof_indices(dofs);
    extended = dofs;
    for (const auto d : dofs)
      if (partner[d] != numbers::invalid_dof_index)
        extended.push_back(partner[d]);
    for (const auto i : extended)
      dsp.add_entries(i, extended.begin(), extended.end());
  }
  sparsity_.copy_from(dsp);
  bulk_stiffness_.reinit(sparsity_);
  system_matrix_.reinit(sparsity_);
  u_.reinit(dof_handler_.n_dofs());
}

void DcbModel::make_crack_plane() {
  // Pair the support points of the top-arm faces on y = 0 with those of the bottom-arm faces.
  const double tol = 1e-9 * specimen_.length;
  auto key = [&](double x) { return std::llround(x / tol); };
  std::map<long long, CrackPlaneNode> by_x;
  std::map<long long, std::array<int, 2 * dim>> filled;
  struct Face {
    double x_left, x_right;
  };
  std::vector<Face> faces;
  std::vector<Point<dim>> support(dof_handler_.n_dofs());
  DoFTools::map_dofs_to_support_points(mapping_, dof_handler_, support);
  std::vector<types::global_dof_index> face_dofs(fe_.n_dofs_per_face());
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    const bool top = cell->material_id() == 0;
    for (const unsigned f : cell->face_indices()) {
      const auto face = cell->face(f);
      if (std::abs(face->center()[1]) > tol)
        continue;
      if (top)
        faces.push_back({std::min(face->vertex(0)[0], face->vertex(1)[0]),
                         std::max(face->vertex(0)[0], face->vertex(1)[0])});
      face->get_dof_indices(face_dofs);
      for (unsigned i = 0; i < face_dofs.size(); ++i) {
        const unsigned c = fe_.face_system_to_component_index(i).first;
        const auto d = face_dofs[i];
        auto& p = by_x[key(support[d][0])];
        p.x = support[d][0];
        (top ? p.top : p.bottom)[c] = d;
        filled[key(support[d][0])][(top ? 0 : dim) + c] = 1;
      }
    }
  }
  for (const auto& [k, f] : filled)
    if (std::count(f.begin(), f.end(), 1) != 2 * dim)
      throw ComputationError("FEM mesh: a crack-plane support point has no partner on the "
                             "other arm (mesh generation error)");
  for (const auto& [k, p] : by_x)
    nodes_.push_back(p);

  interface_ = std::make_unique<CohesiveInterface>(*law_, prm_.contact_stiffness_factor *
                                                              material_.E_T / prm_.element_size);
  std::sort(faces.begin(), faces.end(),
            [](const Face& a, const Face& b) { return a.x_left < b.x_left; });
  const QGaussLobatto<1> lobatto(prm_.degree + 1);
  segment_of_left_node_.assign(nodes_.size(), ~0u);
  auto node_at = [&](double x) {
    const auto it = std::lower_bound(nodes_.begin(), nodes_.end(), x - tol,
                                     [](const CrackPlaneNode& p, double v) { return p.x < v; });
    if (it == nodes_.end() || std::abs(it->x - x) > tol)
      throw ComputationError("FEM mesh: no crack-plane node at x = " + fmt(x));
    return unsigned(it - nodes_.begin());
  };
  // Each segment (face) is integrated with a composite Gauss-Lobatto rule: `m` sub-intervals,
  // each with the degree+1 Lobatto points (m = 1: the points are the face nodes). Next to the
  // tip the opening rises from zero over one element while the law may pass its peak there;
  // interior points see that, nodal points alone do not. Every point has its own history.
  const unsigned m = prm_.interface_subintervals;
  for (const auto& f : faces) {
    const double len = f.x_right - f.x_left;
    std::vector<unsigned> seg_nodes;
    for (unsigned q = 0; q < lobatto.size(); ++q)
      seg_nodes.push_back(node_at(f.x_left + lobatto.point(q)[0] * len));
    std::vector<double> xs, ws;
    for (unsigned i = 0; i < m; ++i)
      for (unsigned q = 0; q < lobatto.size(); ++q) {
        const double x = f.x_left + (i + lobatto.point(q)[0]) / m * len;
        const double w = lobatto.weight(q) * len / m;
        if (!xs.empty() && std::abs(x - xs.back()) < tol)
          ws.back() += w; // joint of two sub-intervals: one point
        else {
          xs.push_back(x);
          ws.push_back(w);
        }
      }
    std::vector<unsigned> pts;
    for (const double x : xs) {
      PointMap map;
      map.nodes = seg_nodes;
      for (unsigned a = 0; a < seg_nodes.size(); ++a) {
        // Lagrange basis over the segment's nodes and its derivative.
        const double xa = nodes_[seg_nodes[a]].x;
        double N = 1, dN = 0;
        for (unsigned b = 0; b < seg_nodes.size(); ++b) {
          if (b == a)
            continue;
          const double xb = nodes_[seg_nodes[b]].x;
          double term = 1 / (xa - xb);
          for (unsigned c = 0; c < seg_nodes.size(); ++c)
            if (c != a && c != b)
              term *= (x - nodes_[seg_nodes[c]].x) / (xa - nodes_[seg_nodes[c]].x);
          dN += term;
          N *= (x - xb) / (xa - xb);
        }
        map.N.push_back(N);
        map.dN.push_back(dN);
      }
      point_map_.push_back(std::move(map));
      pts.push_back(interface_->add_point(x));
    }
    const unsigned s = interface_->add_segment(pts, ws);
    segment_nodes_.push_back(seg_nodes);
    segment_of_left_node_[seg_nodes.front()] = s;
  }
  // The sawn notch is a traction-free crack (contact only); the tip starts at a0.
  notch_node_ = node_at(specimen_.initial_crack);
  tip_node_ = notch_node_;
  for (unsigned s = 0; s < interface_->n_segments(); ++s)
    if (segment_nodes_[s].back() <= notch_node_)
      interface_->open_segment(s, SegmentState::traction_free);
}

void DcbModel::make_constraints(double opening, AffineConstraints<double>& c) const {
  c.clear();
  // Intact ligament: u_top = u_bottom for every point at or ahead of the tip.
  for (unsigned p = tip_node_; p < nodes_.size(); ++p)
    for (unsigned d = 0; d < dim; ++d) {
      c.add_line(nodes_[p].top[d]);
      c.add_entry(nodes_[p].top[d], nodes_[p].bottom[d], 1.0);
    }
  for (const auto d : load_top_) {
    c.add_line(d);
    c.set_inhomogeneity(d, 0.5 * opening);
  }
  for (const auto d : load_bottom_) {
    c.add_line(d);
    c.set_inhomogeneity(d, -0.5 * opening);
  }
  for (const auto d : right_end_)
    c.add_line(d);
  c.close();
}

void DcbModel::assemble_bulk_stiffness() {
  const QGauss<dim> quadrature(prm_.degree + 1);
  FEValues<dim> fe_values(mapping_, fe_, quadrature, update_gradients | update_JxW_values);
  const FEValuesExtractors::Vector displacement(0);
  const unsigned n = fe_.n_dofs_per_cell();
  FullMatrix<double> cell_matrix(n, n);
  std::vector<types::global_dof_index> dofs(n);
  std::vector<SymmetricTensor<2, dim>> eps(n);
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    fe_values.reinit(cell);
    cell_matrix = 0;
    for (unsigned q = 0; q < quadrature.size(); ++q) {
      for (unsigned i = 0; i < n; ++i)
        eps[i] = fe_values[displacement].symmetric_gradient(i, q);
      for (unsigned i = 0; i < n; ++i) {
        const SymmetricTensor<2, dim> sigma_i = C_ * eps[i];
        for (unsigned j = 0; j <= i; ++j)
          cell_matrix(i, j) += sigma_i * eps[j] * fe_values.JxW(q);
      }
    }
    for (unsigned i = 0; i < n; ++i)
      for (unsigned j = 0; j < i; ++j)
        cell_matrix(j, i) = cell_matrix(i, j);
    cell->get_dof_indices(dofs);
    bulk_stiffness_.add(dofs, cell_matrix);
  }
}

// ---------------------------------------------------------------------------------------------
// Equilibrium at a given load-point opening

std::vector<double> DcbModel::node_openings() const {
  std::vector<double> o(nodes_.size());
  for (unsigned a = 0; a < nodes_.size(); ++a)
    o[a] = u_[nodes_[a].top[1]] - u_[nodes_[a].bottom[1]];
  return o;
}

std::vector<double> DcbModel::openings() const {
  const auto nodal = node_openings();
  std::vector<double> o(point_map_.size(), 0.0);
  for (unsigned p = 0; p < point_map_.size(); ++p)
    for (unsigned a = 0; a < point_map_[p].nodes.size(); ++a)
      o[p] += point_map_[p].N[a] * nodal[point_map_[p].nodes[a]];
  return o;
}

void DcbModel::assemble_residual(const Vector<double>& u, Vector<double>& r) const {
  // r = dPi/du: bulk K u plus the interface forces (opening = u_top - u_bottom, mode I),
  // interpolated to the integration points and back to the nodes.
  bulk_stiffness_.vmult(r, u);
  for (unsigned p = 0; p < point_map_.size(); ++p) {
    const auto& map = point_map_[p];
    double opening = 0;
    for (unsigned a = 0; a < map.nodes.size(); ++a)
      opening += map.N[a] * (u[nodes_[map.nodes[a]].top[1]] - u[nodes_[map.nodes[a]].bottom[1]]);
    const double f = interface_->respond(p, opening).force;
    if (f == 0)
      continue;
    for (unsigned a = 0; a < map.nodes.size(); ++a) {
      r[nodes_[map.nodes[a]].top[1]] += map.N[a] * f;
      r[nodes_[map.nodes[a]].bottom[1]] -= map.N[a] * f;
    }
  }
}

double DcbModel::condensed_norm(Vector<double>& r) const {
  homogeneous_constraints_.condense(r);
  return r.l2_norm();
}

void DcbModel::update_jacobian() {
  const auto o = openings();
  std::vector<double> tangents(point_map_.size());
  for (unsigned p = 0; p < point_map_.size(); ++p)
    tangents[p] = interface_->respond(p, o[p]).stiffness;
  // The bulk is linear and piecewise-linear laws have piecewise-constant tangents: between two
  // releases the Jacobian differs from the factorized one only at the interface points that
  // changed branch, each a rank-one term dk c c^T with c the condensed opening operator of the
  // point. A few of them are cheaper as a Woodbury correction (one solve each) than a new
  // factorization. A release changes the constrained space itself: always refactorize.
  if (factorized_epoch_ == constraints_epoch_) {
    std::vector<unsigned> changed;
    for (unsigned p = 0; p < tangents.size(); ++p)
      if (tangents[p] != factorized_tangents_[p])
        changed.push_back(p);
    constexpr std::size_t max_low_rank = 12; // ~ one factorization worth of solves (measured)
    if (changed.size() <= max_low_rank) {
      const auto t0 = Clock::now();
      std::map<unsigned, LowRankTerm> terms;
      for (const unsigned p : changed) {
        auto it = low_rank_.find(p);
        LowRankTerm term = it != low_rank_.end() ? std::move(it->second) : LowRankTerm();
        if (term.c.size() == 0) {
          term.c.reinit(u_.size());
          const auto& map = point_map_[p];
          for (unsigned a = 0; a < map.nodes.size(); ++a) {
            term.c[nodes_[map.nodes[a]].top[1]] += map.N[a];
            term.c[nodes_[map.nodes[a]].bottom[1]] -= map.N[a];
          }
          homogeneous_constraints_.condense(term.c);
          term.z = term.c;
          direct_solver_.solve(term.z);
          ++n_solves_;
        }
        term.dk = tangents[p] - factorized_tangents_[p];
        terms.emplace(p, std::move(term));
      }
      for (auto& [p, term] : low_rank_) // keep unused vectors for later branch changes
        if (terms.find(p) == terms.end()) {
          term.dk = 0;
          terms.emplace(p, std::move(term));
        }
      low_rank_ = std::move(terms);
      t_solve_ += seconds_since(t0);
      return;
    }
  }
  const auto t0 = Clock::now();
  system_matrix_.copy_from(bulk_stiffness_);
  for (unsigned p = 0; p < point_map_.size(); ++p) {
    if (tangents[p] == 0)
      continue;
    const auto& map = point_map_[p];
    for (unsigned a = 0; a < map.nodes.size(); ++a)
      for (unsigned b = 0; b < map.nodes.size(); ++b) {
        const double k = tangents[p] * map.N[a] * map.N[b];
        const auto& na = nodes_[map.nodes[a]];
        const auto& nb = nodes_[map.nodes[b]];
        system_matrix_.add(na.top[1], nb.top[1], k);
        system_matrix_.add(na.top[1], nb.bottom[1], -k);
        system_matrix_.add(na.bottom[1], nb.top[1], -k);
        system_matrix_.add(na.bottom[1], nb.bottom[1], k);
      }
  }
  homogeneous_constraints_.condense(system_matrix_);
  direct_solver_.factorize(system_matrix_);
  factorized_tangents_ = std::move(tangents);
  factorized_epoch_ = constraints_epoch_;
  low_rank_.clear();
  ++n_factorizations_;
  t_factorize_ += seconds_since(t0);
}

void DcbModel::solve_linear(Vector<double>& rhs) {
  // Woodbury: (A + U D U^T)^-1 b = y - Z (D^-1 + U^T Z)^-1 U^T y, y = A^-1 b, Z = A^-1 U.
  direct_solver_.solve(rhs);
  std::vector<const LowRankTerm*> active;
  for (const auto& [p, term] : low_rank_)
    if (term.dk != 0)
      active.push_back(&term);
  if (active.empty())
    return;
  const unsigned k = active.size();
  FullMatrix<double> S(k, k);
  Vector<double> w(k), v(k);
  for (unsigned i = 0; i < k; ++i) {
    S(i, i) = 1 / active[i]->dk;
    for (unsigned j = 0; j < k; ++j)
      S(i, j) += active[i]->c * active[j]->z;
    w[i] = active[i]->c * rhs;
  }
  S.gauss_jordan();
  S.vmult(v, w);
  for (unsigned i = 0; i < k; ++i)
    rhs.add(-v[i], active[i]->z);
}

void DcbModel::predict(double opening) {
  if (opening_ != 0)
    u_ *= opening / opening_;
  opening_ = opening;
  AffineConstraints<double> constraints;
  make_constraints(opening, constraints);
  constraints.distribute(u_);
}

double DcbModel::reaction_norm(const Vector<double>& full) const {
  double s = 0;
  for (const auto d : load_top_)
    s += full[d] * full[d];
  for (const auto d : load_bottom_)
    s += full[d] * full[d];
  return std::max(std::sqrt(s), 1e-6 * j_tip_);
}

bool DcbModel::converged(double norm, double reaction) const {
  return norm <= prm_.newton_tolerance * reaction;
}

bool DcbModel::newton(double opening, std::string& diagnosis) {
  predict(opening);
  Vector<double> r(u_.size()), du(u_.size()), trial(u_.size());
  auto t0 = Clock::now();
  assemble_residual(u_, r);
  double ref = reaction_norm(r);
  double norm = condensed_norm(r);
  t_residual_ += seconds_since(t0);
  for (unsigned it = 0; it <= prm_.max_newton_iterations; ++it) {
    if (converged(norm, ref))
      return true;
    if (it == prm_.max_newton_iterations)
      break;
    ++n_newton_;
    update_jacobian();
    t0 = Clock::now();
    du = r;
    du *= -1.0;
    solve_linear(du);
    homogeneous_constraints_.distribute(du);
    ++n_solves_;
    t_solve_ += seconds_since(t0);

    // Backtracking line search on the condensed residual norm (Armijo-like sufficient decrease).
    t0 = Clock::now();
    double alpha = 1, best_alpha = 0, best_norm = norm, best_ref = ref;
    for (int ls = 0; ls < 8; ++ls, alpha *= 0.5) {
      trial = u_;
      trial.add(alpha, du);
      assemble_residual(trial, r);
      const double trial_ref = reaction_norm(r);
      const double trial_norm = condensed_norm(r);
      if (trial_norm < best_norm) {
        best_norm = trial_norm;
        best_alpha = alpha;
        best_ref = trial_ref;
      }
      if (trial_norm <= (1 - 1e-4 * alpha) * norm)
        break;
    }
    t_residual_ += seconds_since(t0);
    if (best_alpha == 0) {
      diagnosis = "line search found no decrease of the residual " + fmt(norm) + " N/m";
      return false;
    }
    u_.add(best_alpha, du);
    assemble_residual(u_, r);
    ref = best_ref;
    norm = condensed_norm(r);
  }
  diagnosis = "no convergence in " + std::to_string(prm_.max_newton_iterations) +
              " Newton iterations (residual " + fmt(norm / ref) + " of the reaction, tolerance " +
              fmt(prm_.newton_tolerance) + ")";
  return false;
}

bool DcbModel::kinsol(double opening, std::string& diagnosis) {
  predict(opening);
  Vector<double> r(u_.size());
  auto t0 = Clock::now();
  assemble_residual(u_, r);
  const double ref = reaction_norm(r);
  if (converged(condensed_norm(r), ref)) {
    t_residual_ += seconds_since(t0);
    return true;
  }
  t_residual_ += seconds_since(t0);

  using Kinsol = SUNDIALS::KINSOL<Vector<double>>;
  Kinsol::AdditionalData data;
  data.strategy = Kinsol::AdditionalData::linesearch;
  data.maximum_non_linear_iterations = prm_.max_newton_iterations;
  // KINSOL stops on the max norm of the residual: below tolerance / sqrt(n) it guarantees our
  // l2 test (re-checked below, with the reaction of the final state).
  data.function_tolerance = prm_.newton_tolerance * ref / std::sqrt(double(u_.size()));
  // KINSOL also stops when the scaled step max |du_i| / (|u_i| + 1) falls below the step
  // tolerance (displacements in m, unit scaling). Its default eps^(2/3) = 4e-11 m is not small
  // against the last steps of a converging solve at sub-mm openings, so it could end the
  // iteration before the residual test is met (not seen on the seed cases, where the residual
  // test ends every solve): a thousandth of the tolerance times the opening stops only on
  // stagnation.
  data.step_tolerance = 1e-3 * prm_.newton_tolerance * opening;
  // Exact Jacobian at every iteration, like our Newton: between releases it costs a few
  // Woodbury solves, not a factorization (update_jacobian).
  data.maximum_setup_calls = 1;
  Kinsol solver(data);

  // Exceptions must not cross the SUNDIALS C frames: a callback reports them as a fatal
  // return code, and the message joins the diagnosis.
  std::string callback_error;
  auto guarded = [&](const auto& body) -> int {
    try {
      body();
      return 0;
    } catch (const std::exception& e) {
      callback_error = e.what();
      return -1;
    }
  };
  solver.reinit_vector = [n = u_.size()](Vector<double>& v) { v.reinit(n); };
  solver.residual = [&](const Vector<double>& u, Vector<double>& f) {
    return guarded([&] {
      const auto t1 = Clock::now();
      assemble_residual(u, f);
      homogeneous_constraints_.condense(f);
      t_residual_ += seconds_since(t1);
    });
  };
  solver.setup_jacobian = [&](const Vector<double>& u, const Vector<double>&) {
    return guarded([&] {
      u_ = u; // update_jacobian() linearizes at u_
      update_jacobian();
    });
  };
  solver.solve_with_jacobian = [&](const Vector<double>& rhs, Vector<double>& x, double) {
    return guarded([&] {
      const auto t1 = Clock::now();
      x = rhs;
      solve_linear(x);
      homogeneous_constraints_.distribute(x); // tied dofs follow their partners
      ++n_solves_;
      t_solve_ += seconds_since(t1);
    });
  };
  Vector<double> solution = u_;
  unsigned iterations = 0;
  try {
    iterations = solver.solve(solution);
  } catch (const std::exception& e) { // deal.II's own checks inside solve()
    callback_error = e.what();
  }
  n_newton_ += iterations;
  u_ = solution;

  // The release library ignores KINSOL's return status: judge the result ourselves. (The
  // debug library asserts on it instead, which aborts the program at the first failed solve,
  // before the step halving of solve_at() can retry: one reason newton is the default.)
  t0 = Clock::now();
  assemble_residual(u_, r);
  const double final_ref = reaction_norm(r);
  const double norm = condensed_norm(r);
  t_residual_ += seconds_since(t0);
  if (callback_error.empty() && converged(norm, final_ref))
    return true;
  diagnosis = "KINSOL returned after " + std::to_string(iterations) + " of at most " +
              std::to_string(prm_.max_newton_iterations) + " Newton iterations with residual " +
              fmt(norm / final_ref) + " of the reaction (tolerance " + fmt(prm_.newton_tolerance) +
              ")" +
              (callback_error.empty() ? "" : "; KINSOL or a callback failed: " + callback_error);
  return false;
}

void DcbModel::solve_at(double target) {
  // Continuation in the load-point opening, with step halving when Newton fails. Trial states
  // use the committed interface history, so the path within one call does not matter for
  // monotonic opening.
  const Vector<double> u0 = u_;
  const double opening0 = opening_;
  unsigned n =
      std::max(1u, unsigned(std::ceil(std::abs(target - opening0) / prm_.max_opening_increment)));
  std::string diagnosis;
  // At fixed opening (after a release) there is nothing to sub-step.
  const int attempts = target == opening0 ? 1 : 6;
  for (int attempt = 0; attempt < attempts; ++attempt, n *= 2) {
    u_ = u0;
    opening_ = opening0;
    bool ok = true;
    for (unsigned i = 1; i <= n && ok; ++i)
      ok = prm_.nonlinear_solver == FemParameters::NonlinearSolver::kinsol
               ? kinsol(opening0 + (target - opening0) * double(i) / n, diagnosis)
               : newton(opening0 + (target - opening0) * double(i) / n, diagnosis);
    if (ok)
      return;
  }
  std::ostringstream m;
  m << "FEM: no equilibrium at load-point opening " << target / units::mm << " mm with the tip at "
    << nodes_[tip_node_].x / units::mm << " mm";
  if (target == opening0)
    m << " (re-solve at fixed opening after a release)";
  else
    m << " (" << n / 2 << " sub-steps from " << opening0 / units::mm << " mm)";
  m << ": " << diagnosis
    << ". Try a smaller FEM/Element size or Maximum opening increment, a softer Contact "
       "stiffness factor, more Maximum Newton iterations, or check the law for a vertical drop";
  throw ComputationError(m.str());
}

// ---------------------------------------------------------------------------------------------
// Crack growth

bool DcbModel::load_to_critical() {
  // Raise the opening until tip J = J_tip (secant on sqrt(J), exact in one step when linear).
  // Returns false when the tip is already critical at the current opening (no load increase).
  const auto t0 = Clock::now();
  double J = tip_j();
  t_j_ += seconds_since(t0);
  if (!result_.rcurve.empty())
    j_after_release_ = J;
  if (J >= (1 - prm_.tip_tolerance) * j_tip_) {
    if (J > (1 + prm_.tip_tolerance) * j_tip_)
      ++n_unstable_;
    return false;
  }
  const double target = std::sqrt(j_tip_);
  struct Sample {
    double opening, root_j;
  };
  Sample lo{opening_, std::sqrt(std::max(J, 0.0))}, hi{0, 0};
  bool have_hi = false;
  double next;
  const auto& rc = result_.rcurve;
  // The critical opening is a smooth function of the tip position: extrapolate it (quadratic
  // from the last three advances) so that the first trial usually lands within the tolerance.
  const std::size_t n = rc.size();
  if (n >= 3)
    next = 3 * rc[n - 1].load_point_opening - 3 * rc[n - 2].load_point_opening +
           rc[n - 3].load_point_opening;
  else if (n == 2)
    next = 2 * rc[1].load_point_opening - rc[0].load_point_opening;
  else if (J > 0)
    next = opening_ * target / lo.root_j;
  else // first load: corrected beam theory for the LEFM initiation opening as a start
    next = law::cbt_opening(
        specimen_, material_,
        law::cbt_load_at_crack_length(specimen_, material_, j_tip_, specimen_.initial_crack),
        specimen_.initial_crack);
  for (int it = 0; it < 40; ++it) {
    if (have_hi && !(next > lo.opening && next < hi.opening))
      next = 0.5 * (lo.opening + hi.opening);
    if (!have_hi && !(next > lo.opening))
      next = 1.1 * lo.opening;
    solve_at(next);
    ++n_trials_;
    const auto t1 = Clock::now();
    J = tip_j();
    t_j_ += seconds_since(t1);
    path_.emplace_back(opening_, load_per_thickness());
    if (std::abs(J / j_tip_ - 1) <= prm_.tip_tolerance)
      return true;
    const Sample s{opening_, std::sqrt(std::max(J, 0.0))};
    if (J < j_tip_)
      lo = s;
    else {
      hi = s;
      have_hi = true;
    }
    if (have_hi)
      next =
          lo.opening + (target - lo.root_j) * (hi.opening - lo.opening) / (hi.root_j - lo.root_j);
    else
      next = s.root_j > 0 ? opening_ * target / s.root_j : 2 * opening_;
  }
  throw ComputationError("FEM: could not bring the tip J to J_tip = " + fmt(j_tip_) +
                         " J/m^2 with the tip at " + fmt(nodes_[tip_node_].x / units::mm) +
                         " mm (last J " + fmt(J) + ", opening " + fmt(opening_ / units::mm) +
                         " mm): tip J is not monotonic in the opening here");
}

void DcbModel::release_tip() {
  // The segment ahead of the tip becomes a fresh cohesive segment; the tip moves to its far end.
  const unsigned s = segment_of_left_node_[tip_node_];
  if (s == ~0u)
    throw ComputationError("FEM: the crack reached the end of the crack plane");
  interface_->open_segment(s, SegmentState::cohesive);
  tip_node_ = segment_nodes_[s].back();
  make_constraints(0.0, homogeneous_constraints_);
  ++constraints_epoch_;
}

// ---------------------------------------------------------------------------------------------
// Measurements

double DcbModel::domain_j(const Ramp& q, bool crack_face_term) const {
  // J = int_A (sigma_i1 u_i,1 - W) q,1 dA + int_faces sigma_coh d(delta)/dx q dx
  // (domain form of the contour integral with tractions on the crack faces, Moran & Shih 1987;
  // the face term is the cohesive zone inside the domain).
  const QGauss<dim> quadrature(prm_.degree + 1);
  FEValues<dim> fe_values(mapping_, fe_, quadrature,
                          update_gradients | update_JxW_values | update_quadrature_points);
  const FEValuesExtractors::Vector displacement(0);
  std::vector<Tensor<2, dim>> grad(quadrature.size());
  double J = 0;
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    const double xa = cell->vertex(0)[0], xb = cell->vertex(1)[0];
    if (xb <= q.x0 || xa >= q.x3 || (xa >= q.x1 && xb <= q.x2))
      continue;
    fe_values.reinit(cell);
    fe_values[displacement].get_function_gradients(u_, grad);
    for (unsigned k = 0; k < quadrature.size(); ++k) {
      const double dq = q.slope(fe_values.quadrature_point(k)[0]);
      if (dq == 0)
        continue;
      const SymmetricTensor<2, dim> eps = symmetrize(grad[k]);
      const SymmetricTensor<2, dim> sigma = C_ * eps;
      const double W = 0.5 * (sigma * eps);
      J += (sigma[0][0] * grad[k][0][0] + sigma[1][0] * grad[k][1][0] - W) * dq * fe_values.JxW(k);
    }
  }
  if (crack_face_term)
    J += crack_face_j(&q);
  return J;
}

double DcbModel::crack_face_j(const Ramp* ramp) const {
  double J = 0;
  const auto o = openings();
  const auto nodal = node_openings();
  for (unsigned s = 0; s < interface_->n_segments(); ++s) {
    if (interface_->state(s) == SegmentState::intact)
      continue;
    const auto& pts = interface_->segment_points(s);
    const auto& w = interface_->segment_weights(s);
    if (ramp && (interface_->x(pts.back()) <= ramp->x0 || interface_->x(pts.front()) >= ramp->x3))
      continue;
    // d(delta)/dx at each integration point from the interpolant of the nodal openings.
    for (unsigned j = 0; j < pts.size(); ++j) {
      const auto& map = point_map_[pts[j]];
      double slope = 0;
      for (unsigned a = 0; a < map.nodes.size(); ++a)
        slope += map.dN[a] * nodal[map.nodes[a]];
      const double xj = interface_->x(pts[j]);
      J += w[j] * interface_->segment_traction(s, j, o[pts[j]]) * slope *
           (ramp ? ramp->value(xj) : 1.0);
    }
  }
  return J;
}

double DcbModel::tip_j() const {
  const double x = nodes_[tip_node_].x;
  const double r = prm_.tip_domain_elements * dx_;
  // q = 1 on the elements that touch the tip: their gradients carry the largest discretization
  // error of the singular field, and keeping them out of the bulk term took the tip J from 0.9 %
  // to 0.07 % of the far-field J in the LEFM limit (Q1, 1 mm elements, 10 mm arms).
  const double p = std::max(1u, prm_.tip_domain_elements / 2) * dx_;
  return domain_j({x - r, x - p, x + p, x + r}, true);
}

double DcbModel::far_field_j() const {
  // Ramps behind the zone in the free arms (between load line and notch) and ahead of the tip in
  // the intact ligament; q = 1 over the whole zone, so no crack-face term (the zone is inside).
  const double a0 = specimen_.initial_crack, h = specimen_.arm_thickness();
  auto snap = [&](double x) { return std::round(x / dx_) * dx_; };
  const double x_tip = nodes_[tip_node_].x;
  const double x2 = x_tip + prm_.tip_domain_elements * dx_;
  return domain_j({snap(0.2 * a0), snap(0.8 * a0), x2, std::min(snap(x2 + h), x_lines_.back())},
                  false);
}

double DcbModel::stored_energy_2d() const {
  return 0.5 * bulk_stiffness_.matrix_norm_square(u_) + interface_->recoverable_energy(openings()) +
         interface_->dissipated_energy();
}

double DcbModel::load_per_thickness() const {
  Vector<double> r(u_.size());
  assemble_residual(u_, r);
  double P = 0;
  for (const auto d : load_top_)
    P += r[d];
  return P;
}

law::RCurvePoint DcbModel::record_advance() {
  const auto o = openings();
  interface_->commit(o);
  law::RCurvePoint pt;
  const double B = specimen_.width;
  const double x_tip = nodes_[tip_node_].x;
  pt.a = x_tip;

  // Notch root: the sawn-notch tip until the first cohesive point fails, then the trailing edge
  // of the zone, where the opening crosses delta_c between the last failed point and the next.
  const double dc = law_->critical_opening();
  if (dc <= 0) { // no bridging: no zone
    pt.root = x_tip;
    pt.delta_root = 0;
  } else {
    const auto nodal = node_openings();
    int last_failed = -1; // integration points are ordered by x
    for (unsigned p = 0; p < interface_->n_points(); ++p)
      if (interface_->has_failed(p))
        last_failed = int(p);
    if (last_failed < 0) {
      pt.root = nodes_[notch_node_].x;
      pt.delta_root = nodal[notch_node_];
    } else {
      const unsigned f = unsigned(last_failed);
      unsigned n = f + 1; // the next point behind in x (joint points share x)
      while (n + 1 < interface_->n_points() && !(interface_->x(n) > interface_->x(f)))
        ++n;
      const double df = o[f], dn = o[n];
      pt.root =
          (df > dn && dn < dc && df >= dc)
              ? interface_->x(f) + (df - dc) / (df - dn) * (interface_->x(n) - interface_->x(f))
              : interface_->x(n);
      pt.delta_root = dc;
    }
  }
  pt.zone_length = x_tip - pt.root;
  if (tip_node_ > 0)
    max_opening_behind_tip_ = std::max(max_opening_behind_tip_, node_openings()[tip_node_ - 1]);

  auto t0 = Clock::now();
  pt.J_tip = tip_j();
  pt.J_ff = far_field_j();
  t_j_ += seconds_since(t0);
  const double sigma_root = law_->envelope(pt.delta_root);
  pt.R_J = pt.J_ff - 0.5 * pt.delta_root * sigma_root;
  pt.R_eq2 = law::r_curve_eq2(*law_, j_tip_, pt.delta_root);

  const double P = load_per_thickness();
  pt.load = P * B;
  pt.load_point_opening = opening_;
  // External work: trapezoid over the equilibrium states since the last release (all on one
  // branch: same tip, same committed history), ending at this state.
  // Trials that overshot this opening in the secant search lie beyond this state: not on the path.
  path_.erase(
      std::remove_if(path_.begin(), path_.end(), [&](const auto& s) { return s.first > opening_; }),
      path_.end());
  path_.emplace_back(opening_, P);
  std::sort(path_.begin(), path_.end());
  for (std::size_t i = 1; i < path_.size(); ++i)
    work_2d_ +=
        0.5 * (path_[i].second + path_[i - 1].second) * (path_[i].first - path_[i - 1].first);
  path_.clear();
  const double U = 0.5 * bulk_stiffness_.matrix_norm_square(u_);
  const double U_zone = interface_->recoverable_energy(o);
  pt.external_work = work_2d_ * B;
  pt.strain_energy = U * B;
  pt.zone_recoverable = U_zone * B;
  const double dissipated = work_2d_ - U - U_zone;
  pt.dissipated = dissipated * B;
  if (!result_.rcurve.empty())
    pt.R_energy = (dissipated - dissipated_2d_.back()) / (x_tip - result_.rcurve.back().a);
  dissipated_2d_.push_back(dissipated);
  details_.zone_dissipated.push_back(interface_->dissipated_energy() * B);
  details_.tip_dissipated.push_back(tip_dissipated_2d_ * B);
  details_.j_after_release.push_back(j_after_release_);
  // Eq. 1 term measured on the FE fields: minus the crack-face term with q = 1 everywhere.
  details_.zone_integral.push_back(-crack_face_j(nullptr));
  return pt;
}

// ---------------------------------------------------------------------------------------------
// Output

void DcbModel::output_fields(unsigned int advance) {
  if (output_dir_.empty())
    return;
  const auto t0 = Clock::now();
  DataOut<dim> data_out;
  data_out.attach_dof_handler(dof_handler_);
  const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector_field(
      dim, DataComponentInterpretation::component_is_part_of_vector);
  data_out.add_data_vector(u_, std::vector<std::string>(dim, "displacement_m"),
                           DataOut<dim>::type_dof_data, vector_field);
  const StressPostprocessor<dim> stress(C_);
  data_out.add_data_vector(u_, stress);
  data_out.build_patches(mapping_, prm_.degree);
  std::ostringstream name;
  name << "fem_dcb-" << std::setw(4) << std::setfill('0') << advance << ".vtu";
  std::ofstream vtu(output_dir_ + "/" + name.str());
  data_out.write_vtu(vtu);
  // Time axis of the series: the crack-tip position in mm.
  pvd_records_.emplace_back(nodes_[tip_node_].x / units::mm, name.str());
  std::ofstream pvd(output_dir_ + "/fem_dcb.pvd");
  DataOutBase::write_pvd_record(pvd, pvd_records_);
  t_output_ += seconds_since(t0);
}

void DcbModel::write_interface_csv() const {
  if (output_dir_.empty())
    return;
  CsvWriter w(output_dir_ + "/fem_interface.csv",
              {"x_mm", "opening_mm", "traction_kPa", "delta_max_mm", "state"},
              {"fiberbridge fem: crack-plane interface at the end of the run, one row per "
               "integration point (x from the load line; segment ends appear once per segment)",
               "state: 0 tied (intact ligament), 1 traction-free (sawn notch), 2 cohesive, "
               "3 failed (opening past delta_c: traction-free, contact only)"});
  const auto o = openings();
  for (unsigned seg = 0; seg < interface_->n_segments(); ++seg) {
    const auto state = interface_->state(seg);
    for (const unsigned p : interface_->segment_points(seg)) {
      double code = 0;
      if (state == SegmentState::traction_free)
        code = 1;
      else if (state == SegmentState::cohesive)
        code = interface_->has_failed(p) ? 3 : 2;
      const double traction =
          state == SegmentState::intact ? 0.0 : interface_->respond(p, o[p]).traction;
      w.row({interface_->x(p) / units::mm, o[p] / units::mm, traction / units::kPa,
             interface_->delta_max(p) / units::mm, code});
    }
  }
  w.close();
}

// ---------------------------------------------------------------------------------------------
// The algorithm

bool DcbModel::reached_steady_state(double first_root_move) {
  return check_steady_state(result_, dissipated_2d_, first_root_move, prm_);
}

law::SimulationResult DcbModel::run() {
  const auto start = Clock::now();
  result_.model = "fem";
  make_grid();
  setup_system();
  assemble_bulk_stiffness();
  make_constraints(0.0, homogeneous_constraints_);
  result_.n_dofs_or_particles = long(dof_handler_.n_dofs());
  if (!output_dir_.empty())
    std::filesystem::create_directories(output_dir_);
  report("fem: " + std::to_string(triangulation_.n_active_cells()) + " cells, " +
         std::to_string(dof_handler_.n_dofs()) + " dofs, Q" + std::to_string(prm_.degree) +
         ", element " + fmt(dx_ / units::mm) + " mm");

  const double L = specimen_.length, h = specimen_.arm_thickness();
  const double a0 = specimen_.initial_crack;
  double first_root_move = -1;
  unsigned advance = 0;
  path_.emplace_back(0.0, 0.0);
  while (true) {
    // The far-field J domain needs the tip strip and one arm thickness of intact ligament.
    if (nodes_[tip_node_].x + prm_.tip_domain_elements * dx_ + h > L + 1e-9 * L) {
      if (result_.rcurve.empty())
        throw InputError(
            "Specimen: the ligament (Length - Initial crack = " + fmt((L - a0) / units::mm) +
            " mm) is shorter than the J domains "
            "ahead of the tip need (tip strip + one arm thickness = " +
            fmt((prm_.tip_domain_elements * dx_ + h) / units::mm) + " mm)");
      if (first_root_move < 0)
        result_.notes.push_back(
            "no steady state: zone longer than ligament (the notch root never moved; the tip "
            "reached " +
            fmt(nodes_[tip_node_].x / units::mm) + " mm)");
      else
        result_.notes.push_back("no steady state: R_J did not settle within " +
                                fmt(prm_.steady_state_window / units::mm) +
                                " mm before the ligament ran out");
      break;
    }
    load_to_critical();
    const law::RCurvePoint pt = record_advance();
    law::check_rcurve_point(pt); // NaN/Inf ends the run naming the column
    result_.rcurve.push_back(pt);
    if (first_root_move < 0 && pt.root > a0 + 1e-9 * L)
      first_root_move = pt.a;
    if (advance % 10 == 0)
      report("fem: a = " + fmt(pt.a / units::mm) + " mm, root " + fmt(pt.root / units::mm) +
             " mm, opening " + fmt(pt.load_point_opening / units::mm) + " mm, load " +
             fmt(pt.load) + " N, J_tip " + fmt(pt.J_tip) + ", R_J " + fmt(pt.R_J) + " J/m^2");

    if (first_root_move >= 0 && reached_steady_state(first_root_move))
      break;
    ++advance;
    if (prm_.output_every > 0 && advance % prm_.output_every == 0)
      output_fields(advance);
    const double before = stored_energy_2d();
    release_tip();
    solve_at(opening_); // re-equilibrate at fixed opening after the release
    interface_->commit(openings());
    tip_dissipated_2d_ += before - stored_energy_2d(); // no external work at fixed opening
    path_.emplace_back(opening_, load_per_thickness());
  }
  output_fields(advance + 1);
  write_interface_csv();

  // Resolution next to the tip: the first element behind the tip holds openings from zero to
  // the first node's opening. If that passes the end of the law's first linear branch (the
  // elastic rise), the traction varies strongly inside one element.
  const auto kinks = law_->kinks();
  const double rise = kinks.size() > 1 ? kinks[1] : law_->critical_opening();
  if (rise > 0 && max_opening_behind_tip_ > rise)
    result_.notes.push_back(
        "resolution: the opening one element behind the tip reached " +
        fmt(max_opening_behind_tip_ / units::mm) + " mm, past the law's first linear branch (" +
        fmt(rise / units::mm) +
        " mm): the traction varies strongly within the tip element, "
        "integrated with " +
        std::to_string(prm_.interface_subintervals) +
        " sub-intervals per element; if R_J falls below Eq. 2, refine FEM/Element size or raise "
        "FEM/Interface sub-intervals" +
        (regularized_law_ ? " (or lower FEM/Rigid law stiffness "
                            "factor)"
                          : ""));
  details_.unstable_advances = n_unstable_;
  details_.simulated_law_area = law_->area();
  result_.wall_time_s = seconds_since(start);
  result_.method.push_back(
      "tip criterion: domain J over a full-height strip of +-" +
      std::to_string(prm_.tip_domain_elements) +
      " elements (q = 1 on the inner half) with the "
      "cohesive crack-face term; "
      "J_ff: domain J with q = 1 over the whole zone (ramps in the free arms behind the notch "
      "and one arm thickness ahead of the tip)");
  result_.method.push_back(
      std::string("load line at x = 0 (left end, no overhang), ties by AffineConstraints, ") +
      direct_solver_.name() + " direct solver, " +
      (prm_.nonlinear_solver == FemParameters::NonlinearSolver::kinsol
           ? "SUNDIALS KINSOL with line search"
           : "own Newton with line search"));
  result_.notes.push_back(std::to_string(n_unstable_) +
                          " advances at fixed load-point opening (tip J above J_tip after a "
                          "release: unstable growth)");
  result_.method.push_back(
      "time " + fmt(result_.wall_time_s, 3) + " s: " + std::to_string(n_trials_) +
      " equilibrium solves to find the critical openings, " + std::to_string(n_newton_) +
      " Newton iterations, " + std::to_string(n_factorizations_) + " factorizations " +
      fmt(t_factorize_, 3) + " s, " + std::to_string(n_solves_) + " solves " + fmt(t_solve_, 3) +
      " s, residuals/line search " + fmt(t_residual_, 3) + " s, J integrals " + fmt(t_j_, 3) +
      " s, output " + fmt(t_output_, 3) + " s");
  report("fem: done, " + std::to_string(result_.rcurve.size()) + " advances in " +
         fmt(result_.wall_time_s, 3) + " s");
  return result_;
}

} // namespace

law::SimulationResult simulate_dcb(const law::Specimen& specimen, const law::Material& material,
                                   const law::TractionLaw& law, double j_tip,
                                   const FemParameters& parameters, const std::string& output_dir,
                                   const std::function<void(const std::string&)>& progress) {
  FemRunDetails details;
  return simulate_dcb(specimen, material, law, j_tip, parameters, output_dir, progress, details);
}

law::SimulationResult simulate_dcb(const law::Specimen& specimen, const law::Material& material,
                                   const law::TractionLaw& law, double j_tip,
                                   const FemParameters& parameters, const std::string& output_dir,
                                   const std::function<void(const std::string&)>& progress,
                                   FemRunDetails& details) {
  law::begin_fault_context("fem");
  DcbModel model(specimen, material, law, j_tip, parameters, output_dir, progress);
  auto result = model.run();
  details = model.details();
  return result;
}

} // namespace fiberbridge::fem
