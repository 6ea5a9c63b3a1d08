#pragma once
// The DCB finite-element model (dcb_simulation.h) on any number of MPI ranks, 2D and 3D: one
// engine on parallel::distributed::Triangulation (p4est) with Trilinos MPI matrices and vectors
// (issue 14; on one rank it is the serial program), so that `mpirun -np N fiberbridge run
// SCENE.prm` spreads the mesh, the assembly and the linear solves over the ranks.
//
// 3D: the 2D mesh extruded over Specimen/Width (z from 0 to B), free side faces (neither plane
// stress nor plane strain is imposed: the solid decides), the load applied as a prescribed
// vertical displacement of the whole load-line end face of each arm (a rigid loading block free to
// rotate about z). The crack front is straight through the width: ties are released one row of
// crack-plane faces at a time, and the tip criterion is the width-averaged domain J.
#include "fiberbridge/fem/auto_mesh.h"
#include "fiberbridge/fem/dcb_simulation.h"

#include <mpi.h>

#include <functional>
#include <string>

namespace fiberbridge::fem {

/// Cost and size figures of a distributed run (identical on every rank).
struct DistributedRunInfo {
  unsigned n_ranks = 1;
  unsigned dimension = 2;
  long n_dofs = 0;
  long n_cells = 0;
  double peak_memory_MB_sum = 0; ///< sum over ranks of the peak resident set (VmHWM) [MB]
  double peak_memory_MB_max = 0; ///< largest peak resident set of one rank [MB]
  unsigned n_factorizations = 0; ///< Jacobian assemblies + factorizations (or AMG setups)
  unsigned n_linear_solves = 0;
  unsigned n_newton = 0;
  double t_setup = 0, t_assemble = 0, t_factorize = 0, t_solve = 0, t_j = 0, t_output = 0;
  /// The mesh of the run and why (FEM/Element size given or auto; fem/auto_mesh.h).
  MeshChoice mesh;
  double element_size = 0; ///< the crack-plane element after the snap to the notch [m]
};

/// The FEM run of a DCB on the ranks of `comm` (every rank calls it and gets the same result);
/// the overloads without a communicator (dcb_simulation.h) call it on MPI_COMM_SELF. Output (VTU
/// pieces per rank + .pvtu + .pvd, fem_interface.csv) goes to `output_dir` unless empty; only
/// rank 0 writes the shared files. `progress` is called on rank 0 only. (It was
/// `simulate_dcb_distributed`, from when a serial engine existed beside this one; issue 30.)
result::SimulationResult
simulate_dcb(const specimen::Specimen& specimen, const specimen::Material& material,
             const law::TractionLaw& law, double j_tip, const FemParameters& parameters,
             const std::string& output_dir, const std::function<void(const std::string&)>& progress,
             MPI_Comm comm, DistributedRunInfo* info = nullptr, FemRunDetails* details = nullptr);

} // namespace fiberbridge::fem
