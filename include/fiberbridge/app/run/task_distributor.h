#pragma once
// Independent runs across MPI ranks (docs/cluster.md, "Many runs across ranks"): a list of tasks
// (ladder levels, stability cases, the simulations of a scene, forward runs of an
// identification) is spread over the ranks of a communicator, each task runs on one rank with
// the simulations on MPI_COMM_SELF (so the FEM takes its one-rank path), and every rank gets
// every task's result back, in task order. A task's result is an opaque string (the caller
// serializes, e.g. with core/binary_archive.h); the shared files are then written by rank 0 alone
// (core/output_guard.h) from the gathered results.
#include <mpi.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace fiberbridge::app {

/// The communicator a simulation item runs on: MPI_COMM_WORLD, except while a task of
/// run_tasks_across_ranks runs (then MPI_COMM_SELF: the task is the whole run on its rank).
MPI_Comm simulation_communicator();

/// What run_tasks_across_ranks hands back, on every rank, indexed by task.
struct TaskResults {
  std::vector<std::string> output; ///< what each task returned
  std::vector<int> rank;           ///< the rank of `comm` that ran it
  std::vector<double> seconds;     ///< its wall time
  /// Its CPU time (the whole process's, threads included): on a loaded machine a better measure
  /// of the work than the wall time.
  std::vector<double> cpu_seconds;
};

/// Runs task(i) once for every i in [0, n), spread over the ranks of `comm`, and returns every
/// result on every rank. Collective: every rank calls it with the same n and cost.
///
/// Scheduling is dynamic (self-scheduling): a rank that is free takes the next task from a
/// counter held by rank 0 (an MPI-3 atomic fetch-and-add, so rank 0 also runs tasks and nobody
/// waits for it to answer), in order of decreasing `cost` (one estimate per task, any unit;
/// empty = task order): the expensive runs start first and the cheap ones fill the gaps.
///
/// A task that throws stops its rank from taking further tasks; after the gather every rank
/// throws the error of the failed task with the smallest index, InputError and ComputationError
/// with their type (so main prints an input error once, as for a serial run).
TaskResults run_tasks_across_ranks(std::size_t n,
                                   const std::function<std::string(std::size_t)>& task,
                                   MPI_Comm comm, const std::vector<double>& cost = {});

/// While alive, this process writes files (core/output_guard.h), whatever its rank: for a task
/// that owns its output directory (no other rank writes there).
class TaskOwnsItsFiles {
public:
  TaskOwnsItsFiles();
  ~TaskOwnsItsFiles();
  TaskOwnsItsFiles(const TaskOwnsItsFiles&) = delete;
  TaskOwnsItsFiles& operator=(const TaskOwnsItsFiles&) = delete;

private:
  bool previous_;
};

} // namespace fiberbridge::app
