#pragma once
// The FEM engine of the DCB (distributed_dcb.h, dcb_simulation.h), templated on the space
// dimension and instantiated in distributed_dcb_2d.cc and distributed_dcb_3d.cc (one heavy
// translation unit each, so that they compile in parallel). One engine (issue 14): on one rank
// (MPI_COMM_SELF) it is the serial program, as in deal.II's step-40.
//
// The algorithm (run()) in the paper's words (seed section 2.4): start from the sawn notch with
// no cohesive zone; raise the load-point opening until the crack-tip energy release rate reaches
// J_tip; release the tip node, which turns the segment ahead of the old tip into a fresh
// cohesive segment; repeat. The zone grows behind the tip, its trailing edge (the notch root)
// starts to move when the opening there passes delta_c, and the run stops at steady state.
//
// Choices:
// - Crack plane doubled: the two arms are separate meshes on a vertex list of our own (in 3D
//   extruded over the width), the coarse mesh of a parallel::distributed::Triangulation. p4est
//   builds its tree connectivity from shared vertices, and the two arms share none on the crack
//   plane, so the slit stays open; p4est partitions the cells (no refinement).
// - Ahead of the tip the arms are tied by AffineConstraints (u_top = u_bottom per support point
//   pair): exact, no penalty to tune, and release is removing a constraint line.
// - Tip criterion: a domain J integral over a full-height strip around the tip, with the
//   cohesive crack-face term (Moran & Shih). It is degree-independent and uses the same code as
//   the far-field J, so tip J and J_ff are measured alike and their difference checks Eq. 1.
// - The load-point opening at which tip J equals J_tip is found by a secant iteration on
//   sqrt(J) (exact in one step for linear elasticity). When tip J exceeds J_tip right after a
//   release (unstable growth), the tip advances again at fixed opening.
// - Nonlinear solver (FEM/Nonlinear solver): own Newton with backtracking line search on the
//   condensed residual (default), or SUNDIALS KINSOL with its line search on the same residual,
//   Jacobian and linear solves. The release-library KINSOL does not report failure: its result is
//   re-checked against the same convergence test.
// - The crack plane (ties, cohesive points, the notch-root bookkeeping) is small next to the
//   bulk: every rank holds ALL crack-plane dofs as ghosts (gathered with all_gather) and keeps an
//   identical copy of the CohesiveInterface. With both dofs of a tied pair relevant everywhere,
//   AffineConstraints condenses ties across ranks; each row of crack-plane faces (a "segment",
//   the whole width in 3D) is assembled by the rank that owns its first top dof.
// - Every decision that steers the algorithm (convergence, line search, tip J against J_tip)
//   uses global sums, so all ranks take the same branch.
// - Residual: K u (the bulk stiffness assembled once) plus the interface forces, condensed.
// - Linear solves (FEM/Linear solver): Amesos KLU or MUMPS on the condensed Jacobian, whose
//   pattern follows the tie set; factorized after each release. Between releases the Jacobian
//   differs from the factorized one only at the interface points that changed branch: a low-rank
//   (Woodbury) correction, built from global dot products only. Or CG + ML AMG on an SPD secant
//   Jacobian, set up again at every change.
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/cohesive_interface.h"
#include "fiberbridge/fem/dcb_common.h"
#include "fiberbridge/fem/distributed_dcb.h"
#include "fiberbridge/result/numerical_fault.h"
#include "fiberbridge/result/steady_state.h"

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/sundials/kinsol.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <unordered_map>

namespace fiberbridge::fem::distributed {

using namespace dealii;
using Vec = TrilinosWrappers::MPI::Vector;

template <int dim>
class DistributedDcbModel {
public:
  DistributedDcbModel(const specimen::Specimen& specimen, const specimen::Material& material,
                      const law::TractionLaw& law, double j_tip, const FemParameters& parameters,
                      const std::string& output_dir,
                      const std::function<void(const std::string&)>& progress, MPI_Comm comm);
  result::SimulationResult run();
  const DistributedRunInfo& info() const { return info_; }
  const FemRunDetails& details() const { return details_; }

private:
  /// One pair of coincident crack-plane support points (a "node"), at station (ix, iz).
  struct Node {
    double x = 0, z = 0;
    types::global_dof_index top[dim], bottom[dim];
  };
  struct PointMap {
    std::vector<unsigned> nodes; ///< global node indices
    std::vector<unsigned> local; ///< their positions in the segment's node list
    std::vector<double> N, dN;   ///< Lagrange weights and their x-derivatives
  };
  /// Interface points at one x inside one segment (all z in 3D), with their z weights.
  struct Station {
    std::vector<unsigned> points;
    std::vector<double> wz;
  };

  // Setup.
  void make_grid();
  void setup_system();
  void make_interface();
  void make_constraints(double opening, AffineConstraints<double>& c) const;
  // Algebra.
  double gsum(double local) const;
  double norm(const Vec& v) const;
  void assemble_residual(const Vec& u, Vec& r, Vec& r_full);
  void update_jacobian();
  void solve_linear(const Vec& rhs, Vec& x);
  void predict(double opening);
  double reaction_norm(const Vec& r_full) const;
  bool newton(double opening, std::string& diagnosis);
  double roundoff_floor(const Vec& u) const; ///< residual norm below which round-off rules [N/m]
  /// "; N crack-face points in contact at x = ... mm" for a failed solve's diagnosis (on u_).
  std::string contact_summary();
  bool kinsol(double opening, std::string& diagnosis);
  void solve_at(double target);
  void sync() { u_ghost_ = u_; }
  // Growth.
  bool load_to_critical();
  void release_tip();
  // Measurements (on u_ghost_).
  std::vector<double> node_openings() const;
  std::vector<double> openings() const;
  double station_opening(unsigned ix, const std::vector<double>& nodal) const;
  double domain_j(const Ramp& q, bool crack_face_term) const;
  double crack_face_j(const Ramp* ramp) const;
  double tip_j() const;
  double far_field_j() const;
  double bulk_energy() const; ///< per width [J/m]
  double stored_energy() const;
  double load_per_width();
  result::RCurvePoint record_advance();
  /// The shared rule (result::find_steady_state); reports and returns true once reached.
  bool reached_steady_state(bool final_state);
  void output_fields(unsigned advance);
  void write_interface_csv() const;
  void report(const std::string& line) const {
    if (progress_ && rank_ == 0)
      progress_(line);
  }
  unsigned node_index(unsigned ix, unsigned iz) const { return ix * n_z_ + iz; }

  const specimen::Specimen specimen_;
  const specimen::Material material_;
  const law::TractionLaw& user_law_;
  std::unique_ptr<law::ElasticRiseLaw> regularized_law_;
  const law::TractionLaw* law_ = nullptr;
  const double j_tip_;
  const FemParameters prm_;
  const std::string output_dir_;
  const std::function<void(const std::string&)> progress_;
  const MPI_Comm comm_;
  const unsigned rank_, n_ranks_;
  const SymmetricTensor<4, dim> C_;
  /// Width over which the 3D fields are integrated (1 m in 2D: the 2D fields are per width).
  double width_ = 1;

  parallel::distributed::Triangulation<dim> triangulation_;
  FESystem<dim> fe_;
  DoFHandler<dim> dof_handler_;
  MappingQ1<dim> mapping_;
  std::vector<double> x_lines_, z_lines_;
  double dx_ = 0;

  IndexSet owned_, relevant_;
  std::vector<Node> nodes_; ///< sorted by x, then z
  std::vector<double> x_st_, z_st_;
  unsigned n_z_ = 1;
  std::vector<double> node_zw_; ///< width weight of each z station (sum = width_)
  std::vector<types::global_dof_index> load_top_, load_bottom_, support_;
  /// Component and support point of each locally owned dof (by index within owned_), for the
  /// rigid-body modes of the AMG near null space.
  std::vector<std::array<double, 4>> owned_support_;
  std::vector<double> owned_arm_; ///< +1 top arm, -1 bottom arm, by index within owned_

  std::unique_ptr<CohesiveInterface> interface_;
  std::vector<PointMap> point_map_;
  std::vector<double> point_z_;
  std::vector<Station> stations_;
  std::vector<std::vector<unsigned>> segment_stations_; ///< x-station indices of a segment
  std::vector<std::vector<unsigned>> segment_nodes_;    ///< node indices of a segment
  std::vector<std::vector<unsigned>> segment_points_;
  std::vector<bool> segment_mine_; ///< this rank assembles the segment
  std::vector<unsigned> segment_of_left_station_;
  unsigned tip_ = 0, notch_ = 0; ///< x-station indices

  /// Bulk cell matrices: the mesh has few distinct cell shapes (a size per layer), so one
  /// matrix per shape instead of one per cell or a reassembly per Newton step.
  std::vector<FullMatrix<double>> shape_matrices_;
  std::vector<unsigned> cell_shape_; ///< by active_cell_index, for locally owned cells

  /// The bulk stiffness K, unconstrained (the residual is K u plus the interface forces,
  /// condensed afterwards), on the extended sparsity pattern.
  TrilinosWrappers::SparseMatrix bulk_;
  /// The condensed Jacobian that the direct solver (or AMG) refers to.
  TrilinosWrappers::SparseMatrix jacobian_;
  std::unique_ptr<TrilinosWrappers::SolverDirect> direct_;
  SolverControl direct_control_;
  TrilinosWrappers::PreconditionAMG amg_;
  AffineConstraints<double> hom_;
  unsigned epoch_ = 0, factorized_epoch_ = ~0u;
  std::vector<double> factorized_tangents_;
  void factorize(const std::vector<double>& tangents);
  void condense(const Vec& full, Vec& out);
  void condensed_pattern();
  unsigned pattern_epoch_ = ~0u;
  /// Woodbury correction of the factorized Jacobian: changed point -> (tangent change dk, the
  /// condensed opening operator c of the point, A^-1 c). Only global dot products combine
  /// them, so the correction works on any number of ranks.
  struct LowRankTerm {
    double dk = 0;
    Vec c, z;
  };
  std::map<unsigned, LowRankTerm> low_rank_;
  std::vector<const LowRankTerm*> woodbury_; ///< the active terms (dk != 0)
  FullMatrix<double> woodbury_inverse_;      ///< (D^-1 + U^T Z)^-1 of the active terms
  std::map<std::pair<unsigned, unsigned>, double> cz_;
  LowRankTerm low_rank_term(unsigned p);

