// fiberbridge: the command line (docs/design.md section 5; the commands are in commands.cc).
#include "fiberbridge/app/cli/commands.h"
#include "fiberbridge/core/output_guard.h"

#include <deal.II/base/mpi.h>

#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  // Started without mpirun, Open MPI 4.1's singleton start forks a runtime daemon (orted) before
  // main can run: about 0.3 s of every invocation (docs/verification.md, "Process start"). No
  // command spawns processes, so the singleton runs isolated. A user's own setting wins; under
  // mpirun or srun the variable is never read (those starts are not singletons).
  setenv("OMPI_MCA_ess_singleton_isolated", "1", /*overwrite=*/0);
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // Under mpirun every rank runs the command (the distributed FEM is collective); rank 0 alone
  // writes the shared files and prints (core/output_guard.h). Errors found identically on all
  // ranks (input errors) are printed by rank 0 only; others carry the rank.
  const unsigned rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  fiberbridge::set_output_enabled(rank == 0);
  return fiberbridge::app::run_command_line({argv + 1, argv + argc}, rank);
}
