// The two JacobianSolver strategies (jacobian_solver.h; docs/design.md section 2, "One engine").
#include "jacobian_solver.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/fem/dcb_common.h"

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/vector.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

#include <map>
#include <string>

namespace fiberbridge::fem {

using namespace dealii;

namespace {

/// Amesos KLU or MUMPS: one factorization per constraint set, and between releases a Woodbury
/// correction for the interface points whose tangent changed branch. The bulk is linear and
/// piecewise-linear laws have piecewise-constant tangents, so the Jacobian differs from the
/// factorized one only by rank-one terms dk c c^T; only the factorized solve and global dot
/// products combine them, so the correction works on any number of ranks.
class DirectWoodbury : public JacobianSolver {
public:
  DirectWoodbury(JacobianSystem& system, std::string amesos_name, std::size_t max_low_rank,
                 TimerOutput& timer)
      : system_(system), amesos_name_(std::move(amesos_name)), max_low_rank_(max_low_rank),
        timer_(timer) {}

  bool needs_spd_tangents() const override { return false; }

  void update(const std::vector<double>& tangents, unsigned epoch) override {
    // A release changes the constrained space itself: always refactorize; too many changed
    // points too (in 3D a branch change happens at every z point of a station, hence the cap
    // scales with the z stations).
    if (factorized_epoch_ == epoch) {
      if (tangents == factorized_tangents_ && low_rank_.empty())
        return;
      std::vector<unsigned> changed;
      for (unsigned p = 0; p < tangents.size(); ++p)
        if (tangents[p] != factorized_tangents_[p])
          changed.push_back(p);
      if (changed.size() <= max_low_rank_) {
        correct(tangents, changed);
        return;
      }
    }
    factorize(tangents, epoch);
  }

  void solve(const Vec& rhs, Vec& x) override {
    // (A + U D U^T)^-1 b = y - Z (D^-1 + U^T Z)^-1 U^T y, y = A^-1 b, Z = A^-1 U.
    const TimerOutput::Scope timed(timer_, "solve");
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
    ++stats_.n_linear_solves;
  }

private:
  /// A changed point: tangent change dk, condensed opening operator c, and A^-1 c.
  struct LowRankTerm {
    double dk = 0;
    Vec c, z;
  };

  void factorize(const std::vector<double>& tangents, unsigned epoch) {
    direct_.reset(); // it refers to jacobian_: destroy it before the matrix changes
    system_.assemble_jacobian(tangents, jacobian_); // timed as assembly
    const TimerOutput::Scope timed(timer_, "factorize");
    direct_ = std::make_unique<TrilinosWrappers::SolverDirect>(
        direct_control_, TrilinosWrappers::SolverDirect::AdditionalData(false, amesos_name_));
    direct_->initialize(jacobian_); // symbolic and numeric factorization
    factorized_tangents_ = tangents;
    factorized_epoch_ = epoch;
    low_rank_.clear();
    woodbury_.clear();
    cz_.clear();
    ++stats_.n_factorizations;
  }

  void correct(const std::vector<double>& tangents, const std::vector<unsigned>& changed) {
    const TimerOutput::Scope timed(timer_, "solve");
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
    // The small matrix S = D^-1 + U^T Z of the active terms, inverted once per Jacobian; the
    // dot products c_p . z_q are kept while the factorization lives.
    woodbury_.clear();
    std::vector<unsigned> ids;
    for (const auto& [p, term] : low_rank_)
      if (term.dk != 0) {
        woodbury_.push_back(&term);
        ids.push_back(p);
      }
    const unsigned k = ids.size();
    woodbury_inverse_.reinit(k, k);
    for (unsigned i = 0; i < k; ++i)
      for (unsigned j = 0; j < k; ++j) {
        auto it = cz_.find({ids[i], ids[j]});
        if (it == cz_.end())
          it = cz_.emplace(std::make_pair(ids[i], ids[j]), woodbury_[i]->c * woodbury_[j]->z).first;
        woodbury_inverse_(i, j) = it->second + (i == j ? 1 / woodbury_[i]->dk : 0.0);
      }
    if (k > 0)
      woodbury_inverse_.gauss_jordan();
  }

  LowRankTerm low_rank_term(unsigned p) {
    LowRankTerm term;
    system_.opening_operator(p, term.c);
    term.z.reinit(system_.owned_dofs(), system_.communicator());
    direct_->solve(term.z, term.c);
    ++stats_.n_linear_solves;
    return term;
  }

