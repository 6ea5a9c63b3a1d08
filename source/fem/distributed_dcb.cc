// Engine choice and the dimension dispatch of the distributed engine (light translation unit;
// the engine itself is in distributed_dcb.templates.h, instantiated in distributed_dcb_2d.cc and
// distributed_dcb_3d.cc).
#include "fiberbridge/fem/distributed_dcb.h"

#include "fiberbridge/core/error.h"

namespace fiberbridge::fem {

namespace distributed {
template <int dim>
law::SimulationResult
run_distributed(const law::Specimen&, const law::Material&, const law::TractionLaw&, double,
                const FemParameters&, const std::string&,
                const std::function<void(const std::string&)>&, MPI_Comm, DistributedRunInfo&);
} // namespace distributed

bool use_distributed_engine(const FemParameters& p, unsigned n_ranks) {
  switch (p.engine) {
  case FemParameters::Engine::serial:
    if (p.dimension == 3)
      throw InputError("FEM/Engine = serial: the serial engine is 2D only; Dimension = 3 needs "
                       "Engine = distributed (or auto)");
    if (n_ranks > 1)
      throw InputError("FEM/Engine = serial under mpirun with " + std::to_string(n_ranks) +
                       " ranks: every rank would run the same serial model; use Engine = "
                       "distributed (or auto), or run on one rank");
    return false;
  case FemParameters::Engine::distributed:
    return true;
  case FemParameters::Engine::automatic:
    break;
  }
  return p.dimension == 3 || n_ranks > 1 || p.linear_solver == FemParameters::LinearSolver::mumps ||
         p.linear_solver == FemParameters::LinearSolver::cg_amg;
}

law::SimulationResult
simulate_dcb_distributed(const law::Specimen& specimen, const law::Material& material,
                         const law::TractionLaw& law, double j_tip, const FemParameters& parameters,
                         const std::string& output_dir,
                         const std::function<void(const std::string&)>& progress, MPI_Comm comm,
                         DistributedRunInfo* info) {
  DistributedRunInfo local;
  DistributedRunInfo& i = info ? *info : local;
  if (parameters.dimension == 3)
    return distributed::run_distributed<3>(specimen, material, law, j_tip, parameters, output_dir,
                                           progress, comm, i);
  if (parameters.dimension == 2)
    return distributed::run_distributed<2>(specimen, material, law, j_tip, parameters, output_dir,
                                           progress, comm, i);
  throw InputError("FEM/Dimension: must be 2 or 3");
}

} // namespace fiberbridge::fem
