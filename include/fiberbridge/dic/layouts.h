#pragma once
// The DIC frame layouts, named once (issue 40 item 4): what each DIC package writes, as one entry
// per layout that the frame reader (frame_reader.cc), the virtual DIC writer
// (result/virtual_dic.cc) and the sections and options that name a layout
// (app/scene/dic_section.cc, fem/virtual_dic_parameters.cc, app/cli/commands.cc) share.
//
// Adding a layout: its entry in source/dic/layout_<name>.cc (names, description, extension,
// the reader's preset headers, the writer) and its name in FIBERBRIDGE_DIC_LAYOUTS below.
#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace fiberbridge::dic {

/// The registration list: one X(name) per layout, in the order help texts list them.
#define FIBERBRIDGE_DIC_LAYOUTS(X) X(vic) X(dice) X(gom) X(plain)

/// automatic: detect from the file (the reader only).
enum class Layout {
  automatic,
#define FIBERBRIDGE_DIC_LAYOUT_ENUM(name) name,
  FIBERBRIDGE_DIC_LAYOUTS(FIBERBRIDGE_DIC_LAYOUT_ENUM)
#undef FIBERBRIDGE_DIC_LAYOUT_ENUM
};

/// Our frame columns, in the reader's order: reference coordinates, displacements, the strain
/// normal to the crack plane, a confidence column, a time.
enum FrameColumn { col_x, col_y, col_u, col_v, col_eyy, col_valid, col_time, n_frame_columns };

/// What a virtual frame's file states about it (its header and metadata).
struct FrameFileHeader {
  unsigned number = 0;   ///< image number
  double time = 0;       ///< s
  double load = 0;       ///< N (metadata where the layout carries signals)
  double opening_mm = 0; ///< mm (ditto)
  bool pixels = false;   ///< coordinates and displacements in px, else mm
  bool y_down = false;   ///< the image's y axis points down
  double strain_window_mm = 0;
};

/// One point as a layout writes it, in the file's units; strains as fractions.
struct FramePoint {
  std::size_t index = 0; ///< 0-based point number
  double x = 0, y = 0, u = 0, v = 0, exx = 0, eyy = 0, exy = 0;
  double sigma = 0; ///< the correlation's confidence (px); ignored where failed
  bool ok = true;   ///< false: the point did not correlate
};

/// What the reader knows of a file when it meets the header line: for detection.
struct HeaderFacts {
  const std::vector<std::string>& header; ///< cells, unquoted
  char delimiter;
  bool dice_banner;   ///< a "***" comment block above
  bool quoted_header; ///< a header cell in double quotes
};

struct LayoutEntry {
  Layout id;
  const char* name;        ///< as scenes and options spell it
  const char* description; ///< one clause for help texts
  const char* extension;   ///< the frame file's, with its dot
  bool mm_only;            ///< the package writes millimetres only (no px)
  /// Preset headers for our column `col`, in order of preference; `pixels`: the scene states
  /// px (VIC writes both pairs). Empty: the layout has no such column.
  std::vector<std::string> (*preset)(int col, bool pixels);
  bool by_stem; ///< headers match by their name before a "[unit]" (GOM's "epsy [%]")
  /// How surely a header is this layout's (0: not; the highest wins; plain's 0 is the fallback).
  int (*detect)(const HeaderFacts& facts);
  /// Strains in percent when the strain column states no unit.
  bool percent_strains;
  /// Writes the file's header lines and one point's line (empty for no writer).
  void (*write_header)(std::string& out, const FrameFileHeader& h);
  void (*write_point)(std::string& out, const FramePoint& p);
};

/// Every layout, in registration order.
const std::vector<const LayoutEntry*>& layouts();
/// The entry of `layout` (not automatic).
const LayoutEntry& layout_entry(Layout layout);
/// The entry spelled `name`, nullptr for none.
const LayoutEntry* find_layout(std::string_view name);
/// The names joined by `sep` ("vic|dice|gom|plain"), those with a writer only if `writable`.
std::string layout_names(const char* sep, bool writable = false);
/// "vic (...), dice (...), ..." for help texts.
std::string layout_descriptions(bool writable = false);

/// "auto" or a layout's name; InputError naming `where` otherwise.
Layout parse_layout(const std::string& text, const std::string& where);
/// A layout with a writer, InputError naming `where` otherwise.
Layout parse_written_layout(const std::string& text, const std::string& where);
const char* layout_name(Layout layout);

/// Appends `values` with `sep` between them and a line end (9 significant digits, shortest form:
/// a frame has ~10^4 such lines).
void append_values(std::string& out, std::initializer_list<double> values, const char* sep);
/// %.9g
std::string number_text(double v);

/// Each layout's entry, defined in its own file (source/dic/layout_<name>.cc).
#define FIBERBRIDGE_DIC_LAYOUT_DECLARE(name) const LayoutEntry& name##_layout();
FIBERBRIDGE_DIC_LAYOUTS(FIBERBRIDGE_DIC_LAYOUT_DECLARE)
#undef FIBERBRIDGE_DIC_LAYOUT_DECLARE

} // namespace fiberbridge::dic
