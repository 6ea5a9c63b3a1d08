#include "fiberbridge/result/virtual_dic.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

namespace fiberbridge::result {

using units::mm;

DicLayout parse_dic_layout(const std::string& text, const std::string& key) {
  return dic::parse_written_layout(text, key);
}

const char* dic_layout_name(DicLayout layout) {
  return dic::layout_name(layout);
}

const char* dic_layout_extension(DicLayout layout) {
  return dic::layout_entry(layout).extension;
}

std::string dic_layout_selection() {
  return dic::layout_names("|", true);
}

std::string dic_layout_descriptions() {
  return dic::layout_descriptions(true);
}

void VirtualDicSettings::validate(const std::string& section) const {
  auto require = [&](bool ok, const char* key, const std::string& what) {
    if (!ok)
      throw InputError(section + "/" + key + ": " + what);
  };
  require(frame_rate > 0, "Frame rate", "must be positive (Hz)");
  require(record_rate > 0, "Record rate", "must be positive (Hz)");
  require(crosshead_rate > 0, "Crosshead rate", "must be positive (mm/min)");
  require(std::isfinite(first_frame_time), "First frame time", "must be a number (s)");
  require(spacing > 0, "Point spacing", "must be positive (mm)");
  require(noise >= 0, "Displacement noise", "must be >= 0 (mm)");
  // A window of one spacing holds a single column or row of points: no gradient across it.
  require(strain_window >= 2 * spacing * (1 - 1e-9), "Strain window",
          "must span at least two point spacings (" + fmt(2 * spacing / mm) + " mm)");
  require(pixel_size > 0, "Pixel size", "must be positive (mm/px)");
  require(failed_fraction >= 0 && failed_fraction < 1, "Failed fraction", "must lie in [0, 1)");
  require(!(pixels && dic::layout_entry(layout).mm_only), "Coordinates",
          std::string(dic_layout_name(layout)) + " frames are in mm; px is for the other layouts");
}

DicGrid make_dic_grid(const VirtualDicSettings& s, double length, double half_height) {
  const double xa = s.x_from < s.x_to ? s.x_from : 0.0, xb = s.x_from < s.x_to ? s.x_to : length;
  const double ya = s.y_from < s.y_to ? s.y_from : -half_height,
               yb = s.y_from < s.y_to ? s.y_to : half_height;
  const double h = s.spacing, eps = 1e-9;
  DicGrid g;
  g.spacing = h;
  g.x0 = xa;
  g.nx = xb >= xa ? unsigned(std::floor((xb - xa) / h + eps)) + 1 : 0;
  // Rows at (m + 1/2) h: none on the crack plane y = 0.
  const double m_lo = std::ceil(ya / h - 0.5 - eps), m_hi = std::floor(yb / h - 0.5 + eps);
  g.y0 = (m_lo + 0.5) * h;
  g.ny = m_hi >= m_lo ? unsigned(m_hi - m_lo) + 1 : 0;
  if (g.nx == 0 || g.ny == 0)
    throw InputError("Virtual DIC: the field of view x " + fmt(xa / mm) + ".." + fmt(xb / mm) +
                     " mm, y " + fmt(ya / mm) + ".." + fmt(yb / mm) + " mm holds no point at " +
                     fmt(h / mm) + " mm spacing (rows sit half a spacing off the crack plane)");
  return g;
}

DicStrains fit_dic_strains(const DicGrid& grid, const std::vector<double>& u,
                           const std::vector<double>& v, const std::vector<char>& valid,
                           double window, bool lagrange) {
  const std::size_t n = grid.size();
  const int half = int(std::floor(window / (2 * grid.spacing) + 1e-9));
  DicStrains e;
  e.exx.assign(n, 0.0);
  e.eyy.assign(n, 0.0);
  e.exy.assign(n, 0.0);
  e.ok.assign(n, 0);
  const int nx = int(grid.nx), ny = int(grid.ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::size_t k = std::size_t(j) * nx + i;
      if (!valid[k])
        continue;
      // Normal equations of u = a + b di + c dj in grid units (di, dj integers: well scaled).
      double S = 0, Si = 0, Sj = 0, Sii = 0, Sij = 0, Sjj = 0;
      double Su = 0, Sui = 0, Suj = 0, Sv = 0, Svi = 0, Svj = 0;
      for (int dj = -half; dj <= half; ++dj) {
        const int jj = j + dj;
        if (jj < 0 || jj >= ny)
          continue;
        for (int di = -half; di <= half; ++di) {
          const int ii = i + di;
          if (ii < 0 || ii >= nx)
            continue;
          const std::size_t q = std::size_t(jj) * nx + ii;
          if (!valid[q])
            continue;
          S += 1;
          Si += di;
          Sj += dj;
          Sii += di * di;
          Sij += di * dj;
          Sjj += dj * dj;
          Su += u[q];
          Sui += u[q] * di;
          Suj += u[q] * dj;
          Sv += v[q];
          Svi += v[q] * di;
          Svj += v[q] * dj;
        }
      }
      // Cofactors of the symmetric 3x3 matrix [[S, Si, Sj], [Si, Sii, Sij], [Sj, Sij, Sjj]].
      const double c00 = Sii * Sjj - Sij * Sij, c01 = Sij * Sj - Si * Sjj,
                   c02 = Si * Sij - Sii * Sj, c11 = S * Sjj - Sj * Sj, c12 = Si * Sj - S * Sij,
                   c22 = S * Sii - Si * Si;
      const double det = S * c00 + Si * c01 + Sj * c02;
      // Collinear points (one row or column) leave the matrix singular; the scale of det is
      // S^3 window^4 in grid units, so a relative bound separates them from round-off.
      if (!(det > 1e-9 * S * S * S))
        continue;
      const double h = grid.spacing;
      const double ux = (c01 * Su + c11 * Sui + c12 * Suj) / det / h,
                   uy = (c02 * Su + c12 * Sui + c22 * Suj) / det / h,
                   vx = (c01 * Sv + c11 * Svi + c12 * Svj) / det / h,
                   vy = (c02 * Sv + c12 * Svi + c22 * Svj) / det / h;
      e.exx[k] = ux;
      e.eyy[k] = vy;
      e.exy[k] = 0.5 * (uy + vx);
      if (lagrange) {
        e.exx[k] += 0.5 * (ux * ux + vx * vx);
        e.eyy[k] += 0.5 * (uy * uy + vy * vy);
        e.exy[k] += 0.5 * (ux * uy + vx * vy);
      }
      e.ok[k] = 1;
    }
  return e;
}

double frame_x(const VirtualDicSettings& s, const DicGrid& grid, double x) {
  // Pixels from a corner one spacing outside the field of view, as an area of interest sits
  // inside an image.
  return s.pixels ? (x - (grid.x0 - grid.spacing)) / s.pixel_size : x / mm;
}

double frame_y(const VirtualDicSettings& s, const DicGrid& grid, double y) {
  if (!s.pixels)
    return (s.y_down ? -y : y) / mm;
  const double bottom = grid.y0 - grid.spacing,
               top = grid.y0 + double(grid.ny - 1) * grid.spacing + grid.spacing;
  return (s.y_down ? top - y : y - bottom) / s.pixel_size;
}

namespace {

void write_text(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    if (!out)
      throw InputError("Virtual DIC: cannot write " + path);
  }
  std::filesystem::rename(tmp, path);
}

} // namespace