  Vec u_, u_ghost_, scratch_ghost_, residual_ghost_;
  double opening_ = 0;
  double work_ = 0; ///< external work per width [J/m]
  std::vector<std::pair<double, double>> path_;

  result::SimulationResult result_;
  DistributedRunInfo info_;
  double max_opening_behind_tip_ = 0;
  double tip_dissipated_ = 0;                      ///< energy released by the releases [J/m]
  double j_after_release_ = result::not_available; ///< tip J right after the last release
  FemRunDetails details_;
  unsigned n_trials_ = 0, n_unstable_ = 0;
  std::vector<std::pair<double, std::string>> pvd_records_;
};

// ---------------------------------------------------------------------------------------------

template <int dim>
DistributedDcbModel<dim>::DistributedDcbModel(
    const specimen::Specimen& specimen, const specimen::Material& material,
    const law::TractionLaw& law, double j_tip, const FemParameters& parameters,
    const std::string& output_dir, const std::function<void(const std::string&)>& progress,
    MPI_Comm comm)
    : specimen_(specimen), material_(material), user_law_(law), j_tip_(j_tip), prm_(parameters),
      output_dir_(output_dir), progress_(progress), comm_(comm),
      rank_(Utilities::MPI::this_mpi_process(comm)),
      n_ranks_(Utilities::MPI::n_mpi_processes(comm)),
      C_(orthotropic_stiffness<dim>(material, parameters)), triangulation_(comm),
      fe_(FE_Q<dim>(parameters.degree), dim), dof_handler_(triangulation_) {
  specimen_.validate();
  material_.validate();
  prm_.validate();
  if (!(j_tip > 0))
    throw InputError("Cohesive law/J tip: the FEM tip criterion needs J tip > 0");
  if (dim == 3)
    width_ = specimen_.width;
  law_ = insertable_law(law, material, prm_, regularized_law_, result_.notes);
  for (const auto& note : prm_.deprecation_notes)
    result_.notes.push_back(note);
}

template <int dim>
double DistributedDcbModel<dim>::gsum(double local) const {
  // Reduce on rank 0 and broadcast: every rank gets the same bits (an allreduce need not), so
  // all ranks take the same branch in every test that uses the value.
  double global = 0;
  MPI_Reduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, 0, comm_);
  MPI_Bcast(&global, 1, MPI_DOUBLE, 0, comm_);
  return global;
}

template <int dim>
double DistributedDcbModel<dim>::norm(const Vec& v) const {
  double s = 0;
  for (auto it = v.begin(); it != v.end(); ++it)
    s += *it * *it;
  return std::sqrt(gsum(s));
}

// ---------------------------------------------------------------------------------------------
// Setup

template <int dim>
void DistributedDcbModel<dim>::make_grid() {
  // x and y lines from dcb_mesh_lines (one element per advance, graded heights).
  const DcbMeshLines lines = dcb_mesh_lines(specimen_, prm_);
  dx_ = lines.dx;
  x_lines_ = lines.x;
  const std::vector<double>& y_lines = lines.y;
  z_lines_ = {0.0};
  if (dim == 3) {
    const unsigned nz = prm_.width_elements > 0
                            ? prm_.width_elements
                            : std::max(1u, unsigned(std::lround(specimen_.width / dx_)));
    for (unsigned k = 1; k <= nz; ++k)
      z_lines_.push_back(specimen_.width * k / nz);
  }

  const unsigned nx = x_lines_.size() - 1, ny = y_lines.size() - 1;
  const unsigned nzl = dim == 3 ? z_lines_.size() : 1; // vertex layers in z
  std::vector<Point<dim>> vertices;
  for (int side : {+1, -1}) // top arm, then the bottom arm with its own crack-plane vertices
    for (unsigned k = 0; k < nzl; ++k)
      for (unsigned j = 0; j <= ny; ++j)
        for (unsigned i = 0; i <= nx; ++i) {
          Point<dim> p;
          p[0] = x_lines_[i];
          p[1] = side * y_lines[j];
          if (dim == 3)
            p[dim - 1] = z_lines_[k];
          vertices.push_back(p);
        }
  auto index = [&](unsigned arm, unsigned i, unsigned j, unsigned k) {
    return arm * (nx + 1) * (ny + 1) * nzl + k * (nx + 1) * (ny + 1) + j * (nx + 1) + i;
  };
  std::vector<CellData<dim>> cells;
  for (unsigned arm = 0; arm < 2; ++arm)
    for (unsigned k = 0; k < (dim == 3 ? nzl - 1 : 1u); ++k) {
      for (unsigned j = 0; j < ny; ++j)
        for (unsigned i = 0; i < nx; ++i) {
          CellData<dim> c;
          // Lexicographic vertex order (x fastest, then y increasing, then z): the bottom arm
          // counts j downwards, so its "lower" row is j + 1.
          unsigned v = 0;
          for (unsigned dz = 0; dz < (dim == 3 ? 2u : 1u); ++dz)
            for (unsigned dy = 0; dy < 2; ++dy)
              for (unsigned di = 0; di < 2; ++di) {
                const unsigned jj = arm == 0 ? j + dy : j + 1 - dy;
                c.vertices[v++] = index(arm, i + di, jj, k + dz);
              }
          c.material_id = arm; // 0 top, 1 bottom
          cells.push_back(c);
        }
    }
  triangulation_.create_triangulation(vertices, cells, SubCellData());
}

