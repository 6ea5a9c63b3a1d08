#pragma once
// The virtual test (issue 32, item 5; docs/design.md section 2, "Virtual DIC test"): what a DIC
// system and a testing machine would write for a simulated DCB run. A model hands over its
// equilibrium states (load-point opening, load, the crack's truth and the displacements at the
// points of a regular grid in the reference configuration); this writes
//   frames/dcb_0001.<ext> ...   one file per image at the frame rate, in the layout a DIC package
//                               exports (VIC-2D CSV, DICe solution file, GOM/ZEISS nodemap),
//                               displacements with seeded Gaussian noise, strains from a local
//                               least-squares fit over a strain window, as DIC software computes
//                               them (so a window across the crack includes its opening);
//   machine.csv                 the testing machine's record (time_s, load_N, opening_mm) on the
//                               same clock;
//   virtual_test_truth.csv      the model's truth per frame (not in the frames);
//   dic_scene.prm               a scene that reads the frames with the DIC item (issue 32's
//                               Interface keys) and reduces them.
// No deal.II here: the FEM samples its field (source/fem/virtual_dic.h); the layouts and the fit
// are shared with any reader test that needs frames of a known field.
#include "fiberbridge/dic/layouts.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fiberbridge::result {

/// The export layouts: the DIC library's table (dic/layouts.h), those with a writer.
using DicLayout = dic::Layout;
/// A layout with a writer by name; throws InputError naming `key` otherwise.
DicLayout parse_dic_layout(const std::string& text, const std::string& key);
const char* dic_layout_name(DicLayout layout);
/// The frame file's extension with its dot (".csv"; ".txt" for dice, as DICe names its files).
const char* dic_layout_extension(DicLayout layout);
/// "vic|dice|gom|plain": the layouts the virtual test writes, for a Selection pattern.
std::string dic_layout_selection();
/// "vic (VIC-2D/3D CSV), ...": the same with their descriptions, for help texts.
std::string dic_layout_descriptions();

/// The virtual DIC system and testing machine (FEM section, subsection Virtual DIC; SI units).
struct VirtualDicSettings {
  bool enabled = false;
  DicLayout layout = DicLayout::vic;
  double frame_rate = 1;             ///< images per second [Hz] (the paper: 1 Hz)
  double record_rate = 10;           ///< machine record rows per second [Hz]
  double crosshead_rate = 5e-3 / 60; ///< load-point opening rate: the virtual clock [m/s]
  double first_frame_time = 0;       ///< time of the first image on the machine's clock [s]
  /// Field of view in the specimen's coordinates (x from the load line, y from the crack plane)
  /// [m]; an empty range (from >= to) takes the specimen's extent.
  double x_from = 0, x_to = 0, y_from = 0, y_to = 0;
  double spacing = 1e-3;       ///< point spacing (DIC step) [m]
  double noise = 0;            ///< standard deviation of each displacement component [m]
  double strain_window = 5e-3; ///< side of the square window of the strain fit [m]
  bool lagrange = false;       ///< Green-Lagrange strain instead of the infinitesimal one
  bool pixels = false;         ///< frame coordinates and displacements in pixels
  double pixel_size = 0.02e-3; ///< [m/px]; also scales VIC's and DICe's sigma
  bool y_down = false;         ///< frame y axis points down (image convention)
  double failed_fraction = 0;  ///< share of points that fail to correlate in each frame
  std::uint64_t seed = 1;      ///< noise and failures: the same seed, the same files

  /// Throws InputError "<section>/<key>: ..." for values out of range.
  void validate(const std::string& section) const;
};

/// A regular grid of points in the reference configuration: x_i = x0 + i s, y_j = y0 + j s, point
/// k = j nx + i. The rows sit half a spacing off the crack plane (y0 = y_crack + (m + 1/2) s), so
/// that no point lies on the plane where the two crack faces have the same reference position.
struct DicGrid {
  double x0 = 0, y0 = 0, spacing = 0;
  unsigned nx = 0, ny = 0;
  std::size_t size() const { return std::size_t(nx) * ny; }
  double x(std::size_t k) const { return x0 + double(k % nx) * spacing; }
  double y(std::size_t k) const { return y0 + double(k / nx) * spacing; }
};
/// The grid of `s` over its field of view (the specimen's extent [0, length] x [-half_height,
/// half_height] where a range is empty), rows offset by half a spacing from y = 0 (the crack
/// plane). Throws InputError when the field of view holds no point.
DicGrid make_dic_grid(const VirtualDicSettings& s, double length, double half_height);

