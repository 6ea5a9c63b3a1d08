#pragma once
// The independent simulations of one scene (beam, fem, mpm) as tasks across MPI ranks
// (task_distributor.h). The rule (docs/cluster.md, "Many runs across ranks"):
//   - on one rank nothing changes: the items run one after the other;
//   - under mpirun with N > 1 ranks, every simulation item the scene runs becomes one task on
//     MPI_COMM_SELF (the FEM then runs on that one rank), except a FEM that needs all ranks
//     (FEM/Dimension = 3 or the deprecated FEM/Engine = distributed), which stays collective;
//   - a scene whose only such task would be the 2D FEM runs the FEM over all ranks (one big
//     run, nothing else to overlap with).
// Every rank ends with the same results and summary blocks as a serial run; rank 0 alone writes
// the shared files, while each task writes its own model's files (rcurve_<model>.csv, fields).
#include "fiberbridge/app/scene/scene_context.h"

#include <set>
#include <string>

namespace fiberbridge::app {

/// Called by the scene runner before each item. For a simulation item: on the first call, runs
/// every simulation of `wanted` that the rule above distributes, as tasks across the ranks, and
/// records them in ctx (summary block "simulation_tasks"); returns true when `item` ran so
/// (the runner then skips it). Always false on one rank and for the other items.
bool ran_as_simulation_task(SceneContext& ctx, const std::string& item,
                            const std::set<std::string>& wanted);

} // namespace fiberbridge::app
