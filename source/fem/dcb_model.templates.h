#pragma once
// DcbModel<dim> (dcb_model.h): the growth loop and the bulk algebra that ties the pieces
// together. The algorithm (run()) in the paper's words (seed section 2.4; docs/design.md
// section 2, "FEM"): start from the sawn notch with no cohesive zone; raise the load-point
// opening until the crack-tip energy release rate reaches J_tip; release the tip node, which
// turns the segment ahead of the old tip into a fresh cohesive segment; repeat. The zone grows
// behind the tip, its trailing edge (the notch root) starts to move when the opening there
// passes delta_c, and the run stops at steady state.
//
// Choices (docs/design.md section 2):
// - Residual: K u (the bulk stiffness assembled once) plus the interface forces, condensed.
// - The load-point opening at which tip J equals J_tip is found by a secant iteration on
//   sqrt(J) (exact in one step for linear elasticity). When tip J exceeds J_tip right after a
//   release (unstable growth), the tip advances again at fixed opening.
// - Every decision that steers the algorithm (convergence, line search, tip J against J_tip)
//   uses sums broadcast from rank 0, so all ranks take the same branch.
#include "dcb_model.h"
#include "j_integrals.h"
#include "root_j_secant.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/finite_strain.h"
#include "fiberbridge/law/rigid_law.h"
#include "fiberbridge/result/numerical_fault.h"
#include "fiberbridge/result/steady_state.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/vector.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>

namespace fiberbridge::fem {

using namespace dealii;

template <int dim>
DcbModel<dim>::DcbModel(const specimen::Specimen& specimen, const specimen::Material& material,
                        const law::TractionLaw& law, double j_tip, const FemParameters& parameters,
                        const std::string& output_dir,
                        const std::function<void(const std::string&)>& progress, MPI_Comm comm)
    : specimen_(specimen), material_(material), j_tip_(j_tip), prm_(parameters),
      output_dir_(output_dir), progress_(progress), comm_(comm),
      rank_(Utilities::MPI::this_mpi_process(comm)),
      n_ranks_(Utilities::MPI::n_mpi_processes(comm)),
      C_(orthotropic_stiffness<dim>(material, parameters)),
      finite_(parameters.nonlinear.kinematics == FemParameters::Nonlinear::Kinematics::finite),
      triangulation_(comm), fe_(FE_Q<dim>(parameters.mesh.degree), dim),
      dof_handler_(triangulation_), crack_(1e-9 * specimen.length),
      timer_(MPI_COMM_SELF, std::cout, TimerOutput::never, TimerOutput::wall_times),
      output_(output_dir, comm, finite_) {
  specimen_.validate();
  material_.validate();
  prm_.validate();
  if (!(j_tip > 0))
    throw InputError("Cohesive law/J tip: the FEM tip criterion needs J tip > 0");
  if (dim == 3)
    width_ = specimen_.width;
  // The one rule for rigid laws (law/rigid_law.h): extrinsic insertion, the law as given from
  // sigma(0+), with a note. The tie holds a segment closed until its release; afterwards the tip
  // node is tied, so the traction there acts on both sides of one node and cancels, and the tip
  // J's crack-face term integrates the law's sigma(0+) at the tip point.
  law_ = &law;
  law::note_rigid_law_insertion(law, result_.notes);
  // FEM/Linear solver: auto takes the condensed arms where they apply (docs/design.md section
  // 2, "Condensed arms (issue 34 item 3)"); an explicit condensed that cannot apply is refused.
  using LS = FemParameters::Linear::Solver;
  const bool condensable = dim == 2 && n_ranks_ == 1 && !finite_;
  linear_solver_ = prm_.linear.solver;
  if (linear_solver_ == LS::automatic)
    linear_solver_ = condensable ? LS::condensed : LS::klu;
  else if (linear_solver_ == LS::condensed && !condensable)
    throw InputError("FEM/Linear solver = condensed: applies to 2D runs on one MPI rank with "
                     "FEM/Kinematics = small only (this run: " +
                     std::to_string(dim) + "D, " + std::to_string(n_ranks_) + " ranks, " +
                     (finite_ ? "finite" : "small") + " kinematics); use auto or klu");
  for (const auto& note : prm_.deprecation_notes)
    result_.notes.push_back(note);
}

// ---------------------------------------------------------------------------------------------
// Setup

template <int dim>
void DcbModel<dim>::setup_dofs() {
  dof_handler_.distribute_dofs(fe_);
  owned_ = dof_handler_.locally_owned_dofs();
  IndexSet relevant;
  DoFTools::extract_locally_relevant_dofs(dof_handler_, relevant);

  // Support points of the owned cells: the crack plane notes its own, the rest is kept for the
  // predictor and the AMG near null space.
  const Quadrature<dim> support(fe_.get_unit_support_points());
  FEValues<dim> fv(mapping_, fe_, support, update_quadrature_points);
  std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
  owned_support_.assign(owned_.n_elements(), {{0, 0, 0, 0}});
  owned_arm_.assign(owned_.n_elements(), 0.0);
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    if (!cell->is_locally_owned())
      continue;
    fv.reinit(cell);
    cell->get_dof_indices(dofs);
    const bool top = cell->material_id() == 0;
    for (unsigned i = 0; i < dofs.size(); ++i) {
      const auto& p = fv.quadrature_point(i);
      const unsigned c = fe_.system_to_component_index(i).first;
      if (owned_.is_element(dofs[i])) {
        const double z = dim == 3 ? p[dim - 1] : 0.0;
        owned_support_[owned_.index_within_set(dofs[i])] = {{double(c), p[0], p[1], z}};
        owned_arm_[owned_.index_within_set(dofs[i])] = top ? 1.0 : -1.0;
      }
      crack_.note_support_point(dofs[i], c, p, top);
    }
  }
  crack_.gather(comm_);
  if (finite_) {
    // The load lines hold their mean opening (crack_plane.h): weights from the end face x = 0.
    const QGauss<dim - 1> face_quadrature(fe_.degree + 1);
    FEFaceValues<dim> ffv(mapping_, fe_, face_quadrature, update_values | update_JxW_values);
    std::map<types::global_dof_index, double> weights;
    for (const auto& cell : dof_handler_.active_cell_iterators()) {
      if (!cell->is_locally_owned())
        continue;
      for (const unsigned f : cell->face_indices()) {
        if (!cell->face(f)->at_boundary() ||
            std::abs(cell->face(f)->center()[0]) > 1e-9 * specimen_.length)
          continue;
        ffv.reinit(cell, f);
        cell->get_dof_indices(dofs);
        for (unsigned i = 0; i < dofs.size(); ++i)
          if (fe_.system_to_component_index(i).first == 1 && fe_.has_support_on_face(i, f))
            for (unsigned q = 0; q < face_quadrature.size(); ++q)
              weights[dofs[i]] += ffv.shape_value_component(i, q, 1) * ffv.JxW(q);
      }
    }
    crack_.hold_mean_load_line(weights, comm_);
  }