template <int dim>
void DistributedDcbModel<dim>::setup_system() {
  const auto t0 = Clock::now();
  dof_handler_.distribute_dofs(fe_);
  owned_ = dof_handler_.locally_owned_dofs();
  IndexSet relevant;
  DoFTools::extract_locally_relevant_dofs(dof_handler_, relevant);

  // Crack-plane and load-line dofs of the owned cells, gathered on every rank:
  // (kind 0 crack / 1 load, x, z, component, top?, dof) as doubles (dofs < 2^53).
  const double tol = 1e-9 * specimen_.length;
  const Quadrature<dim> support(fe_.get_unit_support_points());
  FEValues<dim> fv(mapping_, fe_, support, update_quadrature_points);
  std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
  std::vector<double> mine;
  owned_support_.assign(owned_.n_elements(), {{0, 0, 0, 0}});
  owned_arm_.assign(owned_.n_elements(), 0.0);
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    if (!cell->is_locally_owned())
      continue;
    fv.reinit(cell);
    cell->get_dof_indices(dofs);
    const double top = cell->material_id() == 0 ? 1 : 0;
    for (unsigned i = 0; i < dofs.size(); ++i) {
      const auto& p = fv.quadrature_point(i);
      const double c = fe_.system_to_component_index(i).first;
      const double z = dim == 3 ? p[dim - 1] : 0.0;
      if (owned_.is_element(dofs[i])) {
        owned_support_[owned_.index_within_set(dofs[i])] = {{c, p[0], p[1], z}};
        owned_arm_[owned_.index_within_set(dofs[i])] = top > 0 ? 1.0 : -1.0;
      }
      if (std::abs(p[1]) < tol)
        mine.insert(mine.end(), {0, p[0], z, c, top, double(dofs[i])});
      if (std::abs(p[0]) < tol && c == 1)
        mine.insert(mine.end(), {1, p[0], z, c, top, double(dofs[i])});
    }
  }
  const auto all = Utilities::MPI::all_gather(comm_, mine);
  auto key = [&](double v) { return std::llround(v / tol); };
  std::map<std::pair<long long, long long>, Node> by_xz;
  std::map<std::pair<long long, long long>, std::array<int, 2 * dim>> filled;
  std::set<types::global_dof_index> load_top, load_bottom;
  for (const auto& block : all)
    for (std::size_t r = 0; r + 6 <= block.size(); r += 6) {
      const auto dof = types::global_dof_index(std::llround(block[r + 5]));
      const bool top = block[r + 4] > 0.5;
      if (block[r] > 0.5) {
        (top ? load_top : load_bottom).insert(dof);
        continue;
      }
      const auto k = std::make_pair(key(block[r + 1]), key(block[r + 2]));
      const unsigned c = unsigned(block[r + 3]);
      auto& n = by_xz[k];
      n.x = block[r + 1];
      n.z = block[r + 2];
      (top ? n.top : n.bottom)[c] = dof;
      filled[k][(top ? 0 : dim) + c] = 1;
    }
  for (const auto& [k, f] : filled)
    if (std::count(f.begin(), f.end(), 1) != 2 * dim)
      throw ComputationError("FEM mesh: a crack-plane support point has no partner on the "
                             "other arm (mesh generation error)");
  nodes_.clear();
  std::set<long long> xs, zs;
  for (const auto& [k, n] : by_xz) {
    nodes_.push_back(n);
    xs.insert(k.first);
    zs.insert(k.second);
  }
  n_z_ = zs.size();
  x_st_.clear();
  z_st_.clear();
  for (unsigned a = 0; a < nodes_.size(); a += n_z_)
    x_st_.push_back(nodes_[a].x);
  for (unsigned b = 0; b < n_z_; ++b)
    z_st_.push_back(nodes_[b].z);
  if (nodes_.size() != xs.size() * zs.size())
    throw ComputationError("FEM mesh: the crack-plane nodes do not form a grid in x and z");
  load_top_.assign(load_top.begin(), load_top.end());
  load_bottom_.assign(load_bottom.begin(), load_bottom.end());
  // Rigid-body modes: the crack-plane line at x = L is held in x and y (in 2D the
  // crack-plane point); in 3D its z = 0 end also in z. The load line fixes the rotations
  // about x and z, the line the rotation about y. It carries no load under symmetric opening.
  support_.clear();
  for (unsigned iz = 0; iz < n_z_; ++iz) {
    const auto& n = nodes_[node_index(x_st_.size() - 1, iz)];
    support_.push_back(n.bottom[0]);
    support_.push_back(n.bottom[1]);
    if (dim == 3 && iz == 0)
      support_.push_back(n.bottom[dim - 1]);
  }

  // Relevant = the usual ghosts + every crack-plane and load-line dof (small sets), so that
  // every rank has every tie, load and support constraint and every crack-plane value.
  std::vector<types::global_dof_index> special;
  for (const auto& n : nodes_)
    for (unsigned d = 0; d < dim; ++d) {
      special.push_back(n.top[d]);
      special.push_back(n.bottom[d]);
    }
  special.insert(special.end(), load_top_.begin(), load_top_.end());
  special.insert(special.end(), load_bottom_.begin(), load_bottom_.end());
  std::sort(special.begin(), special.end());
  special.erase(std::unique(special.begin(), special.end()), special.end());
  relevant_ = relevant;
  relevant_.add_indices(special.begin(), special.end());
  relevant_.compress();

  // The bulk stiffness has the plain cell couplings; the Jacobian's pattern follows the tie set
  // (condensed_pattern(), rebuilt at each release).
  DynamicSparsityPattern dsp(relevant_);
  for (const auto& cell : dof_handler_.active_cell_iterators())
    if (cell->is_locally_owned()) {
      cell->get_dof_indices(dofs);
      for (const auto i : dofs)
        dsp.add_entries(i, dofs.begin(), dofs.end());
    }
  SparsityTools::distribute_sparsity_pattern(dsp, owned_, comm_, relevant_);
  bulk_.reinit(owned_, owned_, dsp, comm_);
  u_.reinit(owned_, comm_);
  u_ghost_.reinit(owned_, relevant_, comm_);
  scratch_ghost_.reinit(owned_, relevant_, comm_);
  residual_ghost_.reinit(owned_, relevant_, comm_);

  // Bulk cell matrices by cell shape (vertex offsets from vertex 0, rounded).
  const QGauss<dim> quadrature(prm_.degree + 1);
  FEValues<dim> fe_values(mapping_, fe_, quadrature, update_gradients | update_JxW_values);
  const FEValuesExtractors::Vector displacement(0);
  const unsigned n = fe_.n_dofs_per_cell();
  std::map<std::vector<long long>, unsigned> shapes;
  std::vector<SymmetricTensor<2, dim>> eps(n);
  cell_shape_.assign(triangulation_.n_active_cells(), ~0u);
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    if (!cell->is_locally_owned())
      continue;
    std::vector<long long> k;
    for (unsigned v = 1; v < cell->n_vertices(); ++v)
      for (unsigned d = 0; d < dim; ++d)
        k.push_back(key(cell->vertex(v)[d] - cell->vertex(0)[d]));
    const auto it = shapes.find(k);
    if (it != shapes.end()) {
      cell_shape_[cell->active_cell_index()] = it->second;
      continue;
    }
    fe_values.reinit(cell);
    FullMatrix<double> m(n, n);
    for (unsigned q = 0; q < quadrature.size(); ++q) {
      for (unsigned i = 0; i < n; ++i)
        eps[i] = fe_values[displacement].symmetric_gradient(i, q);
      for (unsigned i = 0; i < n; ++i) {
        const SymmetricTensor<2, dim> sigma_i = C_ * eps[i];
        for (unsigned j = 0; j <= i; ++j)
          m(i, j) += sigma_i * eps[j] * fe_values.JxW(q);
      }
    }
    for (unsigned i = 0; i < n; ++i)
      for (unsigned j = 0; j < i; ++j)
        m(j, i) = m(i, j);
    shapes.emplace(k, shape_matrices_.size());
    cell_shape_[cell->active_cell_index()] = shape_matrices_.size();
    shape_matrices_.push_back(std::move(m));
  }
  for (const auto& cell : dof_handler_.active_cell_iterators())
    if (cell->is_locally_owned()) {
      cell->get_dof_indices(dofs);
      bulk_.add(dofs, shape_matrices_[cell_shape_[cell->active_cell_index()]]);
    }
  bulk_.compress(VectorOperation::add);
  make_interface();
  info_.t_setup += seconds_since(t0);
}

template <int dim>
void DistributedDcbModel<dim>::make_interface() {
  const double tol = 1e-9 * specimen_.length;
  interface_ = std::make_unique<CohesiveInterface>(*law_, prm_.contact_stiffness_factor *
                                                              material_.E_T / prm_.element_size);
  auto station_at = [&](const std::vector<double>& st, double v, const char* what) {
    const auto it = std::lower_bound(st.begin(), st.end(), v - tol);
    if (it == st.end() || std::abs(*it - v) > tol)
      throw ComputationError(std::string("FEM mesh: no crack-plane node at ") + what + " = " +
                             fmt(v));
    return unsigned(it - st.begin());
  };
  // Lagrange basis over the node positions `pos` at v, and its derivative.
  auto lagrange = [](const std::vector<double>& pos, double v, std::vector<double>& N,
                     std::vector<double>& dN) {
    N.assign(pos.size(), 1.0);
    dN.assign(pos.size(), 0.0);
    for (unsigned a = 0; a < pos.size(); ++a)
      for (unsigned b = 0; b < pos.size(); ++b) {
        if (b == a)
          continue;
        double term = 1 / (pos[a] - pos[b]);
        for (unsigned c = 0; c < pos.size(); ++c)
          if (c != a && c != b)
            term *= (v - pos[c]) / (pos[a] - pos[c]);
        dN[a] += term;
        N[a] *= (v - pos[b]) / (pos[a] - pos[b]);
      }
  };
  const QGaussLobatto<1> lobatto(prm_.degree + 1);
  // z rule: per face across the width the nodal Lobatto rule (2D: one point of weight 1).
  struct ZPoint {
    double z, w;
    std::vector<unsigned> iz;
    std::vector<double> N;
  };
  std::vector<ZPoint> zpoints;
  node_zw_.assign(n_z_, 0.0);
  if (dim == 2) {
    zpoints.push_back({0.0, 1.0, {0}, {1.0}});
    node_zw_[0] = 1;
  } else
    for (unsigned k = 0; k + 1 < z_lines_.size(); ++k) {
      const double len = z_lines_[k + 1] - z_lines_[k];
      std::vector<unsigned> iz;
      std::vector<double> pos;
      for (unsigned q = 0; q < lobatto.size(); ++q) {
        iz.push_back(station_at(z_st_, z_lines_[k] + lobatto.point(q)[0] * len, "z"));
        pos.push_back(z_st_[iz.back()]);
      }
      for (unsigned q = 0; q < lobatto.size(); ++q) {
        ZPoint zp;
        zp.z = z_lines_[k] + lobatto.point(q)[0] * len;
        zp.w = lobatto.weight(q) * len;
        zp.iz = iz;
        std::vector<double> dN;
        lagrange(pos, zp.z, zp.N, dN);
        node_zw_[iz[q]] += zp.w;
        zpoints.push_back(zp);
      }
    }

  const unsigned m = prm_.interface_subintervals;
  segment_of_left_station_.assign(x_st_.size(), ~0u);
  const IndexSet& owned = owned_;
  for (unsigned f = 0; f + 1 < x_lines_.size(); ++f) {
    const double xl = x_lines_[f], len = x_lines_[f + 1] - xl;
    std::vector<unsigned> seg_st;
    std::vector<double> pos;
    for (unsigned q = 0; q < lobatto.size(); ++q) {
      seg_st.push_back(station_at(x_st_, xl + lobatto.point(q)[0] * len, "x"));
      pos.push_back(x_st_[seg_st.back()]);
    }
    std::vector<unsigned> seg_nodes;
    for (const unsigned ix : seg_st)
      for (unsigned iz = 0; iz < n_z_; ++iz)
        seg_nodes.push_back(node_index(ix, iz));
    // Composite Lobatto in x (joints of sub-intervals merged).
    std::vector<double> xs, ws;
    for (unsigned i = 0; i < m; ++i)
      for (unsigned q = 0; q < lobatto.size(); ++q) {
        const double x = xl + (i + lobatto.point(q)[0]) / m * len;
        const double w = lobatto.weight(q) * len / m;
        if (!xs.empty() && std::abs(x - xs.back()) < tol)
          ws.back() += w;
        else {
          xs.push_back(x);
          ws.push_back(w);
        }
      }
    std::vector<unsigned> pts;
    std::vector<double> weights;
    std::vector<double> Nx, dNx;
    for (unsigned i = 0; i < xs.size(); ++i) {
      lagrange(pos, xs[i], Nx, dNx);
      Station station;
      for (const auto& zp : zpoints) {
        PointMap map;
        for (unsigned a = 0; a < seg_st.size(); ++a)
          for (unsigned c = 0; c < zp.iz.size(); ++c) {
            const unsigned node = node_index(seg_st[a], zp.iz[c]);
            map.nodes.push_back(node);
            map.local.push_back(
                unsigned(std::find(seg_nodes.begin(), seg_nodes.end(), node) - seg_nodes.begin()));
            map.N.push_back(Nx[a] * zp.N[c]);
            map.dN.push_back(dNx[a] * zp.N[c]);
          }
        point_map_.push_back(std::move(map));
        point_z_.push_back(zp.z);
        const unsigned p = interface_->add_point(xs[i]);
        pts.push_back(p);
        weights.push_back(ws[i] * zp.w);
        station.points.push_back(p);
        station.wz.push_back(zp.w);
      }
      stations_.push_back(std::move(station));
    }
    const unsigned s = interface_->add_segment(pts, weights);
    segment_stations_.push_back(seg_st);
    segment_nodes_.push_back(seg_nodes);
    segment_points_.push_back(pts);
    segment_mine_.push_back(owned.is_element(nodes_[seg_nodes.front()].top[1]));
    segment_of_left_station_[seg_st.front()] = s;
  }
  notch_ = station_at(x_st_, specimen_.initial_crack, "x");
  tip_ = notch_;
  for (unsigned s = 0; s < interface_->n_segments(); ++s)
    if (segment_stations_[s].back() <= notch_)
      interface_->open_segment(s, SegmentState::traction_free);
}

