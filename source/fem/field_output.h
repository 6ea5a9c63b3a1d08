#pragma once
// Output of the FEM (docs/design.md section 2, "One engine"; file names in section 5): the
// displacement and stress fields as VTU (one rank) or VTU pieces + PVTU (several), the PVD
// series with the crack-tip position as its time axis, and fem_interface.csv.
#include "fiberbridge/fem/cohesive_interface.h"
#include "mpi_algebra.h"

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <string>
#include <utility>
#include <vector>

namespace fiberbridge::fem {

template <int dim>
class FieldOutput {
public:
  /// Nothing is written when output_dir is empty. `finite`: the stress is the Cauchy stress of
  /// the finite-strain state (FEM/Kinematics = finite).
  FieldOutput(std::string output_dir, MPI_Comm comm, bool finite)
      : dir_(std::move(output_dir)), comm_(comm), finite_(finite) {}
  /// Writes fem_dcb-NNNN (advance NNNN) and rewrites fem_dcb.pvd on rank 0 (collective).
  void write(const dealii::DoFHandler<dim>& dof_handler, const dealii::Mapping<dim>& mapping,
             const dealii::SymmetricTensor<4, dim>& C, const Vec& u_ghost, unsigned advance,
             double x_tip_mm);

private:
  const std::string dir_;
  const MPI_Comm comm_;
  const bool finite_;
  std::vector<std::pair<double, std::string>> pvd_records_;
};

/// fem_interface.csv (rank 0 only; nothing when output_dir is empty): one row per interface
/// point with its opening (`openings`) and state; z only in 3D (`point_z`).
void write_interface_csv(const std::string& output_dir, MPI_Comm comm, unsigned dim,
                         const CohesiveInterface& interface, const std::vector<double>& openings,
                         const std::vector<double>& point_z);

} // namespace fiberbridge::fem
