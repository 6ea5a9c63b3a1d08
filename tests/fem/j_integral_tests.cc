// The cheap domain J (DomainJIntegral, source/fem/j_integrals.h; issue 34 item 3) against the
// plain FEValues loop (bulk_domain_j_local) it replaces, on small meshes with a smooth nonlinear
// displacement field: graded rows and columns (a few cell shapes shared by many cells), Q1 and
// Q2, 2D and 3D, small and finite kinematics, a tapered mesh whose free faces carry the W n_1 q
// term, and a curved mapping that takes the plain path. And the field output (FieldOutput,
// source/fem/field_output.h), written with zlib's best_speed: every data array of the VTU
// decodes to the size its header and the mesh say.
//
// Tolerance of the J comparisons: the same sums in the same order over the same points; cells of
// one shape use the gradients and JxW of one of them, which differ from their own by the
// round-off of the mapping's Jacobian from shifted vertices (1e-16 relative times the cells'
// aspect ratio, here below 10). 1e-12 relative leaves a factor of 100 for the sums over a few
// hundred points; a wrong cell, dof or shape association is an O(1) error.
#include "field_output.h"
#include "j_integrals.h"

#include <deal.II/base/function.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/numerics/vector_tools.h>

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace fiberbridge;
using namespace dealii;

namespace {

constexpr double kTolerance = 1e-12; // see the file comment

/// An isotropic C (E = 10 GPa, nu = 0.3): the comparison needs a stiffness, not a material.
template <int dim>
SymmetricTensor<4, dim> stiffness() {
  const double E = 10e9, nu = 0.3;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  return lambda * outer_product(unit_symmetric_tensor<dim>(), unit_symmetric_tensor<dim>()) +
         2 * mu * identity_tensor<dim>();
}

/// A smooth field with gradients of a few percent that vary over every cell (so that a cell
/// given another cell's shape data or dofs gives another J).
template <int dim>
class Field : public Function<dim> {
public:
  Field() : Function<dim>(dim) {}
  double value(const Point<dim>& p, unsigned c) const override {
    const double x = p[0], y = p[1], z = dim == 3 ? p[2] : 0.0;
    if (c == 0)
      return 0.02 * x * y + 0.01 * std::sin(3 * x) + 0.005 * z * x;
    if (c == 1)
      return 0.03 * x * x - 0.01 * y * y + 0.004 * std::cos(2 * y + x);
    return 0.01 * x * z + 0.002 * y;
  }
};

/// Graded steps: a few distinct sizes, repeated.
std::vector<double> steps(unsigned n, double h) {
  std::vector<double> s;
  for (unsigned i = 0; i < n; ++i)
    s.push_back(h * (i % 3 == 0 ? 1.0 : i % 3 == 1 ? 0.5 : 0.75));
  return s;
}

template <int dim>
struct Problem {
  Triangulation<dim> triangulation;
  FESystem<dim> fe;
  DoFHandler<dim> dof_handler;
  fem::Vec u;

  explicit Problem(unsigned degree) : fe(FE_Q<dim>(degree), dim) {}
  void make(const std::vector<std::vector<double>>& step_sizes) {
    Point<dim> end;
    for (unsigned d = 0; d < dim; ++d)
      for (const double h : step_sizes[d])
        end[d] += h;
    GridGenerator::subdivided_hyper_rectangle(triangulation, step_sizes, Point<dim>(), end);
  }
  void setup(const Mapping<dim>& mapping) {
    dof_handler.reinit(triangulation);
    dof_handler.distribute_dofs(fe);
    u.reinit(dof_handler.locally_owned_dofs(), MPI_COMM_SELF);
    VectorTools::interpolate(mapping, dof_handler, Field<dim>(), u);
  }
  double plain(const Mapping<dim>& mapping, const fem::Ramp& q, bool finite) const {
    return fem::bulk_domain_j_local(dof_handler, mapping, fe.degree, stiffness<dim>(), u, q,
                                    finite);
  }
};

/// Ramps over the mesh (x in [0, 4]): a tip strip, a far-field one, one whose plateau covers it
/// all (only free faces contribute), one wholly outside.
const std::vector<fem::Ramp> kRamps = {
    {0.8, 1.4, 1.9, 2.6}, {0.3, 2.2, 3.0, 3.9}, {-1, -0.5, 5, 6}, {5, 6, 7, 8}};

/// The cached J against the FEValues loop on every ramp, small and finite strain: the same sums
/// (kTolerance above).
template <int dim>
void expect_cached_equals_plain(Problem<dim>& p, const Mapping<dim>& mapping, unsigned degree,
                                fem::DomainJIntegral<dim>& cached) {
  for (const bool finite : {false, true})
    for (const auto& q : kRamps) {
      const double plain = p.plain(mapping, q, finite);
      EXPECT_NEAR(
          cached.bulk_local(p.dof_handler, mapping, degree, stiffness<dim>(), p.u, q, finite),
          plain, kTolerance * std::abs(plain))
          << "finite " << finite;
    }
}

} // namespace

