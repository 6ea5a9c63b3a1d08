// Reading a specimen mesh (specimen_mesh.h; docs/design.md section 2, "Specimen meshes").
#include "specimen_mesh.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/dcb_common.h"

#include <deal.II/base/config.h>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fiberbridge::fem {

using namespace dealii;

namespace {

std::string mm_text(double metres) {
  return fmt(metres / units::mm) + " mm";
}

/// "name: value, name: value" -> pairs; the names are Gmsh identifiers.
std::vector<std::pair<std::string, double>> parse_pairs(const std::string& text) {
  std::vector<std::pair<std::string, double>> pairs;
  std::stringstream all(text);
  std::string item;
  while (std::getline(all, item, ',')) {
    const auto colon = item.find(':');
    const std::string name = trim_blanks(item.substr(0, colon));
    const std::string value = colon == std::string::npos ? "" : trim_blanks(item.substr(colon + 1));
    const bool identifier = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) &&
                            std::all_of(name.begin(), name.end(), [](char c) {
                              return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                            });
    char* end = nullptr;
    const double v = value.empty() ? 0.0 : std::strtod(value.c_str(), &end);
    if (!identifier || value.empty() || *end != '\0' || !std::isfinite(v))
      throw InputError("FEM/Mesh file parameters: '" + trim_blanks(item) +
                       "' is not a pair 'name: number' (name a Gmsh identifier)");
    pairs.emplace_back(name, v);
  }
  return pairs;
}

std::string quoted(const std::string& s) {
  if (s.find('\'') != std::string::npos)
    throw InputError("FEM/Mesh file: the path " + s + " contains a quote");
  return "'" + s + "'";
}

/// Meshes a .geo with the gmsh executable into a format-2 .msh in the temporary directory.
std::filesystem::path mesh_geo(const std::string& geo,
                               const std::vector<std::pair<std::string, double>>& numbers,
                               unsigned rank) {
#ifdef DEAL_II_GMSH_EXECUTABLE_PATH
  const std::string gmsh = DEAL_II_GMSH_EXECUTABLE_PATH;
#else
  const std::string gmsh = "gmsh";
#endif
  const auto stem = std::filesystem::temp_directory_path() /
                    ("fiberbridge_mesh_" + std::to_string(::getpid()) + "_" + std::to_string(rank));
  const auto msh = std::filesystem::path(stem.string() + ".msh");
  const auto log = std::filesystem::path(stem.string() + ".log");
  std::string command = quoted(gmsh) + " -2 -format msh2 -v 3";
  for (const auto& [name, value] : numbers) {
    char v[64];
    std::snprintf(v, sizeof v, "%.17g", value);
    command += " -setnumber " + name + " " + v;
  }
  command +=
      " -o " + quoted(msh.string()) + " " + quoted(geo) + " > " + quoted(log.string()) + " 2>&1";
  std::filesystem::remove(msh);
  const int status = std::system(command.c_str());
  std::string errors;
  {
    std::ifstream in(log);
    for (std::string line; std::getline(in, line);)
      if (line.rfind("Error", 0) == 0)
        errors += (errors.empty() ? "" : "; ") + line;
  }
  std::filesystem::remove(log);
  if (status != 0 || !errors.empty() || !std::filesystem::exists(msh)) {
    std::filesystem::remove(msh);
    throw InputError("FEM/Mesh file " + geo + ": gmsh (" + gmsh + ") could not mesh it" +
                     (errors.empty() ? std::string(" (is gmsh installed?)") : ": " + errors));
  }
  return msh;
}

/// The first line of a deal.II exception's text that says what went wrong.
std::string reason(const std::exception& e) {
  std::stringstream text(e.what());
  std::string line, last;
  while (std::getline(text, line))
    if (line.find("Additional information") != std::string::npos)
      return std::getline(text, line) ? line : last;
    else if (!line.empty())
      last = line;
  return last;
}

/// The largest x (m) of a boundary face of `mesh` (coordinates in mm) that runs across an arm
/// (more vertical than horizontal) between the load line and the notch tip a0: an end block's
/// edge. 0 if there is none (the load line itself does not count).
double last_end_feature(const Triangulation<2>& mesh, double a0, double tol) {
  double x_feature = 0;
  for (const auto& cell : mesh.active_cell_iterators())
    for (const unsigned f : cell->face_indices()) {
      if (!cell->face(f)->at_boundary())
        continue;
      const Point<2> p = cell->face(f)->vertex(0) * units::mm;
      const Point<2> q = cell->face(f)->vertex(1) * units::mm;
      const double x = std::max(p[0], q[0]);
      if (std::abs(q[1] - p[1]) > std::abs(q[0] - p[0]) && x > tol && x < a0 - tol)
        x_feature = std::max(x_feature, x);
    }
  return x_feature;
}

} // namespace