/// Strains from a least-squares plane through the displacements of the valid points within the
/// square window of side `window` centred on each point (DIC software's strain window: VIC's
/// strain filter, DICe's virtual strain gauge). u, v, valid by grid point. exx = du/dx, eyy =
/// dv/dy, exy = (du/dy + dv/dx)/2, or with `lagrange` E = (H + H^T + H^T H)/2. A point without
/// three non-collinear valid points in its window, or itself not valid, is not ok. Exact for an
/// affine field (the patch test).
struct DicStrains {
  std::vector<double> exx, eyy, exy;
  std::vector<char> ok;
};
DicStrains fit_dic_strains(const DicGrid& grid, const std::vector<double>& u,
                           const std::vector<double>& v, const std::vector<char>& valid,
                           double window, bool lagrange);

/// One image's data in the specimen's frame (m, y up); `valid` false: the point did not
/// correlate. write_dic_frame turns it into the frame's coordinates (mm or px, y up or down).
struct DicFrameData {
  unsigned number = 0; ///< the number in the file name
  double time = 0;     ///< s (GOM metadata only; the reader takes time from the frame rate)
  double load = 0;     ///< N (GOM metadata only, as its "force" signal)
  double opening = 0;  ///< m (GOM metadata only, as its "displacement" signal)
  std::vector<double> u, v;
  DicStrains strains; ///< ok = valid and fitted
};
/// Writes one frame file at `path` in `s.layout` for `grid`.
void write_dic_frame(const std::string& path, const VirtualDicSettings& s, const DicGrid& grid,
                     const DicFrameData& frame);
/// The frame coordinates of the specimen point (x, y) [m] (mm or px; y flipped for y down; px
/// counted from the field of view's corner on the image's top (y down) or bottom (y up) edge).
double frame_x(const VirtualDicSettings& s, const DicGrid& grid, double x);
double frame_y(const VirtualDicSettings& s, const DicGrid& grid, double y);

/// One equilibrium state of the model.
struct VirtualTestState {
  double opening = 0;       ///< load-point opening [m]
  double load = 0;          ///< [N]
  double crack_tip = 0;     ///< traction-free crack tip (the root of the bridging zone) [m]
  double zone_front = 0;    ///< front of the cohesive zone (where the opening leaves zero) [m]
  double delta_root = 0;    ///< opening at the initial notch root [m]
  std::vector<double> u, v; ///< at the grid points [m] (anything where the point is off the body)
};

/// What write() wrote.
struct VirtualTestFiles {
  std::string directory, scene;
  unsigned n_frames = 0, n_points = 0, n_on_body = 0;
  double duration = 0; ///< s, the last state's time on the virtual clock
};

/// Collects the states of one run and writes the virtual test.
class VirtualDicTest {
public:
  /// `on_body`: by grid point, whether it lies on the specimen (off it: never valid).
  VirtualDicTest(const VirtualDicSettings& settings, const DicGrid& grid,
                 std::vector<char> on_body);
  /// States in the order the model reached them; the first is the unloaded one.
  void add_state(VirtualTestState state);
  /// Writes the files into `directory` (created). `scene_sections`: the Specimen (and Material)
  /// sections of the generated scene, as scene text; `initial_crack` [m] places the notch root.
  VirtualTestFiles write(const std::string& directory, const std::string& scene_sections,
                         double initial_crack) const;
  const DicGrid& grid() const { return grid_; }
  const std::vector<char>& on_body() const { return on_body_; }

  /// The virtual clock: the time of each state = its running maximum of the opening over the
  /// crosshead rate. A state whose opening falls below an earlier one (a snap-back) replaces
  /// the state at that earlier time: the machine under opening control jumps there.
  /// Returns (time, state index) pairs, strictly increasing in time.
  std::vector<std::pair<double, std::size_t>> clock() const;

private:
  VirtualDicSettings s_;
  DicGrid grid_;
  std::vector<char> on_body_;
  std::vector<VirtualTestState> states_;
};

} // namespace fiberbridge::result