template <int dim>
void DistributedDcbModel<dim>::make_constraints(double opening,
                                                AffineConstraints<double>& c) const {
  c.clear();
  c.reinit(relevant_);
  for (unsigned ix = tip_; ix < x_st_.size(); ++ix)
    for (unsigned iz = 0; iz < n_z_; ++iz)
      for (unsigned d = 0; d < dim; ++d) {
        const auto& n = nodes_[node_index(ix, iz)];
        c.add_line(n.top[d]);
        c.add_entry(n.top[d], n.bottom[d], 1.0);
      }
  for (const auto d : load_top_) {
    c.add_line(d);
    c.set_inhomogeneity(d, 0.5 * opening);
  }
  for (const auto d : load_bottom_) {
    c.add_line(d);
    c.set_inhomogeneity(d, -0.5 * opening);
  }
  for (const auto d : support_)
    c.add_line(d);
  c.close();
}

// ---------------------------------------------------------------------------------------------
// Algebra

template <int dim>
void DistributedDcbModel<dim>::assemble_residual(const Vec& u, Vec& r, Vec& r_full) {
  // r_full = K u + interface forces (its load-line rows are the reactions); r = r_full
  // condensed (ties moved to their partners, prescribed rows dropped).
  const auto t0 = Clock::now();
  scratch_ghost_ = u;
  bulk_.vmult(r_full, u);
  // Interface forces of the opened segments this rank assembles.
  for (unsigned s = 0; s < interface_->n_segments(); ++s) {
    if (!segment_mine_[s] || interface_->state(s) == SegmentState::intact)
      continue;
    const auto& sn = segment_nodes_[s];
    std::vector<types::global_dof_index> sd(2 * sn.size());
    for (unsigned a = 0; a < sn.size(); ++a) {
      sd[a] = nodes_[sn[a]].top[1];
      sd[sn.size() + a] = nodes_[sn[a]].bottom[1];
    }
    Vector<double> fl(sd.size());
    bool any = false;
    for (const unsigned p : segment_points_[s]) {
      const auto& map = point_map_[p];
      double o = 0;
      for (unsigned a = 0; a < map.nodes.size(); ++a)
        o += map.N[a] * (scratch_ghost_[nodes_[map.nodes[a]].top[1]] -
                         scratch_ghost_[nodes_[map.nodes[a]].bottom[1]]);
      const double force = interface_->respond(p, o).force;
      if (force == 0)
        continue;
      any = true;
      for (unsigned a = 0; a < map.nodes.size(); ++a) {
        fl[map.local[a]] += map.N[a] * force;
        fl[sn.size() + map.local[a]] -= map.N[a] * force;
      }
    }
    if (any)
      r_full.add(sd, fl);
  }
  r_full.compress(VectorOperation::add);
  condense(r_full, r);
  info_.t_assemble += seconds_since(t0);
}

template <int dim>
void DistributedDcbModel<dim>::condense(const Vec& full, Vec& out) {
  // out = full with each constrained value moved to the dofs it is tied to and the constrained
  // rows zeroed: what distribute_local_to_global does during assembly. (AffineConstraints::
  // condense(ghosted, out) assigns the ghosted vector to `out`, which a Trilinos vector takes
  // as a change of its layout on more than one rank.) Every rank holds all constrained dofs as
  // ghosts.
  // One add() and one set() per rank, with lists that may be empty: a Trilinos vector switching
  // between adding and setting assembles globally (collective), so no rank may skip the call.
  residual_ghost_ = full;
  out = full;
  std::vector<types::global_dof_index> idx;
  std::vector<double> val;
  for (const auto& line : hom_.get_lines())
    for (const auto& [j, w] : line.entries)
      if (owned_.is_element(j)) {
        idx.push_back(j);
        val.push_back(w * residual_ghost_[line.index]);
      }
  out.add(idx, val);
  out.compress(VectorOperation::add);
  idx.clear();
  for (const auto& line : hom_.get_lines())
    if (owned_.is_element(line.index))
      idx.push_back(line.index);
  out.set(idx, std::vector<double>(idx.size(), 0.0));
  out.compress(VectorOperation::insert);
}

template <int dim>
void DistributedDcbModel<dim>::update_jacobian() {
  // Tangents of all interface points (identical on every rank).
  const bool amg = prm_.linear_solver == FemParameters::LinearSolver::cg_amg;
  const auto o = openings();
  std::vector<double> tangents(point_map_.size());
  for (unsigned p = 0; p < point_map_.size(); ++p) {
    const auto resp = interface_->respond(p, o[p]);
    tangents[p] = resp.stiffness;
    // CG needs an SPD matrix: a softening point enters with its secant (>= 0) instead of its
    // negative tangent. The residual stays exact, so Newton converges to the same state, as a
    // quasi-Newton (more iterations near the peak of the law).
    if (amg && tangents[p] < 0)
      tangents[p] = o[p] > 0 ? std::max(0.0, resp.force / o[p]) : 0.0;
  }
  // The bulk is linear and piecewise-linear laws have piecewise-constant tangents: between two
  // releases the Jacobian differs from the factorized one only at the interface points that
  // changed branch, each a rank-one term dk c c^T. A few of them are cheaper as a Woodbury
  // correction (one solve each) than a new factorization; in 3D a branch change happens at every
  // z point of a station, hence the cap per z station. A release changes the constrained space
  // itself: always refactorize. AMG has no cheap exact inverse: it is set up again.
  if (factorized_epoch_ == epoch_) {
    if (tangents == factorized_tangents_ && low_rank_.empty())
      return;
    std::vector<unsigned> changed;
    for (unsigned p = 0; p < tangents.size(); ++p)
      if (tangents[p] != factorized_tangents_[p])
        changed.push_back(p);
    const std::size_t max_low_rank = 12 * n_z_; // ~ one factorization worth of solves (2D)
    if (!amg && changed.size() <= max_low_rank) {
      const auto t0 = Clock::now();
      std::map<unsigned, LowRankTerm> terms;
      for (const unsigned p : changed) {
        auto it = low_rank_.find(p);
        LowRankTerm term = it != low_rank_.end() ? std::move(it->second) : low_rank_term(p);
        term.dk = tangents[p] - factorized_tangents_[p];
        terms.emplace(p, std::move(term));
      }
      for (auto& [p, term] : low_rank_) // keep unused vectors for later branch changes
        if (terms.find(p) == terms.end()) {
          term.dk = 0;
          terms.emplace(p, std::move(term));
        }
      low_rank_ = std::move(terms);
      // The small matrix S = D^-1 + U^T Z of the active terms, inverted once per Jacobian;
      // the dot products c_p . z_q are kept while the factorization lives.
      woodbury_.clear();
      for (const auto& [p, term] : low_rank_)
        if (term.dk != 0)
          woodbury_.push_back(&term);
      std::vector<unsigned> ids;
      for (const auto& [p, term] : low_rank_)
        if (term.dk != 0)
          ids.push_back(p);
      const unsigned k = ids.size();
      woodbury_inverse_.reinit(k, k);
      for (unsigned i = 0; i < k; ++i)
        for (unsigned j = 0; j < k; ++j) {
          auto it = cz_.find({ids[i], ids[j]});
          if (it == cz_.end())
            it = cz_.emplace(std::make_pair(ids[i], ids[j]), woodbury_[i]->c * woodbury_[j]->z)
                     .first;
          woodbury_inverse_(i, j) = it->second + (i == j ? 1 / woodbury_[i]->dk : 0.0);
        }
      if (k > 0)
        woodbury_inverse_.gauss_jordan();
      info_.t_solve += seconds_since(t0);
      return;
    }
  }
  factorize(tangents);
}

template <int dim>
typename DistributedDcbModel<dim>::LowRankTerm DistributedDcbModel<dim>::low_rank_term(unsigned p) {
  LowRankTerm term;
  term.c.reinit(owned_, comm_);
  const auto& map = point_map_[p];
  std::vector<types::global_dof_index> idx;
  std::vector<double> val;
  for (unsigned a = 0; a < map.nodes.size(); ++a) {
    const auto& n = nodes_[map.nodes[a]];
    if (owned_.is_element(n.top[1])) {
      idx.push_back(n.top[1]);
      val.push_back(map.N[a]);
    }
    if (owned_.is_element(n.bottom[1])) {
      idx.push_back(n.bottom[1]);
      val.push_back(-map.N[a]);
    }
  }
  term.c.add(idx, val);
  term.c.compress(VectorOperation::add);
  condense(Vec(term.c), term.c);
  term.z.reinit(owned_, comm_);
  direct_->solve(term.z, term.c);
  ++info_.n_linear_solves;
  return term;
}

