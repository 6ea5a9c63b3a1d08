#pragma once
// The vector type of the FEM engine and the two reductions every decision of the algorithm goes
// through (docs/design.md section 2, "What MPI changes"): a sum reduced on rank 0 and broadcast,
// so that every rank gets the same bits and takes the same branch (an allreduce need not).
#include <deal.II/lac/trilinos_vector.h>

#include <mpi.h>

#include <cmath>

namespace fiberbridge::fem {

using Vec = dealii::TrilinosWrappers::MPI::Vector;

inline double broadcast_sum(double local, MPI_Comm comm) {
  double global = 0;
  MPI_Reduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, 0, comm);
  MPI_Bcast(&global, 1, MPI_DOUBLE, 0, comm);
  return global;
}

/// The l2 norm over all ranks, through broadcast_sum (identical on every rank).
inline double broadcast_norm(const Vec& v, MPI_Comm comm) {
  double s = 0;
  for (auto it = v.begin(); it != v.end(); ++it)
    s += *it * *it;
  return std::sqrt(broadcast_sum(s, comm));
}

} // namespace fiberbridge::fem