  JacobianSystem& system_;
  const std::string amesos_name_;
  const std::size_t max_low_rank_;
  TimerOutput& timer_;
  TrilinosWrappers::SparseMatrix jacobian_;
  std::unique_ptr<TrilinosWrappers::SolverDirect> direct_;
  SolverControl direct_control_;
  unsigned factorized_epoch_ = ~0u;
  std::vector<double> factorized_tangents_;
  std::map<unsigned, LowRankTerm> low_rank_;
  std::vector<const LowRankTerm*> woodbury_; ///< the active terms (dk != 0)
  FullMatrix<double> woodbury_inverse_;      ///< (D^-1 + U^T Z)^-1 of the active terms
  std::map<std::pair<unsigned, unsigned>, double> cz_;
};

/// CG + ML AMG on the secant (SPD) Jacobian, set up again at every change: AMG has no cheap
/// exact inverse to correct.
class CgAmg : public JacobianSolver {
public:
  CgAmg(JacobianSystem& system, const FemParameters& parameters, RigidBodyModes modes,
        TimerOutput& timer)
      : system_(system), linear_tolerance_(parameters.linear.tolerance),
        higher_order_(parameters.mesh.degree > 1), modes_(std::move(modes)), timer_(timer) {}

  bool needs_spd_tangents() const override { return true; }

  void update(const std::vector<double>& tangents, unsigned epoch) override {
    if (setup_epoch_ == epoch && tangents == setup_tangents_)
      return;
    system_.assemble_jacobian(tangents, jacobian_); // timed as assembly
    const TimerOutput::Scope timed(timer_, "factorize");
    setup_preconditioner();
    setup_tangents_ = tangents;
    setup_epoch_ = epoch;
    ++stats_.n_factorizations;
  }

  void solve(const Vec& rhs, Vec& x) override {
    const TimerOutput::Scope timed(timer_, "solve");
    SolverControl control(20000, linear_tolerance_ * broadcast_norm(rhs, system_.communicator()));
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
    ++stats_.n_linear_solves;
  }

private:
  void setup_preconditioner() {
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic = true;
    data.higher_order_elements = higher_order_;
    data.smoother_sweeps = 2;
    data.aggregation_threshold = 0.02;
    data.constant_modes = modes_.constant_modes;
    // Near null space: all rigid-body modes, translations AND rotations. With translations only
    // (what AdditionalData::constant_modes can express) the coarse levels cannot represent the
    // bending of the slender arms and CG slows down with the mesh (docs/cluster.md, "Cost of a
    // 3D R curve at 10^7 DoFs on a cluster"). ML takes the modes as a pre-computed null space; the
    // coordinates are centred on the beam for conditioning.
    Teuchos::ParameterList list;
    std::unique_ptr<Epetra_MultiVector> translations;
    data.set_parameters(list, translations, jacobian_);
    const unsigned dim = modes_.dim;
    const unsigned n_modes = dim == 2 ? 3 : 6;
    Epetra_MultiVector modes(jacobian_.trilinos_matrix().DomainMap(), int(n_modes));
    const auto& xc = modes_.centre;
    for (unsigned k = 0; k < modes_.owned_support.size(); ++k) {
      const auto& sp = modes_.owned_support[k];
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
  }

  JacobianSystem& system_;
  const double linear_tolerance_;
  const bool higher_order_;
  const RigidBodyModes modes_;
  TimerOutput& timer_;
  TrilinosWrappers::SparseMatrix jacobian_;
  TrilinosWrappers::PreconditionAMG amg_;
  unsigned setup_epoch_ = ~0u;
  std::vector<double> setup_tangents_;
};

} // namespace

std::unique_ptr<JacobianSolver> make_jacobian_solver(const FemParameters& parameters,
                                                     JacobianSystem& system,
                                                     std::size_t max_low_rank, RigidBodyModes modes,
                                                     TimerOutput& timer) {
  using LS = FemParameters::Linear::Solver;
  if (parameters.linear.solver == LS::cg_amg)
    return std::make_unique<CgAmg>(system, parameters, std::move(modes), timer);
  return std::make_unique<DirectWoodbury>(
      system, parameters.linear.solver == LS::mumps ? "Amesos_Mumps" : "Amesos_Klu", max_low_rank,
      timer);
}

} // namespace fiberbridge::fem