template <int dim>
void DistributedDcbModel<dim>::condensed_pattern() {
  // The couplings of the condensed Jacobian for the current ties: cells and opened segments
  // with the ties applied, no entry for a coupling that condensation removes. The direct
  // solvers factorize every stored entry, zero or not: on the pattern of all possible tie sets
  // (cells extended by the crack-plane partners) KLU's factors and solves cost twice as much.
  DynamicSparsityPattern dsp(relevant_);
  std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
  for (const auto& cell : dof_handler_.active_cell_iterators())
    if (cell->is_locally_owned()) {
      cell->get_dof_indices(dofs);
      hom_.add_entries_local_to_global(dofs, dsp, false);
    }
  for (unsigned s = 0; s < interface_->n_segments(); ++s) {
    if (!segment_mine_[s] || interface_->state(s) == SegmentState::intact)
      continue;
    std::vector<types::global_dof_index> sd;
    for (const unsigned a : segment_nodes_[s]) {
      sd.push_back(nodes_[a].top[1]);
      sd.push_back(nodes_[a].bottom[1]);
    }
    hom_.add_entries_local_to_global(sd, dsp, false);
  }
  SparsityTools::distribute_sparsity_pattern(dsp, owned_, comm_, relevant_);
  jacobian_.reinit(owned_, owned_, dsp, comm_);
  pattern_epoch_ = epoch_;
}

template <int dim>
void DistributedDcbModel<dim>::factorize(const std::vector<double>& tangents) {
  const auto t0 = Clock::now();
  direct_.reset(); // it refers to jacobian_: destroy it before the matrix changes
  if (pattern_epoch_ != epoch_)
    condensed_pattern();
  jacobian_ = 0;
  const unsigned n = fe_.n_dofs_per_cell();
  std::vector<types::global_dof_index> dofs(n);
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    if (!cell->is_locally_owned())
      continue;
    cell->get_dof_indices(dofs);
    hom_.distribute_local_to_global(shape_matrices_[cell_shape_[cell->active_cell_index()]], dofs,
                                    jacobian_);
  }
  for (unsigned s = 0; s < interface_->n_segments(); ++s) {
    if (!segment_mine_[s] || interface_->state(s) == SegmentState::intact)
      continue;
    const auto& sn = segment_nodes_[s];
    const unsigned ns = sn.size();
    std::vector<types::global_dof_index> sd(2 * ns);
    for (unsigned a = 0; a < ns; ++a) {
      sd[a] = nodes_[sn[a]].top[1];
      sd[ns + a] = nodes_[sn[a]].bottom[1];
    }
    FullMatrix<double> kl(2 * ns, 2 * ns);
    bool any = false;
    for (const unsigned p : segment_points_[s]) {
      if (tangents[p] == 0)
        continue;
      any = true;
      const auto& map = point_map_[p];
      for (unsigned a = 0; a < map.nodes.size(); ++a)
        for (unsigned b = 0; b < map.nodes.size(); ++b) {
          const double k = tangents[p] * map.N[a] * map.N[b];
          const unsigned la = map.local[a], lb = map.local[b];
          kl(la, lb) += k;
          kl(la, ns + lb) -= k;
          kl(ns + la, lb) -= k;
          kl(ns + la, ns + lb) += k;
        }
    }
    if (any)
      hom_.distribute_local_to_global(kl, sd, jacobian_);
  }
  jacobian_.compress(VectorOperation::add);
  info_.t_assemble += seconds_since(t0);

  const auto t1 = Clock::now();
  if (prm_.linear_solver == FemParameters::LinearSolver::cg_amg) {
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic = true;
    data.higher_order_elements = prm_.degree > 1;
    data.smoother_sweeps = 2;
    data.aggregation_threshold = 0.02;
    DoFTools::extract_constant_modes(dof_handler_, ComponentMask(dim, true), data.constant_modes);
    // Near null space: all rigid-body modes, translations AND rotations. With translations only
    // (what AdditionalData::constant_modes can express) the coarse levels cannot represent the
    // bending of the slender arms and CG slows down with the mesh (measured: 0.39 s per solve at
    // 14 640 DoFs, 5.2 s at 65 340). ML takes the modes as a pre-computed null space; the
    // coordinates are centred on the beam for conditioning.
    Teuchos::ParameterList list;
    std::unique_ptr<Epetra_MultiVector> translations;
    data.set_parameters(list, translations, jacobian_);
    const unsigned n_modes = dim == 2 ? 3 : 6;
    Epetra_MultiVector modes(jacobian_.trilinos_matrix().DomainMap(), int(n_modes));
    const double xc[3] = {0.5 * specimen_.length, 0.0, 0.5 * (dim == 3 ? specimen_.width : 0.0)};
    for (unsigned k = 0; k < owned_support_.size(); ++k) {
      const auto& sp = owned_support_[k];
      const unsigned c = unsigned(sp[0]);
      const double x[3] = {sp[1] - xc[0], sp[2] - xc[1], sp[3] - xc[2]};
      for (unsigned m = 0; m < dim; ++m)
        modes[m][k] = c == m ? 1.0 : 0.0;
      // Rotations: u = omega x r; 2D only about z.
      if (dim == 2)
        modes[2][k] = c == 0 ? -x[1] : x[0];
      else {
        modes[3][k] = c == 1 ? -x[2] : (c == 2 ? x[1] : 0.0); // about x
        modes[4][k] = c == 0 ? x[2] : (c == 2 ? -x[0] : 0.0); // about y
        modes[5][k] = c == 0 ? -x[1] : (c == 1 ? x[0] : 0.0); // about z
      }
    }
    list.set("null space: type", "pre-computed");
    list.set("null space: dimension", int(n_modes));
    list.set("null space: vectors", modes.Values());
    amg_.initialize(jacobian_, list);
  } else {
    direct_ = std::make_unique<TrilinosWrappers::SolverDirect>(
        direct_control_,
        TrilinosWrappers::SolverDirect::AdditionalData(
            false, prm_.linear_solver == FemParameters::LinearSolver::mumps ? "Amesos_Mumps"
                                                                            : "Amesos_Klu"));
    direct_->initialize(jacobian_); // symbolic and numeric factorization
  }
  factorized_tangents_ = tangents;
  factorized_epoch_ = epoch_;
  low_rank_.clear();
  woodbury_.clear();
  cz_.clear();
  ++info_.n_factorizations;
  info_.t_factorize += seconds_since(t1);
}

template <int dim>
void DistributedDcbModel<dim>::solve_linear(const Vec& rhs, Vec& x) {
  const auto t0 = Clock::now();
  if (prm_.linear_solver == FemParameters::LinearSolver::cg_amg) {
    SolverControl control(20000, prm_.linear_tolerance * norm(rhs));
    SolverCG<Vec> cg(control);
    x = 0;
    try {
      cg.solve(jacobian_, x, rhs, amg_);
    } catch (const std::exception&) {
      throw ComputationError("FEM/Linear solver = cg_amg: CG did not reach the Linear "
                             "tolerance in " +
                             std::to_string(control.last_step()) + " iterations (residual " +
                             fmt(control.last_value()) + "); use mumps");
    }
  } else {
    // Woodbury: (A + U D U^T)^-1 b = y - Z (D^-1 + U^T Z)^-1 U^T y, y = A^-1 b, Z = A^-1 U.
    direct_->solve(x, rhs);
    if (!woodbury_.empty()) {
      const unsigned k = woodbury_.size();
      Vector<double> w(k), v(k);
      for (unsigned i = 0; i < k; ++i)
        w[i] = woodbury_[i]->c * x;
      woodbury_inverse_.vmult(v, w);
      for (unsigned i = 0; i < k; ++i)
        x.add(-v[i], woodbury_[i]->z);
    }
  }
  ++info_.n_linear_solves;
  info_.t_solve += seconds_since(t0);
}

template <int dim>
void DistributedDcbModel<dim>::predict(double opening) {
  if (opening_ != 0)
    u_ *= opening / opening_;
  else {
    // From the undeformed state: the arms turned as rigid hinges about the tip (vertical
    // displacement +-opening/2 (1 - x / a) behind the tip, 0 ahead). The prescribed load-line
    // values alone (a spike of one element) interpolate, on Q2 faces, to a negative opening
    // inside the first element (-Delta/8 at three quarters of it), which switched the contact
    // penalty on in a state that is no state of the specimen: on thin arms Newton then found no
    // decrease of the residual from the first load step (docs/verification.md, "Thin arms").
    const double a = x_st_[tip_];
    std::vector<types::global_dof_index> idx;
    std::vector<double> val;
    for (unsigned k = 0; k < owned_support_.size(); ++k)
      if (owned_support_[k][0] == 1) {
        idx.push_back(owned_.nth_index_in_set(k));
        val.push_back(owned_arm_[k] * 0.5 * opening * std::max(0.0, 1 - owned_support_[k][1] / a));
      }
    u_ = 0;
    u_.set(idx, val);
    u_.compress(VectorOperation::insert);
  }
  opening_ = opening;
  AffineConstraints<double> constraints;
  make_constraints(opening, constraints);
  constraints.distribute(u_);
}

template <int dim>
double DistributedDcbModel<dim>::reaction_norm(const Vec& r_full) const {
  double s = 0;
  for (const auto d : load_top_)
    if (owned_.is_element(d))
      s += r_full[d] * r_full[d];
  for (const auto d : load_bottom_)
    if (owned_.is_element(d))
      s += r_full[d] * r_full[d];
  return std::max(std::sqrt(gsum(s)), 1e-6 * j_tip_ * width_);
}

template <int dim>
double DistributedDcbModel<dim>::roundoff_floor(const Vec& u) const {
  // Estimate of the round-off in r = K u: each row sums terms up to |K|_row |u|, so its error is
  // a few machine epsilons of that; 1e3 epsilons of the largest row sum times the largest
  // displacement, times sqrt(n) for the l2 norm over n rows, is a generous estimate (the same
  // 1e3-epsilon idea as the beam model's Newton, source/beam/dcb_beam.cc). Interface and contact
  // forces are not in K and not in this estimate. Called only where Newton would otherwise fail.
  const double eps = std::numeric_limits<double>::epsilon();
  return 1e3 * eps * bulk_.linfty_norm() * u.linfty_norm() *
         std::sqrt(double(dof_handler_.n_dofs()));
}

