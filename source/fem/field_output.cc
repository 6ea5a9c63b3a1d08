// VTU/PVTU/PVD fields and fem_interface.csv (field_output.h; docs/design.md section 5).
#include "field_output.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/dcb_common.h"

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/numerics/data_out.h>

#include <fstream>
#include <iomanip>
#include <sstream>

namespace fiberbridge::fem {

using namespace dealii;

template <int dim>
void FieldOutput<dim>::write(const DoFHandler<dim>& dof_handler, const Mapping<dim>& mapping,
                             const SymmetricTensor<4, dim>& C, const Vec& u_ghost, unsigned advance,
                             double x_tip_mm) {
  if (dir_.empty())
    return;
  const auto& triangulation = dof_handler.get_triangulation();
  DataOut<dim> data_out;
  data_out.attach_dof_handler(dof_handler);
  const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector_field(
      dim, DataComponentInterpretation::component_is_part_of_vector);
  data_out.add_data_vector(u_ghost, std::vector<std::string>(dim, "displacement_m"),
                           DataOut<dim>::type_dof_data, vector_field);
  const StressPostprocessor<dim> stress(C, finite_);
  data_out.add_data_vector(u_ghost, stress);
  Vector<float> subdomain(triangulation.n_active_cells());
  for (auto& s : subdomain)
    s = float(triangulation.locally_owned_subdomain());
  data_out.add_data_vector(subdomain, "rank");
  data_out.build_patches(mapping, dof_handler.get_fe().degree);
  // zlib's best_speed: deal.II's default (best_compression) spent ~85 % of the output time
  // compressing binary floats that it shrinks no further (docs/verification.md, "Cheaper J
  // integrals and field output"). Same VTU format, same zlib blocks, read by any VTK reader.
  DataOutBase::VtkFlags flags;
  flags.compression_level = DataOutBase::VtkFlags::best_speed;
  data_out.set_flags(flags);
  // One rank: fem_dcb-NNNN.vtu, the files of the one-process runs before issue 14. Several:
  // one .vtu piece per rank and a .pvtu record (collective). Rank 0 keeps the .pvd series with
  // the crack-tip position in mm as its time axis.
  std::string name;
  if (Utilities::MPI::n_mpi_processes(comm_) == 1) {
    std::ostringstream file;
    file << "fem_dcb-" << std::setw(4) << std::setfill('0') << advance << ".vtu";
    name = file.str();
    std::ofstream vtu(dir_ + "/" + name);
    data_out.write_vtu(vtu);
  } else
    name = data_out.write_vtu_with_pvtu_record(dir_ + "/", "fem_dcb", advance, comm_, 4);
  pvd_records_.emplace_back(x_tip_mm, name);
  if (Utilities::MPI::this_mpi_process(comm_) == 0) {
    std::ofstream pvd(dir_ + "/fem_dcb.pvd");
    DataOutBase::write_pvd_record(pvd, pvd_records_);
  }
}

template class FieldOutput<2>;
template class FieldOutput<3>;

void write_interface_csv(const std::string& output_dir, MPI_Comm comm, unsigned dim,
                         const CohesiveInterface& interface, const std::vector<double>& o,
                         const std::vector<double>& point_z) {
  if (output_dir.empty() || Utilities::MPI::this_mpi_process(comm) != 0)
    return;
  std::vector<std::string> header{"x_mm", "opening_mm", "traction_kPa", "delta_max_mm", "state"};
  if (dim == 3)
    header.insert(header.begin() + 1, "z_mm");
  CsvWriter w(output_dir + "/fem_interface.csv", header,
              {"fiberbridge fem (distributed engine, " + std::to_string(dim) +
                   "D): crack-plane interface at the end of the run, one row per integration "
                   "point (x from the load line" +
                   std::string(dim == 3 ? ", z across the width" : "") + ")",
               "state: 0 tied (intact ligament), 1 traction-free (sawn notch), 2 cohesive, "
               "3 failed (opening past delta_c: traction-free, contact only)"});
  for (unsigned seg = 0; seg < interface.n_segments(); ++seg) {
    const auto state = interface.state(seg);
    for (const unsigned p : interface.segment_points(seg)) {
      double code = 0;
      if (state == SegmentState::traction_free)
        code = 1;
      else if (state == SegmentState::cohesive)
        code = interface.has_failed(p) ? 3 : 2;
      const double traction =
          state == SegmentState::intact ? 0.0 : interface.respond(p, o[p]).traction;
      std::vector<double> row{interface.x(p) / units::mm, o[p] / units::mm, traction / units::kPa,
                              interface.delta_max(p) / units::mm, code};
      if (dim == 3)
        row.insert(row.begin() + 1, point_z[p] / units::mm);
      w.row(row);
    }
  }
  w.close();
}

} // namespace fiberbridge::fem