TEST(JIntegral, CachedEqualsPlainOnGradedQ1MeshIn2d) {
  Problem<2> p(1);
  p.make({steps(12, 0.4), steps(5, 0.3)});
  const MappingQ1<2> mapping;
  p.setup(mapping);
  fem::DomainJIntegral<2> cached;
  expect_cached_equals_plain(p, mapping, 1, cached);
  EXPECT_NE(p.plain(mapping, kRamps[0], false), 0.0); // the field has a J to compare
  // 3 column sizes x 3 row sizes: the cache shares them among the 60 cells.
  EXPECT_EQ(cached.n_shapes(), 9u);
}

TEST(JIntegral, CachedEqualsPlainOnQ2And3dMeshes) {
  {
    Problem<2> p(2);
    p.make({steps(6, 0.8), steps(4, 0.5)});
    const MappingQ1<2> mapping;
    p.setup(mapping);
    fem::DomainJIntegral<2> cached;
    expect_cached_equals_plain(p, mapping, 2, cached);
  }
  Problem<3> p(1);
  p.make({steps(8, 0.6), steps(3, 0.4), steps(3, 0.5)});
  const MappingQ1<3> mapping;
  p.setup(mapping);
  fem::DomainJIntegral<3> cached;
  expect_cached_equals_plain(p, mapping, 1, cached);
  EXPECT_NE(p.plain(mapping, kRamps[0], true), 0.0);
}

TEST(JIntegral, CachedKeepsTheFreeFaceTermOfATaperedMesh) {
  // y scaled by 1 + x/4: the top faces slope, their normals have an x component, and no two
  // cells are translates (every cell its own shape).
  Problem<2> p(1);
  p.make({steps(10, 0.4), steps(4, 0.25)});
  GridTools::transform([](const Point<2>& x) { return Point<2>(x[0], x[1] * (1 + 0.25 * x[0])); },
                       p.triangulation);
  const MappingQ1<2> mapping;
  p.setup(mapping);
  fem::DomainJIntegral<2> cached;
  expect_cached_equals_plain(p, mapping, 1, cached);
  // The ramp whose plateau covers the mesh: only the sloping faces contribute, and they do.
  EXPECT_GT(std::abs(p.plain(mapping, kRamps[2], false)), 0.0);
  EXPECT_EQ(cached.n_shapes(), 40u);
}

TEST(JIntegral, CachedTakesThePlainPathForACurvedMappingAndRebuildsForANewMesh) {
  Problem<2> p(1);
  p.make({steps(6, 0.6), steps(3, 0.4)});
  const MappingQ<2> quadratic(2);
  p.setup(quadratic);
  fem::DomainJIntegral<2> cached;
  const double plain = p.plain(quadratic, kRamps[0], false);
  EXPECT_EQ(cached.bulk_local(p.dof_handler, quadratic, 1, stiffness<2>(), p.u, kRamps[0], false),
            plain); // the same function: the same bits
  EXPECT_EQ(cached.n_shapes(), 0u);
  // Another DoFHandler (a refined mesh): the cache is built anew for it.
  const MappingQ1<2> mapping;
  Problem<2> r(1);
  r.make({steps(12, 0.3), steps(6, 0.2)});
  r.setup(mapping);
  const double plain_r = r.plain(mapping, kRamps[1], false);
  EXPECT_NEAR(cached.bulk_local(r.dof_handler, mapping, 1, stiffness<2>(), r.u, kRamps[1], false),
              plain_r, kTolerance * std::abs(plain_r));
  EXPECT_EQ(cached.n_shapes(), 9u);
}

namespace {

std::vector<unsigned char> base64_decode(const std::string& s) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z')
      return c - 'A';
    if (c >= 'a' && c <= 'z')
      return c - 'a' + 26;
    if (c >= '0' && c <= '9')
      return c - '0' + 52;
    return c == '+' ? 62 : c == '/' ? 63 : -1;
  };
  std::vector<unsigned char> out;
  unsigned buffer = 0;
  int bits = 0;
  for (const char c : s) {
    const int v = value(c);
    if (v < 0)
      continue; // '=' padding, white space
    buffer = (buffer << 6) | unsigned(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back((buffer >> bits) & 0xff);
    }
  }
  return out;
}

std::string attribute(const std::string& tag, const std::string& name) {
  const auto at = tag.find(name + "=\"");
  if (at == std::string::npos)
    return "";
  const auto start = at + name.size() + 2;
  return tag.substr(start, tag.find('"', start) - start);
}

} // namespace