template <int dim>
std::string DistributedDcbModel<dim>::contact_summary() {
  sync();
  const auto o = openings();
  unsigned n = 0;
  double lo = 0, hi = 0;
  for (unsigned p = 0; p < o.size(); ++p)
    if (o[p] < 0 && interface_->open_weight(p) > 0) {
      const double x = interface_->x(p);
      lo = n == 0 ? x : std::min(lo, x);
      hi = n == 0 ? x : std::max(hi, x);
      ++n;
    }
  if (n == 0)
    return "; no crack-face point in contact";
  return "; " + std::to_string(n) +
         " crack-face points in contact between x = " + fmt(lo / units::mm) + " and " +
         fmt(hi / units::mm) + " mm";
}

template <int dim>
bool DistributedDcbModel<dim>::newton(double opening, std::string& diagnosis) {
  predict(opening);
  Vec r(owned_, comm_), rf(owned_, comm_), du(owned_, comm_), trial(owned_, comm_),
      rhs(owned_, comm_);
  assemble_residual(u_, r, rf);
  double ref = reaction_norm(rf);
  double nrm = norm(r);
  for (unsigned it = 0; it <= prm_.max_newton_iterations; ++it) {
    if (nrm <= prm_.newton_tolerance * ref)
      return true;
    if (it == prm_.max_newton_iterations)
      break;
    ++info_.n_newton;
    sync();
    update_jacobian();
    rhs = r;
    rhs *= -1.0;
    solve_linear(rhs, du);
    hom_.distribute(du);

    // Backtracking line search on the condensed residual norm.
    double alpha = 1, best_alpha = 0, best_norm = nrm, best_ref = ref;
    for (int ls = 0; ls < 8; ++ls, alpha *= 0.5) {
      trial = u_;
      trial.add(alpha, du);
      assemble_residual(trial, r, rf);
      const double trial_ref = reaction_norm(rf);
      const double trial_norm = norm(r);
      if (trial_norm < best_norm) {
        best_norm = trial_norm;
        best_alpha = alpha;
        best_ref = trial_ref;
      }
      if (trial_norm <= (1 - 1e-4 * alpha) * nrm)
        break;
    }
    if (best_alpha == 0) {
      // Stagnation at the residual's round-off floor is equilibrium, not a failure: the
      // tolerance relative to the reactions can fall below the round-off of the terms that
      // cancel in K u (stiff thin layers, the contact penalty) on refined meshes
      // (docs/verification.md, "Thin arms"). Accepted only when no step decreases the residual.
      if (nrm <= roundoff_floor(u_))
        return true;
      diagnosis =
          "line search found no decrease of the residual " + fmt(nrm) + " N" + contact_summary();
      return false;
    }
    u_.add(best_alpha, du);
    assemble_residual(u_, r, rf);
    ref = best_ref;
    nrm = norm(r);
  }
  if (nrm <= roundoff_floor(u_)) // the iteration limit reached at round-off: also equilibrium
    return true;
  diagnosis = "no convergence in " + std::to_string(prm_.max_newton_iterations) +
              " Newton iterations (residual " + fmt(nrm / ref) + " of the reaction, tolerance " +
              fmt(prm_.newton_tolerance) + ")" + contact_summary();
  return false;
}

template <int dim>
bool DistributedDcbModel<dim>::kinsol(double opening, std::string& diagnosis) {
  // SUNDIALS KINSOL on TrilinosWrappers::MPI::Vector (its N_Vector wrapper reduces over the
  // vectors' communicator), on the same condensed residual, Jacobian and linear solves as
  // newton(). The release library does not report a failed solve (docs/design.md section 7): the
  // result is re-checked against the Newton test here.
  predict(opening);
  Vec r(owned_, comm_), rf(owned_, comm_);
  assemble_residual(u_, r, rf);
  const double ref = reaction_norm(rf);
  if (norm(r) <= prm_.newton_tolerance * ref)
    return true;
  using Kinsol = SUNDIALS::KINSOL<Vec>;
  typename Kinsol::AdditionalData data;
  data.strategy = Kinsol::AdditionalData::linesearch;
  data.maximum_non_linear_iterations = prm_.max_newton_iterations;
  // Max-norm stop below tolerance / sqrt(n) guarantees the l2 test; the step tolerance stops
  // only on stagnation. As in newton(), a residual at its round-off floor is equilibrium: the
  // tolerance relative to the reactions can fall below the round-off of the terms that cancel in
  // K u on refined thin-arm meshes, and KINSOL would then iterate on noise until it gives up.
  const double floor = roundoff_floor(u_);
  data.function_tolerance =
      std::max(prm_.newton_tolerance * ref, floor) / std::sqrt(double(dof_handler_.n_dofs()));
  data.step_tolerance = 1e-3 * prm_.newton_tolerance * opening;
  data.maximum_setup_calls = 1;
  Kinsol solver(data, comm_);
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
  solver.reinit_vector = [&](Vec& v) { v.reinit(owned_, comm_); };
  solver.residual = [&](const Vec& u, Vec& f) {
    return guarded([&] {
      Vec full(owned_, comm_);
      assemble_residual(u, f, full);
    });
  };
  solver.setup_jacobian = [&](const Vec& u, const Vec&) {
    return guarded([&] {
      u_ = u; // update_jacobian() linearizes at u_
      sync();
      update_jacobian();
    });
  };
  solver.solve_with_jacobian = [&](const Vec& rhs, Vec& x, double) {
    return guarded([&] {
      solve_linear(rhs, x);
      hom_.distribute(x); // tied dofs follow their partners
    });
  };
  Vec solution = u_;
  unsigned iterations = 0;
  try {
    iterations = solver.solve(solution);
  } catch (const std::exception& e) {
    callback_error = e.what();
  }
  info_.n_newton += iterations;
  u_ = solution;
  assemble_residual(u_, r, rf);
  const double final_ref = reaction_norm(rf);
  const double nrm = norm(r);
  if (callback_error.empty() &&
      nrm <= std::max(prm_.newton_tolerance * final_ref, roundoff_floor(u_)))
    return true;
  diagnosis = "KINSOL returned after " + std::to_string(iterations) + " of at most " +
              std::to_string(prm_.max_newton_iterations) + " Newton iterations with residual " +
              fmt(nrm / final_ref) + " of the reaction (tolerance " + fmt(prm_.newton_tolerance) +
              ")" +
              (callback_error.empty() ? "" : "; KINSOL or a callback failed: " + callback_error);
  return false;
}

template <int dim>
void DistributedDcbModel<dim>::solve_at(double target) {
  const Vec u0 = u_;
  const double opening0 = opening_;
  unsigned n =
      std::max(1u, unsigned(std::ceil(std::abs(target - opening0) / prm_.max_opening_increment)));
  std::string diagnosis;
  const int attempts = target == opening0 ? 1 : 6;
  for (int attempt = 0; attempt < attempts; ++attempt, n *= 2) {
    u_ = u0;
    opening_ = opening0;
    bool ok = true;
    for (unsigned i = 1; i <= n && ok; ++i)
      ok = prm_.nonlinear_solver == FemParameters::NonlinearSolver::kinsol
               ? kinsol(opening0 + (target - opening0) * double(i) / n, diagnosis)
               : newton(opening0 + (target - opening0) * double(i) / n, diagnosis);
    if (ok) {
      sync();
      return;
    }
  }
  std::ostringstream m;
  m << "FEM: no equilibrium at load-point opening " << target / units::mm << " mm with the tip at "
    << x_st_[tip_] / units::mm << " mm";
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

template <int dim>
bool DistributedDcbModel<dim>::load_to_critical() {
  auto t0 = Clock::now();
  double J = tip_j();
  info_.t_j += seconds_since(t0);
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
  const std::size_t n = rc.size();
  if (n >= 3)
    next = 3 * rc[n - 1].load_point_opening - 3 * rc[n - 2].load_point_opening +
           rc[n - 3].load_point_opening;
  else if (n == 2)
    next = 2 * rc[1].load_point_opening - rc[0].load_point_opening;
  else if (J > 0)
    next = opening_ * target / lo.root_j;
  else
    next = specimen::cbt_opening(
        specimen_, material_,
        specimen::cbt_load_at_crack_length(specimen_, material_, j_tip_, specimen_.initial_crack),
        specimen_.initial_crack);
  for (int it = 0; it < 40; ++it) {
    if (have_hi && !(next > lo.opening && next < hi.opening))
      next = 0.5 * (lo.opening + hi.opening);
    if (!have_hi && !(next > lo.opening))
      next = 1.1 * lo.opening;
    solve_at(next);
    ++n_trials_;
    t0 = Clock::now();
    J = tip_j();
    info_.t_j += seconds_since(t0);
    path_.emplace_back(opening_, load_per_width());
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
                         " J/m^2 with the tip at " + fmt(x_st_[tip_] / units::mm) + " mm (last J " +
                         fmt(J) + ", opening " + fmt(opening_ / units::mm) +
                         " mm): tip J is not monotonic in the opening here");
}

template <int dim>
void DistributedDcbModel<dim>::release_tip() {
  // The row of faces ahead of the tip (the whole width) becomes a fresh cohesive segment.
  const unsigned s = segment_of_left_station_[tip_];
  if (s == ~0u)
    throw ComputationError("FEM: the crack reached the end of the crack plane");
  interface_->open_segment(s, SegmentState::cohesive);
  tip_ = segment_stations_[s].back();
  make_constraints(0.0, hom_);
  ++epoch_;
}

// ---------------------------------------------------------------------------------------------
// Measurements

template <int dim>
std::vector<double> DistributedDcbModel<dim>::node_openings() const {
  std::vector<double> o(nodes_.size());
  for (unsigned a = 0; a < nodes_.size(); ++a)
    o[a] = u_ghost_[nodes_[a].top[1]] - u_ghost_[nodes_[a].bottom[1]];
  return o;
}

template <int dim>
std::vector<double> DistributedDcbModel<dim>::openings() const {
  const auto nodal = node_openings();
  std::vector<double> o(point_map_.size(), 0.0);
  for (unsigned p = 0; p < point_map_.size(); ++p)
    for (unsigned a = 0; a < point_map_[p].nodes.size(); ++a)
      o[p] += point_map_[p].N[a] * nodal[point_map_[p].nodes[a]];
  return o;
}

template <int dim>
double DistributedDcbModel<dim>::station_opening(unsigned ix,
                                                 const std::vector<double>& nodal) const {
  // Width average of the nodal openings at x-station ix (2D: the opening).
  double s = 0;
  for (unsigned iz = 0; iz < n_z_; ++iz)
    s += node_zw_[iz] * nodal[node_index(ix, iz)];
  return s / width_;
}

template <int dim>
double DistributedDcbModel<dim>::domain_j(const Ramp& q, bool crack_face_term) const {
  // J B = int_V (sigma_i1 u_i,1 - W) q,1 dV + int_faces sigma_coh d(delta)/dx q dA (Moran & Shih;
  // q = q(x) across the whole width, so in 3D this is the width average of J along a straight
  // front). Divided by the width: per unit width, as the 2D J.
  const QGauss<dim> quadrature(prm_.degree + 1);
  FEValues<dim> fe_values(mapping_, fe_, quadrature,
                          update_gradients | update_JxW_values | update_quadrature_points);
  const FEValuesExtractors::Vector displacement(0);
  std::vector<Tensor<2, dim>> grad(quadrature.size());
  double J = 0;
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    if (!cell->is_locally_owned())
      continue;
    const double xa = cell->vertex(0)[0], xb = cell->vertex(1)[0];
    if (xb <= q.x0 || xa >= q.x3 || (xa >= q.x1 && xb <= q.x2))
      continue;
    fe_values.reinit(cell);
    fe_values[displacement].get_function_gradients(u_ghost_, grad);
    for (unsigned k = 0; k < quadrature.size(); ++k) {
      const double dq = q.slope(fe_values.quadrature_point(k)[0]);
      if (dq == 0)
        continue;
      const SymmetricTensor<2, dim> eps = symmetrize(grad[k]);
      const SymmetricTensor<2, dim> sigma = C_ * eps;
      const double W = 0.5 * (sigma * eps);
      double t = -W;
      for (unsigned i = 0; i < dim; ++i)
        t += sigma[i][0] * grad[k][i][0];
      J += t * dq * fe_values.JxW(k);
    }
  }
  J = gsum(J) / width_;
  if (crack_face_term)
    J += crack_face_j(&q);
  return J;
}