void write_dic_frame(const std::string& path, const VirtualDicSettings& s, const DicGrid& grid,
                     const DicFrameData& f) {
  const double to_len = s.pixels ? 1 / s.pixel_size : 1 / mm;
  const double flip = s.y_down ? -1 : 1; // v and exy change sign with the y axis
  const dic::LayoutEntry& layout = dic::layout_entry(s.layout);
  dic::FrameFileHeader h;
  h.number = f.number;
  h.time = f.time;
  h.load = f.load;
  h.opening_mm = f.opening / mm;
  h.pixels = s.pixels;
  h.y_down = s.y_down;
  h.strain_window_mm = s.strain_window / mm;
  std::string t;
  t.reserve(grid.size() * 96 + 1024);
  layout.write_header(t, h);
  dic::FramePoint p;
  // The correlation's confidence interval in pixels (VIC's and DICe's sigma) is the noise here.
  p.sigma = s.noise / s.pixel_size;
  for (std::size_t k = 0; k < grid.size(); ++k) {
    p.index = k;
    p.ok = f.strains.ok[k];
    p.x = frame_x(s, grid, grid.x(k));
    p.y = frame_y(s, grid, grid.y(k));
    p.u = p.ok ? f.u[k] * to_len : 0;
    p.v = p.ok ? flip * f.v[k] * to_len : 0;
    p.exx = p.ok ? f.strains.exx[k] : 0;
    p.eyy = p.ok ? f.strains.eyy[k] : 0;
    p.exy = p.ok ? flip * f.strains.exy[k] : 0;
    layout.write_point(t, p);
  }
  write_text(path, t);
}