  // Relevant = the usual ghosts + every crack-plane and load-line dof (small sets), so that
  // every rank has every tie, load and support constraint and every crack-plane value.
  const auto special = crack_.dofs();
  relevant_ = relevant;
  relevant_.add_indices(special.begin(), special.end());
  relevant_.compress();
  u_.reinit(owned_, comm_);
  u_ghost_.reinit(owned_, relevant_, comm_);
  scratch_ghost_.reinit(owned_, relevant_, comm_);
  residual_ghost_.reinit(owned_, relevant_, comm_);
}

template <int dim>
void DcbModel<dim>::assemble_bulk() {
  // The bulk stiffness has the plain cell couplings; the Jacobian's pattern follows the tie set
  // (assemble_jacobian(), rebuilt at each release).
  std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
  DynamicSparsityPattern dsp(relevant_);
  for (const auto& cell : dof_handler_.active_cell_iterators())
    if (cell->is_locally_owned()) {
      cell->get_dof_indices(dofs);
      for (const auto i : dofs)
        dsp.add_entries(i, dofs.begin(), dofs.end());
    }
  SparsityTools::distribute_sparsity_pattern(dsp, owned_, comm_, relevant_);
  bulk_.reinit(owned_, owned_, dsp, comm_);

  // Cell matrices by cell shape (vertex offsets from vertex 0, rounded).
  const double tol = 1e-9 * specimen_.length;
  auto key = [&](double v) { return std::llround(v / tol); };
  const QGauss<dim> quadrature(prm_.mesh.degree + 1);
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
}

// ---------------------------------------------------------------------------------------------
// Algebra

template <int dim>
void DcbModel<dim>::residual(const Vec& u, Vec& r, Vec& r_full) {
  // r_full = K u + interface forces (its load-line rows are the reactions); r = r_full
  // condensed (ties moved to their partners, prescribed rows dropped).
  const TimerOutput::Scope timed(timer_, "assembly");
  // On one rank every dof is owned: the crack plane reads u itself (the copy into a ghosted
  // vector builds an Epetra import each time, measured a fifth of the residual's time).
  const Vec* values = &u;
  if (n_ranks_ > 1 || finite_) {
    scratch_ghost_ = u;
    values = &scratch_ghost_;
  }
  if (finite_) {
    r_full = 0;
    finite_bulk(scratch_ghost_, &r_full, nullptr);
  } else
    bulk_.vmult(r_full, u);
  crack_.add_forces(*values, r_full);
  r_full.compress(VectorOperation::add);
  condense(r_full, r);
}