template <int dim>
double DistributedDcbModel<dim>::crack_face_j(const Ramp* ramp) const {
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
  return J / width_;
}

template <int dim>
double DistributedDcbModel<dim>::tip_j() const {
  const double x = x_st_[tip_];
  const double r = prm_.tip_domain_elements * dx_;
  const double p = std::max(1u, prm_.tip_domain_elements / 2) * dx_;
  return domain_j({x - r, x - p, x + p, x + r}, true);
}

template <int dim>
double DistributedDcbModel<dim>::far_field_j() const {
  const double a0 = specimen_.initial_crack, h = specimen_.arm_thickness();
  auto snap = [&](double x) { return std::round(x / dx_) * dx_; };
  const double x2 = x_st_[tip_] + prm_.tip_domain_elements * dx_;
  return domain_j({snap(0.2 * a0), snap(0.8 * a0), x2, std::min(snap(x2 + h), x_lines_.back())},
                  false);
}

template <int dim>
double DistributedDcbModel<dim>::bulk_energy() const {
  return 0.5 * bulk_.matrix_norm_square(u_) / width_;
}

template <int dim>
double DistributedDcbModel<dim>::stored_energy() const {
  return bulk_energy() +
         (interface_->recoverable_energy(openings()) + interface_->dissipated_energy()) / width_;
}

template <int dim>
double DistributedDcbModel<dim>::load_per_width() {
  Vec r(owned_, comm_), rf(owned_, comm_);
  assemble_residual(u_, r, rf);
  double P = 0;
  for (const auto d : load_top_)
    if (owned_.is_element(d))
      P += rf[d];
  return gsum(P) / width_;
}

template <int dim>
result::RCurvePoint DistributedDcbModel<dim>::record_advance() {
  const auto o = openings();
  interface_->commit(o);
  result::RCurvePoint pt;
  const double B = specimen_.width;
  const double x_tip = x_st_[tip_];
  pt.a = x_tip;
  const auto nodal = node_openings();

  // Notch root on stations (x positions of the interface points; in
  // 3D their width averages: opening, and failed when the width-averaged delta_max passed
  // delta_c). In 2D a station is one point.
  const double dc = law_->critical_opening();
  if (dc <= 0) {
    pt.root = x_tip;
    pt.delta_root = 0;
  } else {
    const unsigned ns = stations_.size();
    std::vector<double> sx(ns), so(ns);
    int last_failed = -1;
    for (unsigned k = 0; k < ns; ++k) {
      const auto& st = stations_[k];
      double wsum = 0, osum = 0, dsum = 0;
      for (unsigned j = 0; j < st.points.size(); ++j) {
        wsum += st.wz[j];
        osum += st.wz[j] * o[st.points[j]];
        dsum += st.wz[j] * interface_->delta_max(st.points[j]);
      }
      sx[k] = interface_->x(st.points[0]);
      so[k] = osum / wsum;
      if (interface_->is_cohesive(st.points[0]) && dsum / wsum >= dc)
        last_failed = int(k);
    }
    if (last_failed < 0) {
      pt.root = x_st_[notch_];
      pt.delta_root = station_opening(notch_, nodal);
    } else {
      const unsigned f = unsigned(last_failed);
      unsigned n = f + 1;
      while (n + 1 < ns && !(sx[n] > sx[f]))
        ++n;
      const double df = so[f], dn = so[n];
      pt.root = (df > dn && dn < dc && df >= dc) ? sx[f] + (df - dc) / (df - dn) * (sx[n] - sx[f])
                                                 : sx[n];
      pt.delta_root = dc;
    }
  }
  pt.zone_length = x_tip - pt.root;
  if (tip_ > 0)
    max_opening_behind_tip_ = std::max(max_opening_behind_tip_, station_opening(tip_ - 1, nodal));

  auto t0 = Clock::now();
  pt.J_tip = tip_j();
  pt.J_ff = far_field_j();
  info_.t_j += seconds_since(t0);
  pt.R_J = pt.J_ff - 0.5 * pt.delta_root * law_->envelope(pt.delta_root);
  pt.R_eq2 = law::r_curve_eq2(*law_, j_tip_, pt.delta_root);

  const double P = load_per_width();
  pt.load = P * B;
  pt.load_point_opening = opening_;
  path_.erase(
      std::remove_if(path_.begin(), path_.end(), [&](const auto& s) { return s.first > opening_; }),
      path_.end());
  path_.emplace_back(opening_, P);
  std::sort(path_.begin(), path_.end());
  for (std::size_t i = 1; i < path_.size(); ++i)
    work_ += 0.5 * (path_[i].second + path_[i - 1].second) * (path_[i].first - path_[i - 1].first);
  path_.clear();
  const double U = bulk_energy();
  const double U_zone = interface_->recoverable_energy(o) / width_;
  pt.external_work = work_ * B;
  pt.strain_energy = U * B;
  pt.zone_recoverable = U_zone * B;
  pt.dissipated = (work_ - U - U_zone) * B; // R_energy: result::fill_r_energy at the end of run()
  details_.zone_dissipated.push_back(interface_->dissipated_energy() / width_ * B);
  details_.tip_dissipated.push_back(tip_dissipated_ * B);
  details_.j_after_release.push_back(j_after_release_);
  // Eq. 1 term measured on the FE fields: minus the crack-face term with q = 1 everywhere.
  details_.zone_integral.push_back(-crack_face_j(nullptr));
  return pt;
}

template <int dim>
bool DistributedDcbModel<dim>::reached_steady_state(bool final_state) {
  const auto rule = steady_state_rule(prm_, specimen_);
  const auto s = result::find_steady_state(result_.rcurve, specimen_.initial_crack, specimen_.width,
                                           law_->critical_opening() > 0, rule);
  if (s.reached || final_state)
    result::report_steady_state(result_, s, rule, "FEM");
  return s.reached;
}

// ---------------------------------------------------------------------------------------------
// Output

template <int dim>
void DistributedDcbModel<dim>::output_fields(unsigned advance) {
  if (output_dir_.empty())
    return;
  const auto t0 = Clock::now();
  DataOut<dim> data_out;
  data_out.attach_dof_handler(dof_handler_);
  const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector_field(
      dim, DataComponentInterpretation::component_is_part_of_vector);
  data_out.add_data_vector(u_ghost_, std::vector<std::string>(dim, "displacement_m"),
                           DataOut<dim>::type_dof_data, vector_field);
  const StressPostprocessor<dim> stress(C_);
  data_out.add_data_vector(u_ghost_, stress);
  Vector<float> subdomain(triangulation_.n_active_cells());
  for (auto& s : subdomain)
    s = float(triangulation_.locally_owned_subdomain());
  data_out.add_data_vector(subdomain, "rank");
  data_out.build_patches(mapping_, prm_.degree);
  // One rank: fem_dcb-NNNN.vtu, the files of the one-process runs before issue 14. Several:
  // one .vtu piece per rank and a .pvtu record (collective). Rank 0 keeps the .pvd series with
  // the crack-tip position in mm as its time axis.
  std::string name;
  if (n_ranks_ == 1) {
    std::ostringstream file;
    file << "fem_dcb-" << std::setw(4) << std::setfill('0') << advance << ".vtu";
    name = file.str();
    std::ofstream vtu(output_dir_ + "/" + name);
    data_out.write_vtu(vtu);
  } else
    name = data_out.write_vtu_with_pvtu_record(output_dir_ + "/", "fem_dcb", advance, comm_, 4);
  pvd_records_.emplace_back(x_st_[tip_] / units::mm, name);
  if (rank_ == 0) {
    std::ofstream pvd(output_dir_ + "/fem_dcb.pvd");
    DataOutBase::write_pvd_record(pvd, pvd_records_);
  }
  info_.t_output += seconds_since(t0);
}

