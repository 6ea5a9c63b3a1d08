#pragma once
// One DIC frame: what DIC software exports for one image, read by header name with a preset per
// layout (docs/design.md section 6, "DIC frames in"; the layouts' table in layouts.h):
//  - VIC-2D / VIC-3D CSV (Correlated Solutions): quoted headers such as "x", "y", "u", "v", "exx",
//    "eyy", "exy", "sigma"; x, y, u, v in pixels, X, Y, U, V (VIC-3D, calibrated VIC-2D) in mm;
//    blank lines between areas of interest; sigma < 0 marks a point that did not correlate.
//  - DICe solution files (Sandia): a `***` comment block, then SUBSET_ID, COORDINATE_X/Y,
//    DISPLACEMENT_X/Y, SIGMA, ..., VSG_STRAIN_XX/YY/XY, comma or space delimited, pixels with y
//    down, SIGMA = -1 for a failed subset.
//  - GOM / ZEISS (ARAMIS, Correlate) and nodemap exports: `;` delimited, `#` metadata lines (the
//    nodemap's header is the last `#` line before the data: "ID; x_undef [mm]; y_undef [mm]; ...;
//    epsy [%]; ..."), strains in percent unless a column says [1].
//  - GOM Correlate / ZEISS Inspect native CSV: a `stage;index;relative_time;date` line and one
//    value row above the point table, then the table's header and a units line (";mm;mm;...;%").
//  - plain: our own names x, y, u, v, eyy (and valid, time_s).
// The coordinates are reference (undeformed) positions in every layout: the points are material
// points, which the extensometer relies on. Values stay in the file's units (mm or px) here; the
// frame geometry (geometry.h) converts them. Strains are fractions once read.
#include "fiberbridge/dic/layouts.h"

#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace fiberbridge::dic {

/// Which header of the frames holds each of our columns: x, y (reference coordinates), u, v
/// (displacements), eyy (strain normal to the crack plane), valid (a confidence column: a
/// negative value marks a failed point, as VIC's sigma and DICe's SIGMA do; a column headed
/// `valid` is a flag, 0 or negative failed), time_s (optional).
/// Without an entry the layout's preset names are used.
struct FrameColumnMap {
  std::map<std::string, std::string> file_header; ///< our name -> header in the frames

  /// Parses "eyy: e_yy, valid: sigma" (entries separated by commas, our name before ':').
  /// InputError naming `where` for an unknown name of ours, a repeat or an entry without ':'.
  static FrameColumnMap parse(const std::string& text, const std::string& where);
};

struct FrameReadOptions {
  Layout layout = Layout::automatic;
  FrameColumnMap columns;
  /// The scene's Coordinates = px: VIC's pixel columns (x, y, u, v) are read first; with mm,
  /// VIC's metric X, Y, U, V first. An export with only the other pair is read in the units the
  /// scene states.
  bool pixel_coordinates = false;
};

struct RawFrame {
  std::string source;
  Layout layout = Layout::plain;       ///< as detected (automatic resolved)
  std::vector<double> x, y, u, v, eyy; ///< file units; eyy a fraction; NaN where failed
  std::vector<unsigned char> valid;    ///< 0: failed point (sigma < 0 or a missing value)
  double time = NAN;                   ///< [s] the time column's first value, if any
  std::size_t n_failed = 0;
  std::map<std::string, std::string> used; ///< our name -> the file's header it came from
  double strain_factor = 1; ///< what the strain column was multiplied by (0.01 for %)
  /// The coordinates' unit the file states ("px" or "mm", DICe's `*** Coordinates:` line), empty
  /// when it says nothing; stated_line is that line.
  std::string stated_coordinates;
  std::size_t stated_line = 0;
  /// [s] GOM native CSV: the stage block's relative_time (also `time` without a time column).
  double stage_time = NAN;
};

/// Reads one frame file. InputError naming file:line for: no header, a missing column (with the
/// columns present), a row with another number of cells than the header, a non-number, an
/// infinite value, no data row, a point given twice with different values.
RawFrame read_frame(const std::string& path, const FrameReadOptions& options);
/// The same on text in memory (`source` names it in messages).
RawFrame parse_frame(std::string_view text, const std::string& source,
                     const FrameReadOptions& options);

} // namespace fiberbridge::dic