template <int dim>
void DcbModel<dim>::condense(const Vec& full, Vec& out) {
  // out = full with each constrained value moved to the dofs it is tied to and the constrained
  // rows zeroed: what distribute_local_to_global does during assembly. (AffineConstraints::
  // condense(ghosted, out) assigns the ghosted vector to `out`, which a Trilinos vector takes
  // as a change of its layout on more than one rank.) Every rank holds all constrained dofs as
  // ghosts.
  // One add() and one set() per rank, with lists that may be empty: a Trilinos vector switching
  // between adding and setting assembles globally (collective), so no rank may skip the call.
  // On one rank `full` holds every value itself (no ghost import).
  const Vec* values = &full;
  if (n_ranks_ > 1) {
    residual_ghost_ = full;
    values = &residual_ghost_;
  }
  out = full;
  std::vector<types::global_dof_index> idx;
  std::vector<double> val;
  for (const auto& line : hom_.get_lines())
    for (const auto& [j, w] : line.entries)
      if (owned_.is_element(j)) {
        idx.push_back(j);
        val.push_back(w * (*values)[line.index]);
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
void DcbModel<dim>::setup_jacobian(const Vec& u) {
  if (&u != &u_)
    u_ = u; // the tangents are taken at u_
  sync();
  // Tangents of all interface points (identical on every rank).
  const auto o = openings();
  const auto& interface = crack_.interface();
  std::vector<double> tangents(crack_.n_points());
  for (unsigned p = 0; p < tangents.size(); ++p) {
    const auto resp = interface.respond(p, o[p]);
    tangents[p] = resp.stiffness;
    // CG needs an SPD matrix: a softening point enters with its secant (>= 0) instead of its
    // negative tangent. The residual stays exact, so Newton converges to the same state, as a
    // quasi-Newton (more iterations near the peak of the law).
    if (solver_->needs_spd_tangents() && tangents[p] < 0)
      tangents[p] = o[p] > 0 ? std::max(0.0, resp.force / o[p]) : 0.0;
  }
  // Finite kinematics changes the bulk tangent with u: a new assembly and factorization, unless
  // the last Newton step contracted the residual well (a chord step with the older bulk tangent
  // and this state's interface tangents, corrected by the low-rank update; at most
  // kMaxChordSteps in a row). Factorizing is most of an iteration's cost, more so in 3D.
  constexpr double kChordContraction = 0.3;
  constexpr unsigned kMaxChordSteps = 8;
  const bool chord = finite_ && solver_ties_epoch_ == epoch_ &&
                     last_contraction_ < kChordContraction && chord_steps_ < kMaxChordSteps;
  last_contraction_ = 1;
  if (chord)
    ++chord_steps_;
  else if (finite_ || solver_ties_epoch_ != epoch_) {
    ++solver_epoch_;
    solver_ties_epoch_ = epoch_;
    chord_steps_ = 0;
  }
  solver_->update(tangents, solver_epoch_);
}

template <int dim>
void DcbModel<dim>::solve_jacobian(const Vec& rhs, Vec& x) {
  solver_->solve(rhs, x);
  hom_.distribute(x); // tied dofs follow their partners
}

template <int dim>
void DcbModel<dim>::assemble_jacobian(const std::vector<double>& tangents,
                                      TrilinosWrappers::SparseMatrix& jacobian) {
  const TimerOutput::Scope timed(timer_, "assembly");
  std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
  if (pattern_epoch_ != epoch_) {
    // The couplings of the condensed Jacobian for the current ties: cells and opened segments
    // with the ties applied, no entry for a coupling that condensation removes. The direct
    // solvers factorize every stored entry, zero or not: on the pattern of all possible tie sets
    // (cells extended by the crack-plane partners) KLU's factors and solves cost twice as much.
    DynamicSparsityPattern dsp(relevant_);
    for (const auto& cell : dof_handler_.active_cell_iterators())
      if (cell->is_locally_owned()) {
        cell->get_dof_indices(dofs);
        hom_.add_entries_local_to_global(dofs, dsp, false);
      }
    crack_.add_pattern(hom_, dsp);
    SparsityTools::distribute_sparsity_pattern(dsp, owned_, comm_, relevant_);
    jacobian.reinit(owned_, owned_, dsp, comm_);
    pattern_epoch_ = epoch_;
  }
  jacobian = 0;
  if (finite_)
    finite_bulk(u_ghost_, nullptr, &jacobian); // the tangent at the linearization point
  else
    for (const auto& cell : dof_handler_.active_cell_iterators()) {
      if (!cell->is_locally_owned())
        continue;
      cell->get_dof_indices(dofs);
      hom_.distribute_local_to_global(shape_matrices_[cell_shape_[cell->active_cell_index()]], dofs,
                                      jacobian);
    }
  crack_.add_jacobian(tangents, hom_, jacobian);
  jacobian.compress(VectorOperation::add);
}

template <int dim>
CondensedArms DcbModel<dim>::condensed_arms() const {
  CondensedArms arms;
  arms.bulk = &bulk_;
  arms.constraints = &hom_;
  arms.boundary = crack_.dofs();
  arms.pairs = crack_.node_pairs();
  for (unsigned p = 0; p < crack_.n_points(); ++p)
    arms.points.push_back(crack_.point_weights(p));
  for (const auto* line : {&crack_.load_top(), &crack_.load_bottom()})
    arms.loads.insert(arms.loads.end(), line->begin(), line->end());
  // One rank: the owned dofs are all dofs, by index.
  arms.order.resize(owned_support_.size());
  for (unsigned k = 0; k < owned_support_.size(); ++k) {
    const auto& sp = owned_support_[k];
    arms.order[owned_.nth_index_in_set(k)] = {{owned_arm_[k], sp[1], sp[3], sp[2], sp[0]}};
  }
  return arms;
}

template <int dim>
void DcbModel<dim>::opening_operator(unsigned p, Vec& c) {
  c.reinit(owned_, comm_);
  crack_.opening_operator(p, owned_, c);
  condense(Vec(c), c);
}

template <int dim>
void DcbModel<dim>::predict(double opening) {
  hinge_predictor_ = opening_ == 0;
  if (opening_ != 0)
    u_ *= opening / opening_;
  else {
    // From the undeformed state: the arms turned as rigid hinges about the tip (vertical
    // displacement +-opening/2 (1 - x / a) behind the tip, 0 ahead). The prescribed load-line
    // values alone (a spike of one element) interpolate, on Q2 faces, to a negative opening
    // inside the first element (-Delta/8 at three quarters of it), which switched the contact
    // penalty on in a state that is no state of the specimen: on thin arms Newton then found no
    // decrease of the residual from the first load step (docs/design.md section 2).
    const double a = crack_.x_tip();
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
double DcbModel<dim>::reaction_norm(const Vec& r_full) const {
  double s = 0;
  for (const auto& line : {&crack_.load_top(), &crack_.load_bottom()})
    for (const auto d : *line)
      if (owned_.is_element(d))
        s += r_full[d] * r_full[d];
  return std::max(std::sqrt(gsum(s)), 1e-6 * j_tip_ * width_);
}

template <int dim>
double DcbModel<dim>::roundoff_floor(const Vec& u) const {
  // Estimate of the round-off in r = K u: each row sums terms up to |K|_row |u|, so its error is
  // a few machine epsilons of that; 1e3 epsilons of the largest row sum times the largest
  // displacement, times sqrt(n) for the l2 norm over n rows, is a generous estimate (the same
  // 1e3-epsilon idea as the beam model's Newton). Interface and contact forces are not in K and
  // not in this estimate. Called only where Newton would otherwise fail.
  const double eps = std::numeric_limits<double>::epsilon();
  return 1e3 * eps * bulk_.linfty_norm() * u.linfty_norm() *
         std::sqrt(double(dof_handler_.n_dofs()));
}

template <int dim>
std::string DcbModel<dim>::contact_summary() {
  sync();
  return crack_.contact_summary(openings());
}

template <int dim>
void DcbModel<dim>::solve_at(double target) {
  const Vec u0 = u_;
  const double opening0 = opening_;
  unsigned n = std::max(
      1u, unsigned(std::ceil(std::abs(target - opening0) / prm_.nonlinear.max_opening_increment)));
  const NonlinearSettings settings{prm_.nonlinear.newton_tolerance,
                                   prm_.nonlinear.max_newton_iterations};
  std::string diagnosis;
  const int attempts = target == opening0 ? 1 : 6;
  for (int attempt = 0; attempt < attempts; ++attempt, n *= 2) {
    u_ = u0;
    opening_ = opening0;
    bool ok = true;
    for (unsigned i = 1; i <= n && ok; ++i) {
      const double opening = opening0 + (target - opening0) * double(i) / n;
      predict(opening);
      const bool kinsol = prm_.nonlinear.solver == FemParameters::Nonlinear::Solver::kinsol;
      const NonlinearSettings rest = condensed_ && !kinsol && !tip_control_ && !hinge_predictor_
                                         ? crack_plane_step(settings)
                                         : settings;
      ok = kinsol ? kinsol_solve(*this, u_, settings, opening, info_.n_newton, diagnosis)
                  : newton_solve(*this, u_, rest, info_.n_newton, diagnosis);
    }
    if (ok) {
      sync();
      return;
    }
  }
  std::ostringstream m;
  m << "FEM: no equilibrium at load-point opening " << target / units::mm << " mm with the tip at "
    << crack_.x_tip() / units::mm << " mm";
  if (target == opening0)
    m << " (re-solve at fixed opening after a release)";
  else
    m << " (" << n / 2 << " sub-steps from " << opening0 / units::mm << " mm)";
  m << ": " << diagnosis
    << ". Try a smaller FEM/Element size or Maximum opening increment, a softer Contact "
       "stiffness factor, more Maximum Newton iterations, or check the law for a vertical drop";
  throw ComputationError(m.str());
}

template <int dim>
NonlinearSettings DcbModel<dim>::crack_plane_step(const NonlinearSettings& settings) {
  // The epochs as setup_jacobian() keeps them (small strain: a new one per tie set).
  if (solver_ties_epoch_ != epoch_) {
    ++solver_epoch_;
    solver_ties_epoch_ = epoch_;
  }
  const auto& interface = crack_.interface();
  CrackPlaneForces forces;
  forces.interface = &interface;
  forces.active.assign(crack_.n_points(), false);
  for (unsigned s = 0; s < interface.n_segments(); ++s)
    if (interface.state(s) != SegmentState::intact)
      for (const unsigned p : interface.segment_points(s))
        forces.active[p] = true;
  unsigned used = 0;
  const bool converged = condensed_->crack_plane_newton(u_, forces, solver_epoch_, settings,
                                                        1e-6 * j_tip_ * width_, used);
  info_.n_newton += used;
  if (!converged)
    ++n_crack_plane_fallbacks_;
  NonlinearSettings rest = settings;
  rest.spent = used;
  rest.max_iterations = settings.max_iterations - used;
  return rest;
}

// ---------------------------------------------------------------------------------------------
// Crack growth

template <int dim>
bool DcbModel<dim>::load_to_critical() {
  if (tip_control_)
    return load_to_critical_at_tip();
  if (result_.rcurve.empty())
    return load_to_critical_by_opening(); // no zone yet: nothing can turn back
  const Vec u0 = u_;
  const double opening0 = opening_;
  const auto path0 = path_;
  try {
    return load_to_critical_by_opening();
  } catch (const ComputationError& e) {
    // The load-point opening lost the state (the path turns back): trace it from the state
    // after the release under the crack-tip opening control.
    u_ = u0;
    opening_ = opening0;
    path_ = path0;
    sync();
    switch_to_tip_control(e.what());
    const double eta = control_opening();
    for (auto& s : path_)
      s.param = eta; // the one state since the release
    return load_to_critical_at_tip();
  }
}

template <int dim>
bool DcbModel<dim>::load_to_critical_by_opening() {
  double J = timed_tip_j();
  if (!result_.rcurve.empty())
    j_after_release_ = J;
  if (J >= (1 - prm_.nonlinear.tip_tolerance) * j_tip_) {
    if (J > (1 + prm_.nonlinear.tip_tolerance) * j_tip_)
      ++n_unstable_;
    return false;
  }
  RootJSecant search(j_tip_, opening_, J);
  double next;
  const auto& rc = result_.rcurve;
  const std::size_t n = rc.size();
  if (n >= 3)
    next = 3 * rc[n - 1].load_point_opening - 3 * rc[n - 2].load_point_opening +
           rc[n - 3].load_point_opening;
  else if (n == 2)
    next = 2 * rc[1].load_point_opening - rc[0].load_point_opening;
  else if (J > 0)
    next = opening_ * std::sqrt(j_tip_) / std::sqrt(J);
  else
    next = specimen::cbt_opening(
        specimen_, material_,
        specimen::cbt_load_at_crack_length(specimen_, material_, j_tip_, specimen_.initial_crack),
        specimen_.initial_crack);
  for (int it = 0; it < 40; ++it) {
    solve_at(search.safeguard(next));
    ++n_trials_;
    J = timed_tip_j();
    path_.push_back({opening_, opening_, load_per_width()});
    if (std::abs(J / j_tip_ - 1) <= prm_.nonlinear.tip_tolerance)
      return true;
    next = search.add(opening_, J);
  }
  throw ComputationError("FEM: could not bring the tip J to J_tip = " + fmt(j_tip_) +
                         " J/m^2 with the tip at " + fmt(crack_.x_tip() / units::mm) +
                         " mm (last J " + fmt(J) + ", opening " + fmt(opening_ / units::mm) +
                         " mm): tip J is not monotonic in the opening here");
}

template <int dim>
void DcbModel<dim>::release_tip() {
  crack_.release_tip();
  make_constraints(0.0, hom_);
  ++epoch_;
}

template <int dim>
void DcbModel<dim>::re_equilibrate(double stored_before, const Vec& u_before, double load_before) {
  if (!tip_control_) {
    try {
      solve_at(opening_); // re-equilibrate at fixed opening after the release
      crack_.interface().commit(openings());
      tip_dissipated_ += stored_before - stored_energy(); // no external work at fixed opening
      path_.push_back({opening_, opening_, load_per_width()});
      return;
    } catch (const ComputationError& e) {
      u_ = u_before; // the released state, not yet in equilibrium
      sync();
      switch_to_tip_control(e.what());
    }
  }
  // Under the crack-tip control the release and the re-equilibration are one traced step: the
  // tip's energy drop is accounted at its first equilibrium state (account_release()).
  path_.push_back({0.0, opening_, load_before}); // the controlled node was tied: opening 0
  release_pending_ = true;
  release_stored_ = stored_before;
  release_opening_ = opening_;
  release_load_ = load_before;
  min_opening_since_record_ = opening_;
}

// ---------------------------------------------------------------------------------------------
// Measurements

template <int dim>
double DcbModel<dim>::domain_j(const Ramp& q, bool crack_face_term) const {
  // J B = int_V (sigma_i1 u_i,1 - W) q,1 dV + int_faces sigma_coh d(delta)/dx q dA (Moran & Shih;
  // q = q(x) across the whole width, so in 3D this is the width average of J along a straight
  // front). Divided by the width: per unit width, as the 2D J.
  double J = gsum(j_domain_.bulk_local(dof_handler_, mapping_, prm_.mesh.degree, C_, u_ghost_, q,
                                       finite_)) /
             width_;
  if (crack_face_term)
    J += crack_face_j(&q);
  return J;
}

template <int dim>
double DcbModel<dim>::tip_j() const {
  return domain_j(tip_j_weight(crack_.x_tip(), prm_.j_domain.half_width_elements, geometry_.dx),
                  true);
}

template <int dim>
double DcbModel<dim>::far_field_j() const {
  return domain_j(far_field_j_weight(specimen_.initial_crack, specimen_.arm_thickness(),
                                     crack_.x_tip(), prm_.j_domain.half_width_elements,
                                     geometry_.dx, geometry_.x_lines.back(),
                                     geometry_.x_last_end_feature),
                  false);
}

template <int dim>
double DcbModel<dim>::bulk_energy() const {
  if (finite_)
    return gsum(finite_bulk(u_ghost_, nullptr, nullptr)) / width_;
  return 0.5 * bulk_.matrix_norm_square(u_) / width_;
}

template <int dim>
double DcbModel<dim>::finite_bulk(const Vec& u_ghost, Vec* forces,
                                  TrilinosWrappers::SparseMatrix* jacobian) const {
  // Total Lagrangian: f_i = int P : grad N_i dV, K_ij = int grad N_i : dP/dF : grad N_j dV
  // = int (grad N_i S) : grad N_j + sym(F^T grad N_i) : C : sym(F^T grad N_j) dV (step-44's
  // material and geometric parts).
  const QGauss<dim> quadrature(prm_.mesh.degree + 1);
  FEValues<dim> fv(mapping_, fe_, quadrature, update_gradients | update_JxW_values);
  const FEValuesExtractors::Vector displacement(0);
  const unsigned n = fe_.n_dofs_per_cell();
  std::vector<Tensor<2, dim>> H(quadrature.size()), G(n), GS(n);
  std::vector<SymmetricTensor<2, dim>> e(n), Ce(n);
  std::vector<types::global_dof_index> dofs(n);
  Vector<double> f(n);
  FullMatrix<double> k(n, n);
  double energy = 0;
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    if (!cell->is_locally_owned())
      continue;
    fv.reinit(cell);
    fv[displacement].get_function_gradients(u_ghost, H);
    f = 0;
    k = 0;
    for (unsigned q = 0; q < quadrature.size(); ++q) {
      const SvkPoint<dim> s(C_, H[q]);
      const double dV = fv.JxW(q);
      energy += s.W * dV;
      if (!forces && !jacobian)
        continue;
      for (unsigned i = 0; i < n; ++i) {
        G[i] = fv[displacement].gradient(i, q);
        if (forces)
          f(i) += scalar_product(s.P, G[i]) * dV;
      }
      if (!jacobian)
        continue;
      const Tensor<2, dim> S(s.S);
      for (unsigned i = 0; i < n; ++i) {
        GS[i] = G[i] * S;
        e[i] = s.strain_variation(G[i]);
        Ce[i] = C_ * e[i];
      }
      for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j <= i; ++j)
          k(i, j) += (scalar_product(GS[i], G[j]) + e[i] * Ce[j]) * dV;
    }
    if (!forces && !jacobian)
      continue;
    cell->get_dof_indices(dofs);
    if (forces)
      forces->add(dofs, f);
    if (jacobian) {
      for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < i; ++j)
          k(j, i) = k(i, j);
      hom_.distribute_local_to_global(k, dofs, *jacobian);
    }
  }
  return energy;
}

template <int dim>
double DcbModel<dim>::stored_energy() const {
  const auto& interface = crack_.interface();
  return bulk_energy() +
         (interface.recoverable_energy(openings()) + interface.dissipated_energy()) / width_;
}

template <int dim>
double DcbModel<dim>::load_per_width() {
  double P = 0;
  if (n_ranks_ == 1 && !finite_) {
    // The reactions are rows of K u: the load-line dofs are no crack-plane dofs (crack_plane.h),
    // so no interface force acts there. A few sparse rows instead of a whole residual (a load is
    // read after every equilibrium).
    const Epetra_CrsMatrix& K = bulk_.trilinos_matrix();
    const double* values_u = u_.trilinos_vector()[0];
    for (const auto d : crack_.load_top()) {
      int count = 0;
      double* values = nullptr;
      int* columns = nullptr;
      K.ExtractMyRowView(int(owned_.index_within_set(d)), count, values, columns);
      double row = 0;
      for (int e = 0; e < count; ++e)
        row += values[e] * values_u[columns[e]];
      P += row;
    }
    return P / width_;
  }
  Vec r(owned_, comm_), rf(owned_, comm_);
  residual(u_, r, rf);
  for (const auto d : crack_.load_top())
    if (owned_.is_element(d))
      P += rf[d];
  return gsum(P) / width_;
}

template <int dim>
result::RCurvePoint DcbModel<dim>::record_advance() {
  auto& interface = crack_.interface();
  const auto o = openings();
  interface.commit(o);
  result::RCurvePoint pt;
  const double B = specimen_.width;
  const double x_tip = crack_.x_tip();
  pt.a = x_tip;
  const auto nodal = crack_.node_openings(u_ghost_);
  const double dc = law_->critical_opening();
  // The zone's root and its opening (delta_c once the notch root has failed), for R_J and Eq. 2.
  double zone_root_opening = 0;
  if (dc <= 0) {
    pt.root = x_tip;
    pt.delta_root = 0;
  } else {
    std::tie(pt.root, zone_root_opening) = crack_.notch_root(o, nodal, dc, width_);
    // delta_root is the opening at the initial notch root, as a clip gauge or the virtual
    // extensometer reads it and as the beam and the MPM report it: past delta_c once the root
    // has failed (the zone's own root then holds delta_c). A simulated record's delta_root (the
    // fit's correction, identify) and R(delta_root) beside other models need this one.
    pt.delta_root = crack_.station_opening(crack_.notch_station(), nodal, width_);
  }
  pt.zone_length = x_tip - pt.root;
  const unsigned tip = crack_.tip_station();
  if (tip > 0)
    max_opening_behind_tip_ =
        std::max(max_opening_behind_tip_, crack_.station_opening(tip - 1, nodal, width_));

  {
    const TimerOutput::Scope timed(timer_, "J integrals");
    pt.J_tip = tip_j();
    pt.J_ff = far_field_j();
  }
  pt.R_J = pt.J_ff - 0.5 * zone_root_opening * law_->envelope(zone_root_opening);
  pt.R_eq2 = law::r_curve_eq2(*law_, j_tip_, zone_root_opening);

  const double P = load_per_width();
  pt.load = P * B;
  pt.load_point_opening = opening_;
  // The work over the traced path: states ordered by the control parameter (trial states past
  // the accepted one are not on the path); under the crack-tip control the opening may fall.
  const double param = tip_control_ ? control_opening() : opening_;
  last_control_opening_ = crack_.station_opening(control_station(), nodal, width_);
  path_.erase(
      std::remove_if(path_.begin(), path_.end(), [&](const auto& s) { return s.param > param; }),
      path_.end());
  path_.push_back({param, opening_, P});
  std::sort(path_.begin(), path_.end());
  for (std::size_t i = 1; i < path_.size(); ++i)
    work_ += 0.5 * (path_[i].load + path_[i - 1].load) * (path_[i].opening - path_[i - 1].opening);
  path_.clear();
  const double U = bulk_energy();
  const double U_zone = interface.recoverable_energy(o) / width_;
  pt.external_work = work_ * B;
  pt.strain_energy = U * B;
  pt.zone_recoverable = U_zone * B;
  pt.dissipated = (work_ - U - U_zone) * B; // R_energy: result::fill_r_energy at the end of run()
  details_.zone_dissipated.push_back(interface.dissipated_energy() / width_ * B);
  details_.tip_dissipated.push_back(tip_dissipated_ * B);
  details_.j_after_release.push_back(j_after_release_);
  // Eq. 1 term measured on the FE fields: minus the crack-face term with q = 1 everywhere.
  details_.zone_integral.push_back(-crack_face_j(nullptr));
  return pt;
}

template <int dim>
bool DcbModel<dim>::reached_steady_state() const {
  return result::find_steady_state(result_.rcurve, specimen_.initial_crack, specimen_.width,
                                   law_->critical_opening() > 0, steady_state_rule(prm_, specimen_))
      .reached;
}

template <int dim>
void DcbModel<dim>::output_fields(unsigned advance) {
  if (output_dir_.empty())
    return;
  const TimerOutput::Scope timed(timer_, "output");
  output_.write(dof_handler_, mapping_, C_, u_ghost_, advance, crack_.x_tip() / units::mm);
}

// ---------------------------------------------------------------------------------------------
// The algorithm

template <int dim>
result::SimulationResult DcbModel<dim>::run() {
  const auto start = Clock::now();
  result_.model = "fem";
  geometry_ = make_dcb_mesh(specimen_, prm_, triangulation_);
  {
    const TimerOutput::Scope timed(timer_, "setup");
    setup_dofs();
    assemble_bulk();
    crack_.make_interface(
        *law_, prm_.interface.contact_stiffness_factor * material_.E_T / prm_.mesh.element_size,
        prm_.mesh.degree, prm_.interface.subintervals, geometry_.x_lines, geometry_.z_lines, owned_,
        specimen_.initial_crack);
    RigidBodyModes modes;
    if (linear_solver_ == FemParameters::Linear::Solver::cg_amg) {
      modes.dim = dim;
      modes.owned_support = owned_support_;
      modes.centre = {{0.5 * specimen_.length, 0.0, 0.5 * (dim == 3 ? specimen_.width : 0.0)}};
      DoFTools::extract_constant_modes(dof_handler_, ComponentMask(dim, true),
                                       modes.constant_modes);
    }
    // ~ one factorization worth of solves (2D); in 3D a branch change happens at every z point of
    // a station, hence the cap per z station.
    make_constraints(0.0, hom_);
    // auto: the dense crack-plane system costs O(m^3) once and O(m^2) per release and solve;
    // past about a thousand crack-plane dofs (fine or quadratic meshes on long ligaments) the
    // sparse factorizations are cheaper, above all on short runs (measured: the thin-composite
    // refinement ladder, Q2 down to 0.5 mm, took 13 times longer condensed).
    constexpr std::size_t kAutoMaxCondensedDofs = 1000;
    if (prm_.linear.solver == FemParameters::Linear::Solver::automatic &&
        crack_.dofs().size() > kAutoMaxCondensedDofs)
      linear_solver_ = FemParameters::Linear::Solver::klu;
    if (linear_solver_ == FemParameters::Linear::Solver::condensed) {
      try {
        auto condensed = make_condensed_solver(condensed_arms(), timer_);
        condensed_ = condensed.get();
        solver_ = std::move(condensed);
      } catch (const ComputationError& e) {
        // A mesh or constraint the condensed arms do not take (condensed_solver.h): auto falls
        // back to klu with a note; an explicit choice fails with the reason.
        if (prm_.linear.solver != FemParameters::Linear::Solver::automatic)
          throw;
        linear_solver_ = FemParameters::Linear::Solver::klu;
        result_.notes.push_back(std::string("FEM/Linear solver = auto took klu: ") + e.what());
      }
    }
    if (!solver_)
      solver_ = make_jacobian_solver(prm_, *this, 12 * crack_.n_z(), std::move(modes), timer_);
  }
  if (prm_.virtual_dic.settings.enabled) {
    if (output_dir_.empty())
      throw InputError("FEM/Virtual DIC/Enabled: the virtual test writes into the output "
                       "directory; the run has none");
    const TimerOutput::Scope timed(timer_, "output");
    virtual_test_ = std::make_unique<VirtualTestRecorder<dim>>(
        prm_.virtual_dic.settings, specimen_, material_, dof_handler_, mapping_, comm_);
  }
  result_.n_dofs_or_particles = long(dof_handler_.n_dofs());
  info_.n_ranks = n_ranks_;
  info_.dimension = dim;
  info_.n_dofs = long(dof_handler_.n_dofs());
  info_.n_cells = long(triangulation_.n_global_active_cells());
  if (!output_dir_.empty() && rank_ == 0)
    std::filesystem::create_directories(output_dir_);
  MPI_Barrier(comm_);
  const double dx = geometry_.dx;
  report(
      "fem (distributed, " + std::to_string(dim) + "D, " + std::to_string(n_ranks_) +
      " MPI ranks): " + std::to_string(info_.n_cells) + " cells, " + std::to_string(info_.n_dofs) +
      " dofs, Q" + std::to_string(prm_.mesh.degree) + ", element " + fmt(dx / units::mm) + " mm" +
      (dim == 3 ? ", " + std::to_string(geometry_.z_lines.size() - 1) + " layers across the width"
                : std::string()));

  const double L = specimen_.length, h = specimen_.arm_thickness();
  const double a0 = specimen_.initial_crack;
  double first_root_move = -1;
  unsigned advance = 0;
  path_.push_back({0.0, 0.0, 0.0});
  while (true) {
    if (crack_.x_tip() + prm_.j_domain.half_width_elements * dx + h > L + 1e-9 * L) {
      if (result_.rcurve.empty())
        throw InputError(
            "Specimen: the ligament (Length - Initial crack = " + fmt((L - a0) / units::mm) +
            " mm) is shorter than the J domains ahead of the tip need (tip strip + one arm "
            "thickness = " +
            fmt((prm_.j_domain.half_width_elements * dx + h) / units::mm) + " mm)");
      if (first_root_move < 0)
        result_.notes.push_back(
            "no steady state: zone longer than ligament (the notch root never moved; the tip "
            "reached " +
            fmt(crack_.x_tip() / units::mm) + " mm)");
      break;
    }
    load_to_critical();
    const result::RCurvePoint pt = record_advance();
    result::check_rcurve_point(
        pt); // NaN/Inf ends the run naming the column (the same on every rank)
    result_.rcurve.push_back(pt);
    if (virtual_test_) {
      const TimerOutput::Scope timed(timer_, "output");
      virtual_test_->record(u_ghost_, pt.load_point_opening, pt.load, pt.root, pt.a);
    }
    if (first_root_move < 0 && pt.root > a0 + 1e-9 * L)
      first_root_move = pt.a;
    if (advance % 10 == 0)
      report("fem: a = " + fmt(pt.a / units::mm) + " mm, root " + fmt(pt.root / units::mm) +
             " mm, opening " + fmt(pt.load_point_opening / units::mm) + " mm, load " +
             fmt(pt.load) + " N, J_tip " + fmt(pt.J_tip) + ", R_J " + fmt(pt.R_J) + " J/m^2");
    if (reached_steady_state())
      break;
    ++advance;
    if (prm_.output.vtu_every > 0 && advance % prm_.output.vtu_every == 0)
      output_fields(advance);
    const double before = stored_energy();
    const Vec u_before = u_;
    release_tip();
    re_equilibrate(before, u_before, pt.load / specimen_.width);
  }
  // The post-processing all three models share: R_energy, the steady-state rule and its note,
  // R_J against Eq. 2 (docs/design.md section 2, "Steady state and G_ss").
  result::finish_rcurve(result_, *law_, j_tip_, specimen_.initial_crack, specimen_.width,
                        steady_state_rule(prm_, specimen_), "FEM");
  note_snap_back();
  output_fields(advance + 1);
  write_interface_csv(output_dir_, comm_, dim, crack_.interface(), openings(), crack_.point_z());
  if (virtual_test_) {
    const TimerOutput::Scope timed(timer_, "output");
    const auto files = virtual_test_->write(output_dir_);
    result_.notes.push_back("virtual test (FEM/Virtual DIC): " + std::to_string(files.n_frames) +
                            " frames of " + std::to_string(files.n_points) + " points over " +
                            fmt(files.duration, 4) + " s in " + files.directory +
                            "; run its scene " + files.scene);
  }
  summarize(start);
  return result_;
}

template <int dim>
void DcbModel<dim>::summarize(Clock::time_point start) {
  const auto kinks = law_->kinks();
  const double rise = kinks.size() > 1 ? kinks[1] : law_->critical_opening();
  if (rise > 0 && max_opening_behind_tip_ > rise)
    result_.notes.push_back(
        "resolution: the opening one element behind the tip reached " +
        fmt(max_opening_behind_tip_ / units::mm) + " mm, past the law's first linear branch (" +
        fmt(rise / units::mm) +
        " mm): the traction varies strongly within the tip element, integrated with " +
        std::to_string(prm_.interface.subintervals) +
        " sub-intervals per element; if R_J falls below Eq. 2, refine FEM/Element size or raise "
        "FEM/Interface sub-intervals");
  if (finite_)
    result_.method.push_back(
        "kinematics: finite (FEM/Kinematics = finite): total Lagrangian, orthotropic St "
        "Venant-Kirchhoff, domain J with the first Piola-Kirchhoff stress in the reference "
        "configuration, load lines held at their mean opening (the loaded ends rotate freely); "
        "the cohesive opening is the jump normal to the undeformed crack plane");
  else
    note_small_strain_bound(result_);
  result::note_zone_resolution(result_, geometry_.dx, "elements", "FEM/Element size");
  details_.unstable_advances = n_unstable_;
  details_.simulated_law_area = law_->area();
  if (dim == 3 && !material_.plane_stress)
    result_.notes.push_back("Material/Plane = strain is not used in 3D: the solid with free "
                            "side faces decides the out-of-plane state");

  const auto& stats = solver_->stats();
  info_.n_factorizations = stats.n_factorizations;
  info_.n_linear_solves = stats.n_linear_solves;
  // A section never entered (output without an output directory) is absent: 0 s.
  auto times = timer_.get_summary_data(TimerOutput::total_wall_time);
  info_.t_setup = times["setup"];
  info_.t_assemble = times["assembly"];
  info_.t_factorize = times["factorize"];
  info_.t_solve = times["solve"];
  info_.t_j = times["J integrals"];
  info_.t_output = times["output"];
  Utilities::System::MemoryStats memory;
  Utilities::System::get_memory_stats(memory);
  const double mb = double(memory.VmHWM) / 1024.0;
  info_.peak_memory_MB_sum = gsum(mb);
  info_.peak_memory_MB_max = Utilities::MPI::max(mb, comm_);
  result_.wall_time_s = seconds_since(start);
  // The wall time of rank 0 is the run's (all ranks end together at the last collective).
  MPI_Bcast(&result_.wall_time_s, 1, MPI_DOUBLE, 0, comm_);
  using LS = FemParameters::Linear::Solver;
  const std::string solver_name =
      linear_solver_ == LS::mumps ? "Trilinos Amesos MUMPS (distributed)"
      : linear_solver_ == LS::klu ? "Trilinos Amesos KLU (gathered on one rank)"
      : linear_solver_ == LS::condensed
          ? "arms condensed onto the crack plane (FEM/Linear solver = condensed" +
                std::string(prm_.linear.solver == LS::automatic ? ", chosen by auto" : "") + ": " +
                std::to_string(stats.n_factorizations) + " dense inverses, " +
                std::to_string(stats.n_bordered) + " bordered releases, " +
                std::to_string(stats.n_low_rank) +
                " linearizations with tangent changes by the "
                "Woodbury identity, " +
                std::to_string(stats.n_folds) + " folded into the inverse, " +
                std::to_string(stats.n_refinements) + " refined solves, " +
                std::to_string(stats.n_drift_refreshes) + " refreshes for round-off drift; " +
                std::to_string(n_crack_plane_fallbacks_) +
                " crack-plane Newton runs stopped short and went on in the full Newton)"
          : "CG + Trilinos ML AMG on the secant (SPD) Jacobian";
  result_.method.push_back(
      "distributed engine: " + std::to_string(dim) + "D, " + std::to_string(n_ranks_) +
      " MPI ranks, parallel::distributed::Triangulation (p4est), Trilinos MPI matrices, " +
      solver_name +
      (prm_.nonlinear.solver == FemParameters::Nonlinear::Solver::kinsol
           ? ", SUNDIALS KINSOL with line search on MPI vectors"
           : ", own Newton with line search"));
  result_.method.push_back(
      "tip criterion: domain J over a full-height strip of +-" +
      std::to_string(prm_.j_domain.half_width_elements) +
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
}

template <int dim>
result::SimulationResult
run_dcb_model(const specimen::Specimen& specimen, const specimen::Material& material,
              const law::TractionLaw& law, double j_tip, const FemParameters& parameters,
              const std::string& output_dir,
              const std::function<void(const std::string&)>& progress, MPI_Comm comm,
              DistributedRunInfo& info, FemRunDetails& details) {
  // FEM/Polynomial degree = auto is resolved here, before the finite element is built.
  FemParameters resolved = parameters;
  std::vector<std::string> degree_notes;
  resolved.mesh.degree = resolve_degree(specimen, material, parameters, degree_notes);
  DcbModel<dim> model(specimen, material, law, j_tip, resolved, output_dir, progress, comm);
  auto result = model.run();
  result.notes.insert(result.notes.begin(), degree_notes.begin(), degree_notes.end());
  info = model.info();
  details = model.details();
  return result;
}

} // namespace fiberbridge::fem

// The crack-tip opening control (bordered Newton) in a file of its own.
#include "dcb_model_tip_control.templates.h"

// The explicit instantiations of one dimension, used by dcb_model_2d.cc and dcb_model_3d.cc (a
// translation unit each, so that the two compile in parallel).
#define FIBERBRIDGE_FEM_INSTANTIATE_DCB_MODEL(dim)                                                 \
  namespace fiberbridge::fem {                                                                     \
  template class DcbModel<dim>;                                                                    \
  template result::SimulationResult                                                                \
  run_dcb_model<dim>(const specimen::Specimen&, const specimen::Material&,                         \
                     const law::TractionLaw&, double, const FemParameters&, const std::string&,    \
                     const std::function<void(const std::string&)>&, MPI_Comm,                     \
                     DistributedRunInfo&, FemRunDetails&);                                         \
  }
