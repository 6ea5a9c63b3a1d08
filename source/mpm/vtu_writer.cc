#include "fiberbridge/mpm/vtu_writer.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"

#include <cstdio>
#include <sstream>

namespace fiberbridge::mpm {

ParticleVtuWriter::ParticleVtuWriter(std::string directory, std::string base)
    : directory_(std::move(directory)), base_(std::move(base)) {}

void ParticleVtuWriter::write(const ExplicitSolver& solver) {
  const Particles& P = solver.particles();
  const std::size_t n = P.size();
  char name[64];
  std::snprintf(name, sizeof name, "_%04zu.vtu", written_.size());
  const std::string file = base_ + name;

  std::ostringstream s;
  s.precision(9);
  s << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n
    << "\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t p = 0; p < n; ++p)
    s << P.x[p] << ' ' << P.y[p] << " 0\n";
  s << "</DataArray>\n</Points>\n<Cells>\n"
    << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t p = 0; p < n; ++p)
    s << p << '\n';
  s << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t p = 0; p < n; ++p)
    s << p + 1 << '\n';
  s << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t p = 0; p < n; ++p)
    s << "1\n"; // VTK_VERTEX
  s << "</DataArray>\n</Cells>\n<PointData Vectors=\"displacement_m\">\n"
    << "<DataArray type=\"Float64\" Name=\"displacement_m\" NumberOfComponents=\"3\" "
       "format=\"ascii\">\n";
  for (std::size_t p = 0; p < n; ++p)
    s << P.x[p] - P.X[p] << ' ' << P.y[p] - P.Y[p] << " 0\n";
  s << "</DataArray>\n<DataArray type=\"Float64\" Name=\"velocity_m_s\" "
       "NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t p = 0; p < n; ++p)
    s << P.vx[p] << ' ' << P.vy[p] << " 0\n";
  s << "</DataArray>\n<DataArray type=\"Float64\" Name=\"stress_Pa\" NumberOfComponents=\"9\" "
       "format=\"ascii\">\n";
  for (std::size_t p = 0; p < n; ++p) {
    const auto& t = P.stress[p];
    s << t[0] << ' ' << t[2] << " 0 " << t[2] << ' ' << t[1] << " 0 0 0 0\n";
  }
  s << "</DataArray>\n<DataArray type=\"Float64\" Name=\"strain_energy_density_J_m3\" "
       "format=\"ascii\">\n";
  for (std::size_t p = 0; p < n; ++p)
    s << solver.energy_density(static_cast<int>(p)) << '\n';
  s << "</DataArray>\n</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  write_file_atomically(directory_ + "/" + file, s.str());
  written_.emplace_back(solver.time(), file);

  std::ostringstream pvd;
  pvd.precision(12);
  pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
      << "<Collection>\n";
  for (const auto& [t, f] : written_)
    pvd << "<DataSet timestep=\"" << t << "\" part=\"0\" file=\"" << f << "\"/>\n";
  pvd << "</Collection>\n</VTKFile>\n";
  write_file_atomically(directory_ + "/" + base_ + ".pvd", pvd.str());
}

} // namespace fiberbridge::mpm