VirtualDicTest::VirtualDicTest(const VirtualDicSettings& settings, const DicGrid& grid,
                               std::vector<char> on_body)
    : s_(settings), grid_(grid), on_body_(std::move(on_body)) {
  if (on_body_.size() != grid_.size())
    throw std::logic_error("VirtualDicTest: on_body has the wrong size");
}

void VirtualDicTest::add_state(VirtualTestState state) {
  if (state.u.size() != grid_.size() || state.v.size() != grid_.size())
    throw std::logic_error("VirtualDicTest::add_state: displacements of the wrong size");
  states_.push_back(std::move(state));
}

std::vector<std::pair<double, std::size_t>> VirtualDicTest::clock() const {
  std::vector<std::pair<double, std::size_t>> c;
  double running_max = -HUGE_VAL;
  for (std::size_t k = 0; k < states_.size(); ++k) {
    const double v = states_[k].opening;
    if (c.empty() || v > running_max) {
      running_max = std::max(v, 0.0);
      c.emplace_back(running_max / s_.crosshead_rate, k);
    } else
      c.back().second = k; // the machine jumps to this state at the earlier maximum
  }
  return c;
}

VirtualTestFiles VirtualDicTest::write(const std::string& directory,
                                       const std::string& scene_sections,
                                       double initial_crack) const {
  if (states_.empty())
    throw std::logic_error("VirtualDicTest::write: no state");
  namespace fs = std::filesystem;
  const std::string frames_dir = directory + "/frames";
  fs::create_directories(frames_dir);
  // A rerun with fewer frames must not leave the old run's last frames behind.
  for (const auto& entry : fs::directory_iterator(frames_dir))
    if (entry.path().filename().string().rfind("dcb_", 0) == 0)
      fs::remove(entry.path());
  const auto c = clock();
  const double t_end = c.back().first;

  // The state at time t: linear in time between the states that bracket it (between two
  // recorded equilibria the tip moves by one element; the fields and the truth alike are
  // interpolated, docs/design.md section 2, "Virtual DIC test").
  struct Blend {
    std::size_t a, b;
    double w;
  };
  auto blend = [&](double t) -> Blend {
    if (t <= c.front().first)
      return {c.front().second, c.front().second, 0.0};
    for (std::size_t i = 1; i < c.size(); ++i)
      if (t <= c[i].first)
        return {c[i - 1].second, c[i].second, (t - c[i - 1].first) / (c[i].first - c[i - 1].first)};
    return {c.back().second, c.back().second, 0.0};
  };
  auto mix = [](double x, double y, double w) { return (1 - w) * x + w * y; };

  VirtualTestFiles out;
  out.directory = directory;
  out.n_points = unsigned(grid_.size());
  out.n_on_body = unsigned(std::count(on_body_.begin(), on_body_.end(), char(1)));
  out.duration = t_end;

  CsvWriter truth(
      directory + "/virtual_test_truth.csv",
      {"frame", "time_s", "load_N", "opening_mm", "crack_tip_mm", "zone_front_mm", "delta_root_mm"},
      {"virtual test: the model's truth at each DIC frame (not in the frames)",
       "crack_tip_mm: traction-free crack tip (root of the bridging zone), "
       "zone_front_mm: front of the cohesive zone, both from the load line;",
       "delta_root_mm: opening at the initial notch root; linear in time between "
       "the model's equilibrium states"});
  const std::string ext = dic_layout_extension(s_.layout);
  const std::uint64_t seed = s_.seed;
  for (unsigned f = 1;; ++f) {
    const double t = s_.first_frame_time + double(f - 1) / s_.frame_rate;
    if (t > t_end * (1 + 1e-12))
      break;
    const Blend b = blend(t);
    const auto &A = states_[b.a], &B = states_[b.b];
    DicFrameData fr;
    fr.number = f;
    fr.time = t;
    fr.load = mix(A.load, B.load, b.w);
    fr.opening = mix(A.opening, B.opening, b.w);
    const std::size_t n = grid_.size();
    fr.u.resize(n);
    fr.v.resize(n);
    std::vector<char> valid(n);
    // One stream per frame (seed, frame number): a frame's noise does not depend on the others.
    std::seed_seq seq{std::uint32_t(seed), std::uint32_t(seed >> 32), std::uint32_t(f)};
    std::mt19937_64 rng(seq);
    std::normal_distribution<double> gauss(0.0, 1.0);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (std::size_t k = 0; k < n; ++k) {
      const double nu = gauss(rng), nv = gauss(rng), fail = uniform(rng);
      valid[k] = on_body_[k] && !(fail < s_.failed_fraction);
      fr.u[k] = valid[k] ? mix(A.u[k], B.u[k], b.w) + s_.noise * nu : 0.0;
      fr.v[k] = valid[k] ? mix(A.v[k], B.v[k], b.w) + s_.noise * nv : 0.0;
    }
    fr.strains = fit_dic_strains(grid_, fr.u, fr.v, valid, s_.strain_window, s_.lagrange);
    char name[32];
    std::snprintf(name, sizeof name, "dcb_%04u", f);
    write_dic_frame(frames_dir + "/" + name + ext, s_, grid_, fr);
    truth.row({double(f), t, fr.load, fr.opening / mm, mix(A.crack_tip, B.crack_tip, b.w) / mm,
               mix(A.zone_front, B.zone_front, b.w) / mm,
               mix(A.delta_root, B.delta_root, b.w) / mm});
    out.n_frames = f;
  }
  truth.close();

  CsvWriter machine(directory + "/machine.csv", {"time_s", "load_N", "opening_mm"},
                    {"virtual testing machine: load-point opening at " +
                     fmt(s_.crosshead_rate / mm * 60) + " mm/min, " + fmt(s_.record_rate) +
                     " rows per second, the DIC frames' clock"});
  for (unsigned r = 0;; ++r) {
    const double t = double(r) / s_.record_rate;
    if (t > t_end * (1 + 1e-12))
      break;
    const Blend b = blend(t);
    machine.row({t, mix(states_[b.a].load, states_[b.b].load, b.w),
                 mix(states_[b.a].opening, states_[b.b].opening, b.w) / mm});
  }
  machine.close();

  // The scene, in the frames' own coordinates (issue 32's Interface keys).
  const double a0_frame = frame_x(s_, grid_, initial_crack);
  const double crack_y_frame = frame_y(s_, grid_, 0.0);
  // The extensometer's points one spacing above and below the crack plane: between the first and
  // second rows on each side, so each has points of its own arm around it.
  const double gauge = 2 * grid_.spacing;
  std::string sc;
  sc += "# Virtual test written by the fiberbridge FEM (FEM/Virtual DIC): " +
        std::to_string(out.n_frames) + " frames of " + std::to_string(out.n_points) + " points (" +
        std::to_string(out.n_on_body) + " on the specimen), layout " + dic_layout_name(s_.layout) +
        ", point spacing " + fmt(grid_.spacing / mm) + " mm, displacement noise " +
        fmt(s_.noise / mm) + " mm, strain window " + fmt(s_.strain_window / mm) + " mm (" +
        (s_.lagrange ? "Green-Lagrange" : "infinitesimal") +
        " strain).\n# The model's truth per frame is in virtual_test_truth.csv. Run:\n"
        "#   fiberbridge run " +
        directory + "/dic_scene.prm\n";
  sc += "set Output directory = " + fs::absolute(fs::path(directory) / "dic_output").string() +
        "\nset Run = dic, reduce, extract\n\n";
  sc += scene_sections;
  sc += "\nsubsection DIC\n";
  sc += "  set Frames                    = frames/dcb_*" + ext + "\n";
  sc += std::string("  set Format                    = ") + dic_layout_name(s_.layout) + "\n";
  sc += std::string("  set Coordinates               = ") + (s_.pixels ? "px" : "mm") + "\n";
  if (s_.pixels)
    sc += "  set Pixel size                = " + fmt(s_.pixel_size / mm, 9) + "\n";
  sc += std::string("  set Y axis                    = ") + (s_.y_down ? "down" : "up") + "\n";
  sc += "  set Crack plane y             = " + fmt(crack_y_frame, 9) + "\n";
  sc += "  set Notch root x              = " + fmt(a0_frame, 9) + "\n";
  sc += "  set Growth direction          = +x\n";
  sc += "  set Frame rate                = " + fmt(s_.frame_rate, 9) + "\n";
  sc += "  set First frame time          = " + fmt(s_.first_frame_time, 9) + "\n";
  sc += "  set Strain threshold          = 0.01\n";
  sc += "  set Extensometer gauge length = " + fmt(gauge / mm, 9) + "\n";
  sc += "end\n\nsubsection Test\n  set Files = machine.csv\nend\n";
  out.scene = directory + "/dic_scene.prm";
  write_text(out.scene, sc);
  return out;
}

} // namespace fiberbridge::result