TEST(FemFieldOutput, VtuWrittenWithBestSpeedDecodesToTheMeshSizes) {
  // deal.II writes each binary array as a base64 header (UInt32: blocks, block size, last block
  // size, compressed sizes) and the base64 zlib blocks. A reader (VTK's vtkZLibDataCompressor)
  // needs the blocks to inflate to the sizes the header gives, and those to be the mesh's points
  // and cells times the components.
  Problem<2> p(1);
  p.make({steps(9, 0.4), steps(4, 0.3)});
  const MappingQ1<2> mapping;
  p.setup(mapping);
  const auto dir = std::filesystem::temp_directory_path() / "fiberbridge_field_output_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  fem::FieldOutput<2> output(dir.string(), MPI_COMM_SELF, false);
  fem::Vec ghost = p.u;
  output.write(p.dof_handler, mapping, stiffness<2>(), ghost, 3, 12.5);
  std::ifstream in(dir / "fem_dcb-0003.vtu");
  ASSERT_TRUE(in.good());
  std::stringstream text;
  text << in.rdbuf();
  const std::string vtu = text.str();
  ASSERT_NE(vtu.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  // No header_type: VTK's default, UInt32.
  ASSERT_EQ(vtu.find("header_type"), std::string::npos);
  const std::size_t piece = vtu.find("<Piece");
  const std::string piece_tag = vtu.substr(piece, vtu.find('>', piece) - piece);
  const unsigned n_points = std::stoul(attribute(piece_tag, "NumberOfPoints"));
  const unsigned n_cells = std::stoul(attribute(piece_tag, "NumberOfCells"));
  EXPECT_EQ(n_cells, 36u); // one patch per cell, Q1: one VTK cell each
  EXPECT_EQ(n_points, 4 * n_cells);
  unsigned n_arrays = 0;
  std::vector<std::string> names;
  for (std::size_t at = vtu.find("<DataArray"); at != std::string::npos;
       at = vtu.find("<DataArray", at + 1)) {
    const std::size_t body = vtu.find('>', at) + 1;
    const std::string tag = vtu.substr(at, body - at);
    const std::string data = vtu.substr(body, vtu.find("</DataArray>", body) - body);
    ASSERT_EQ(attribute(tag, "format"), "binary") << tag;
    // The header: 4 UInt32 words for one block, 16 bytes = 24 base64 characters.
    std::string trimmed;
    for (const char c : data)
      if (!std::isspace(static_cast<unsigned char>(c)))
        trimmed += c;
    const auto header = base64_decode(trimmed.substr(0, 24));
    ASSERT_EQ(header.size(), 16u);
    auto word = [&](unsigned i) {
      return std::uint32_t(header[4 * i]) | std::uint32_t(header[4 * i + 1]) << 8 |
             std::uint32_t(header[4 * i + 2]) << 16 | std::uint32_t(header[4 * i + 3]) << 24;
    };
    ASSERT_EQ(word(0), 1u) << tag; // one block
    const auto compressed = base64_decode(trimmed.substr(24));
    ASSERT_EQ(compressed.size(), word(3)) << tag;
    // The zlib stream's header: deflate (0x78), FLEVEL 0, the fastest algorithm (best_speed;
    // deal.II's default best_compression writes FLEVEL 3).
    ASSERT_GE(compressed.size(), 2u);
    EXPECT_EQ(compressed[0], 0x78) << tag;
    EXPECT_EQ(compressed[1] >> 6, 0) << tag;
    std::vector<unsigned char> raw(word(1));
    uLongf raw_size = raw.size();
    ASSERT_EQ(uncompress(raw.data(), &raw_size, compressed.data(), compressed.size()), Z_OK) << tag;
    EXPECT_EQ(raw_size, word(1)) << tag;
    // Sizes: Float32 point data (3 components of points and of the displacement), the stress
    // components one each, Int32/UInt8 cell arrays.
    const std::string type = attribute(tag, "type"), name = attribute(tag, "Name");
    const unsigned components = attribute(tag, "NumberOfComponents").empty()
                                    ? 1
                                    : std::stoul(attribute(tag, "NumberOfComponents"));
    const unsigned bytes = type == "Float32" || type == "Int32" ? 4 : type == "UInt8" ? 1 : 8;
    if (name == "connectivity")
      EXPECT_EQ(raw_size, 4u * n_cells * bytes);
    else if (name == "offsets" || name == "types")
      EXPECT_EQ(raw_size, n_cells * bytes);
    else if (name == "rank")
      EXPECT_EQ(raw_size, n_points * bytes) << "cell data as point data, as deal.II writes it";
    else
      EXPECT_EQ(raw_size, std::size_t(n_points) * components * bytes) << tag;
    names.push_back(name);
    ++n_arrays;
  }
  // Points, connectivity, offsets, types, displacement, three stresses, rank.
  EXPECT_EQ(n_arrays, 9u);
  EXPECT_NE(std::find(names.begin(), names.end(), "displacement_m"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "stress_xy_Pa"), names.end());
  std::filesystem::remove_all(dir);
}