template <int dim>
void DistributedDcbModel<dim>::write_interface_csv() const {
  if (output_dir_.empty() || rank_ != 0)
    return;
  std::vector<std::string> header{"x_mm", "opening_mm", "traction_kPa", "delta_max_mm", "state"};
  if (dim == 3)
    header.insert(header.begin() + 1, "z_mm");
  CsvWriter w(output_dir_ + "/fem_interface.csv", header,
              {"fiberbridge fem (distributed engine, " + std::to_string(dim) +
                   "D): crack-plane interface at the end of the run, one row per integration "
                   "point (x from the load line" +
                   std::string(dim == 3 ? ", z across the width" : "") + ")",
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
      std::vector<double> row{interface_->x(p) / units::mm, o[p] / units::mm, traction / units::kPa,
                              interface_->delta_max(p) / units::mm, code};
      if (dim == 3)
        row.insert(row.begin() + 1, point_z_[p] / units::mm);
      w.row(row);
    }
  }
  w.close();
}

// ---------------------------------------------------------------------------------------------
// The algorithm (as DcbModel::run)

template <int dim>
result::SimulationResult DistributedDcbModel<dim>::run() {
  const auto start = Clock::now();
  result_.model = "fem";
  make_grid();
  setup_system();
  make_constraints(0.0, hom_);
  result_.n_dofs_or_particles = long(dof_handler_.n_dofs());
  info_.n_ranks = n_ranks_;
  info_.dimension = dim;
  info_.n_dofs = long(dof_handler_.n_dofs());
  info_.n_cells = long(triangulation_.n_global_active_cells());
  if (!output_dir_.empty() && rank_ == 0)
    std::filesystem::create_directories(output_dir_);
  MPI_Barrier(comm_);
  report("fem (distributed, " + std::to_string(dim) + "D, " + std::to_string(n_ranks_) +
         " MPI ranks): " + std::to_string(info_.n_cells) + " cells, " +
         std::to_string(info_.n_dofs) + " dofs, Q" + std::to_string(prm_.degree) + ", element " +
         fmt(dx_ / units::mm) + " mm" +
         (dim == 3 ? ", " + std::to_string(z_lines_.size() - 1) + " layers across the width"
                   : std::string()));

  const double L = specimen_.length, h = specimen_.arm_thickness();
  const double a0 = specimen_.initial_crack;
  double first_root_move = -1;
  unsigned advance = 0;
  path_.emplace_back(0.0, 0.0);
  while (true) {
    if (x_st_[tip_] + prm_.tip_domain_elements * dx_ + h > L + 1e-9 * L) {
      if (result_.rcurve.empty())
        throw InputError(
            "Specimen: the ligament (Length - Initial crack = " + fmt((L - a0) / units::mm) +
            " mm) is shorter than the J domains ahead of the tip need (tip strip + one arm "
            "thickness = " +
            fmt((prm_.tip_domain_elements * dx_ + h) / units::mm) + " mm)");
      if (first_root_move < 0)
        result_.notes.push_back(
            "no steady state: zone longer than ligament (the notch root never moved; the tip "
            "reached " +
            fmt(x_st_[tip_] / units::mm) + " mm)");
      reached_steady_state(true); // not reached: the note and G_ss of the shared rule
      break;
    }
    load_to_critical();
    const result::RCurvePoint pt = record_advance();
    result::check_rcurve_point(
        pt); // NaN/Inf ends the run naming the column (the same on every rank)
    result_.rcurve.push_back(pt);
    if (first_root_move < 0 && pt.root > a0 + 1e-9 * L)
      first_root_move = pt.a;
    if (advance % 10 == 0)
      report("fem: a = " + fmt(pt.a / units::mm) + " mm, root " + fmt(pt.root / units::mm) +
             " mm, opening " + fmt(pt.load_point_opening / units::mm) + " mm, load " +
             fmt(pt.load) + " N, J_tip " + fmt(pt.J_tip) + ", R_J " + fmt(pt.R_J) + " J/m^2");
    if (reached_steady_state(false))
      break;
    ++advance;
    if (prm_.output_every > 0 && advance % prm_.output_every == 0)
      output_fields(advance);
    const double before = stored_energy();
    release_tip();
    solve_at(opening_); // re-equilibrate at fixed opening after the release
    interface_->commit(openings());
    tip_dissipated_ += before - stored_energy(); // no external work at fixed opening
    path_.emplace_back(opening_, load_per_width());
  }
  output_fields(advance + 1);
  write_interface_csv();
  result::fill_r_energy(result_.rcurve, specimen_.width);

  const auto kinks = law_->kinks();
  const double rise = kinks.size() > 1 ? kinks[1] : law_->critical_opening();
  if (rise > 0 && max_opening_behind_tip_ > rise)
    result_.notes.push_back(
        "resolution: the opening one element behind the tip reached " +
        fmt(max_opening_behind_tip_ / units::mm) + " mm, past the law's first linear branch (" +
        fmt(rise / units::mm) +
        " mm): the traction varies strongly within the tip element, integrated with " +
        std::to_string(prm_.interface_subintervals) +
        " sub-intervals per element; if R_J falls below Eq. 2, refine FEM/Element size or raise "
        "FEM/Interface sub-intervals" +
        (regularized_law_ ? " (or lower FEM/Rigid law stiffness factor)" : ""));
  note_small_strain_bound(result_);
  note_zone_resolution(result_, dx_);
  details_.unstable_advances = n_unstable_;
  details_.simulated_law_area = law_->area();
  if (dim == 3 && !material_.plane_stress)
    result_.notes.push_back("Material/Plane = strain is not used in 3D: the solid with free "
                            "side faces decides the out-of-plane state");

  Utilities::System::MemoryStats stats;
  Utilities::System::get_memory_stats(stats);
  const double mb = double(stats.VmHWM) / 1024.0;
  info_.peak_memory_MB_sum = gsum(mb);
  info_.peak_memory_MB_max = Utilities::MPI::max(mb, comm_);
  result_.wall_time_s = seconds_since(start);
  // The wall time of rank 0 is the run's (all ranks end together at the last collective).
  MPI_Bcast(&result_.wall_time_s, 1, MPI_DOUBLE, 0, comm_);
  const char* solver_name = prm_.linear_solver == FemParameters::LinearSolver::mumps
                                ? "Trilinos Amesos MUMPS (distributed)"
                            : prm_.linear_solver == FemParameters::LinearSolver::klu
                                ? "Trilinos Amesos KLU (gathered on one rank)"
                                : "CG + Trilinos ML AMG on the secant (SPD) Jacobian";
  result_.method.push_back(
      "distributed engine: " + std::to_string(dim) + "D, " + std::to_string(n_ranks_) +
      " MPI ranks, parallel::distributed::Triangulation (p4est), Trilinos MPI matrices, " +
      solver_name +
      (prm_.nonlinear_solver == FemParameters::NonlinearSolver::kinsol
           ? ", SUNDIALS KINSOL with line search on MPI vectors"
           : ", own Newton with line search"));
  result_.method.push_back(
      "tip criterion: domain J over a full-height strip of +-" +
      std::to_string(prm_.tip_domain_elements) +
      " elements (q = 1 on the inner half) with the cohesive crack-face term" +
      (dim == 3 ? ", over the whole width (width-averaged J of a straight through-width front)"
                : "") +
      "; J_ff: domain J with q = 1 over the whole zone");
  result_.notes.push_back(std::to_string(n_unstable_) +
                          " advances at fixed load-point opening (tip J above J_tip after a "
                          "release: unstable growth)");
  result_.method.push_back(
      "time " + fmt(result_.wall_time_s, 3) + " s: setup " + fmt(info_.t_setup, 3) + " s, " +
      std::to_string(n_trials_) + " equilibrium solves, " + std::to_string(info_.n_newton) +
      " Newton iterations, " + std::to_string(info_.n_factorizations) +
      " Jacobian factorizations " + fmt(info_.t_factorize, 3) + " s, " +
      std::to_string(info_.n_linear_solves) + " solves " + fmt(info_.t_solve, 3) + " s, assembly " +
      fmt(info_.t_assemble, 3) + " s, J integrals " + fmt(info_.t_j, 3) + " s, output " +
      fmt(info_.t_output, 3) + " s; peak memory " + fmt(info_.peak_memory_MB_sum, 4) +
      " MB over all ranks");
  report("fem: done, " + std::to_string(result_.rcurve.size()) + " advances in " +
         fmt(result_.wall_time_s, 3) + " s");
  return result_;
}

template <int dim>
result::SimulationResult
run_distributed(const specimen::Specimen& specimen, const specimen::Material& material,
                const law::TractionLaw& law, double j_tip, const FemParameters& parameters,
                const std::string& output_dir,
                const std::function<void(const std::string&)>& progress, MPI_Comm comm,
                DistributedRunInfo& info, FemRunDetails& details) {
  // FEM/Polynomial degree = auto is resolved here, before the finite element is built.
  FemParameters resolved = parameters;
  std::vector<std::string> degree_notes;
  resolved.degree = resolve_degree(specimen, material, parameters, degree_notes);
  DistributedDcbModel<dim> model(specimen, material, law, j_tip, resolved, output_dir, progress,
                                 comm);
  auto result = model.run();
  result.notes.insert(result.notes.begin(), degree_notes.begin(), degree_notes.end());
  info = model.info();
  details = model.details();
  return result;
}

} // namespace fiberbridge::fem::distributed