std::vector<std::pair<std::string, double>> gmsh_numbers(const specimen::Specimen& specimen,
                                                         const FemParameters& p) {
  // Lengths in mm, as the scene speaks them (and as a user draws a specimen in Gmsh).
  std::vector<std::pair<std::string, double>> numbers = {
      {"L", specimen.length / units::mm},
      {"a0", specimen.initial_crack / units::mm},
      {"h", specimen.arm_thickness() / units::mm},
      {"dx", crack_plane_step(specimen, p) / units::mm},
      {"layers", double(p.mesh.min_layers)},
      {"grading", p.mesh.grading}};
  for (const auto& pair : parse_pairs(p.mesh.file_parameters))
    numbers.push_back(pair);
  return numbers;
}

DcbGeometry read_specimen_mesh(const specimen::Specimen& specimen, const FemParameters& p,
                               parallel::distributed::Triangulation<2>& triangulation) {
  const std::string& file = p.mesh.file;
  const std::string where = "FEM/Mesh file " + file;
  const std::string extension = std::filesystem::path(file).extension().string();
  if (extension != ".geo" && extension != ".msh")
    throw InputError(where + ": expected a Gmsh .geo or .msh file");
  if (!std::filesystem::exists(file))
    throw InputError(where + ": no such file");
  const double dx = crack_plane_step(specimen, p);
  // Nodes within 1e-4 dx of a station are on it: Gmsh writes 16 digits, a user's script may
  // write fewer (the snapping below moves them by less than that).
  const double L = specimen.length, tol = 1e-4 * dx;

  // Read into a serial triangulation first: its coarse description is checked and relabelled
  // before the distributed one is made.
  Triangulation<2> serial;
  {
    std::filesystem::path msh = file;
    if (extension == ".geo")
      msh = mesh_geo(file, gmsh_numbers(specimen, p),
                     Utilities::MPI::this_mpi_process(triangulation.get_communicator()));
    GridIn<2> grid_in;
    grid_in.attach_triangulation(serial);
    std::ifstream in(msh);
    try {
      grid_in.read_msh(in);
    } catch (const std::exception& e) {
      if (extension == ".geo")
        std::filesystem::remove(msh);
      throw InputError(where + ": not a deal.II-readable quadrilateral Gmsh mesh (" + reason(e) +
                       ")");
    }
    if (extension == ".geo")
      std::filesystem::remove(msh);
  }
  if (serial.n_active_cells() == 0 || !serial.all_reference_cells_are_hyper_cube())
    throw InputError(where + ": expected a mesh of quadrilaterals only (Gmsh: Recombine the "
                             "surfaces); the FEM's elements are FE_Q");
  const double x_feature = last_end_feature(serial, specimen.initial_crack, tol);
  if (x_feature > 0 && std::ceil((x_feature + specimen.arm_thickness()) / dx - 1e-9) * dx >=
                           std::round(0.8 * specimen.initial_crack / dx) * dx)
    throw InputError(where + ": a free face across the arm at x = " + mm_text(x_feature) +
                     " (an end block's edge) leaves no room for the far-field J domain between "
                     "it and the notch: it must end more than one arm thickness before 0.8 a0 = " +
                     mm_text(0.8 * specimen.initial_crack));
  auto [vertices, cells, subcell_data] = GridTools::get_coarse_mesh_description(serial);
  for (auto& v : vertices)
    v *= units::mm; // a specimen mesh is drawn in mm

  // Gmsh places nodes on straight lines with round-off (1e-14 relative): snap them onto the
  // crack plane and onto the x stations k dx, so that the crack plane's nodes, the interface's
  // elements and the J ramps' kinks lie exactly where the engine puts its mesh lines.
  for (auto& v : vertices) {
    if (std::abs(v[1]) < tol)
      v[1] = 0;
    const double k = std::round(v[0] / dx);
    if (std::abs(v[0] - k * dx) < tol)
      v[0] = k * dx;
    if (std::abs(v[0] - L) < tol)
      v[0] = L;
  }

  // Arms from the physical surfaces: 1 upper -> material 0, 2 lower -> 1 (the engine's ids).
  std::vector<int> arm_of_vertex(vertices.size(), -1);
  double y_min = 0, y_max = 0, x_min = 0;
  for (auto& c : cells) {
    Point<2> centre;
    for (const unsigned v : c.vertices)
      centre += vertices[v] / double(c.vertices.size());
    if (c.material_id != 1 && c.material_id != 2)
      throw InputError(where + ": a cell at (" + mm_text(centre[0]) + ", " + mm_text(centre[1]) +
                       ") has physical surface " + std::to_string(c.material_id) +
                       "; expected 1 (upper arm, y > 0) or 2 (lower arm, y < 0)");
    const int arm = int(c.material_id) - 1;
    if ((arm == 0) != (centre[1] > 0))
      throw InputError(where + ": a cell of physical surface " + std::to_string(c.material_id) +
                       " lies at y = " + mm_text(centre[1]) +
                       "; surface 1 is the upper arm "
                       "(y > 0), 2 the lower (y < 0)");
    c.material_id = arm;
    for (const unsigned v : c.vertices) {
      if (arm_of_vertex[v] >= 0 && arm_of_vertex[v] != arm)
        throw InputError(where + ": the arms share the vertex at (" + mm_text(vertices[v][0]) +
                         ", " + mm_text(vertices[v][1]) +
                         "); the crack plane must be two "
                         "coincident curves, one per arm, so that the arms can separate");
      arm_of_vertex[v] = arm;
      y_min = std::min(y_min, vertices[v][1]);
      y_max = std::max(y_max, vertices[v][1]);
      x_min = std::min(x_min, vertices[v][0]);
    }
  }
  if (!(y_max > 0) || !(y_min < 0))
    throw InputError(where + ": expected both arms (physical surfaces 1 and 2)");
  if (x_min < -tol)
    throw InputError(where + ": the mesh reaches x = " + mm_text(x_min) +
                     "; the load line is x = 0 and the specimen starts there");

  // The crack plane: the same x stations on both arms, every dx from 0 to L (the last element
  // may be up to half an element longer or shorter, as in the generated mesh).
  std::vector<double> xs[2];
  unsigned load_line[2] = {0, 0};
  for (unsigned v = 0; v < vertices.size(); ++v) {
    if (arm_of_vertex[v] < 0)
      continue;
    if (std::abs(vertices[v][1]) < tol)
      xs[arm_of_vertex[v]].push_back(vertices[v][0]);
    if (std::abs(vertices[v][0]) < tol)
      ++load_line[arm_of_vertex[v]];
  }
  for (auto& x : xs) {
    std::sort(x.begin(), x.end());
    x.erase(std::unique(x.begin(), x.end(), [&](double u, double w) { return w - u < tol; }),
            x.end());
  }
  auto stations_text = [&](const std::vector<double>& x) {
    return x.empty() ? std::string("none")
                     : std::to_string(x.size()) + " from x = " + mm_text(x.front()) + " to " +
                           mm_text(x.back());
  };
  if (xs[0].size() != xs[1].size() ||
      !std::equal(xs[0].begin(), xs[0].end(), xs[1].begin(),
                  [&](double u, double w) { return std::abs(u - w) < tol; }))
    throw InputError(where + ": the arms' crack-plane nodes (y = 0) differ: upper arm " +
                     stations_text(xs[0]) + ", lower arm " + stations_text(xs[1]) +
                     "; both arms need the same stations");
  const auto& x = xs[0];
  if (x.size() < 2 || std::abs(x.front()) > tol || std::abs(x.back() - L) > tol)
    throw InputError(where + ": the crack-plane nodes run " + stations_text(x) +
                     "; expected from the load line x = 0 to Specimen/Length = " + mm_text(L));
  for (std::size_t i = 1; i < x.size(); ++i) {
    const double step = x[i] - x[i - 1];
    const bool last = i + 1 == x.size();
    if (last ? (step > 1.5 * dx + tol) : std::abs(step - dx) > tol)
      throw InputError(where + ": crack-plane nodes at x = " + mm_text(x[i - 1]) + " and " +
                       mm_text(x[i]) + " are " + mm_text(step) +
                       " apart; the scene's element "
                       "length is dx = " +
                       mm_text(dx) +
                       " (Specimen/Initial crack / round(Initial "
                       "crack / FEM/Element size)): every crack-plane element must be dx long, "
                       "the last at most 1.5 dx");
  }
  for (unsigned arm = 0; arm < 2; ++arm)
    if (load_line[arm] < 2)
      throw InputError(where + ": the " + std::string(arm == 0 ? "upper" : "lower") + " arm has " +
                       std::to_string(load_line[arm]) +
                       " node(s) on the load "
                       "line x = 0; expected its end face or a pin line there");

  // Physical curves are not needed (the engine finds y = 0 and x = 0 itself): drop their ids.
  GridTools::delete_unused_vertices(vertices, cells, subcell_data);
  triangulation.create_triangulation(vertices, cells, SubCellData());
  DcbGeometry g;
  g.dx = dx;
  g.x_lines = x;
  g.z_lines = {0.0};
  g.x_last_end_feature = x_feature;
  return g;
}

} // namespace fiberbridge::fem
