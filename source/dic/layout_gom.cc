// GOM / ZEISS (ARAMIS, Correlate, Inspect): `;` delimited, strains in percent unless a column
// says [1]. Read: the nodemap export (`#` metadata, the header the last `#` line before the data:
// "ID; x_undef [mm]; y_undef [mm]; ...; epsy [%]; ...") and the native CSV (a
// `stage;index;relative_time;date` block above the point table and a units line under its
// header). Written: the nodemap, failed facets absent, millimetres only.
#include "fiberbridge/dic/layouts.h"

#include <cmath>

namespace fiberbridge::dic {

namespace {

std::vector<std::string> preset(int col, bool) {
  switch (col) {
  case col_x:
    return {"x_undef", "x", "x0"};
  case col_y:
    return {"y_undef", "y", "y0"};
  case col_u:
    return {"u", "dx", "disp_x", "displacement_x"};
  case col_v:
    return {"v", "dy", "disp_y", "displacement_y"};
  case col_eyy:
    return {"epsy", "eps_y", "epsilon_y", "eps_yy", "epsilon_yy", "eyy"};
  default:
    return {};
  }
}

int detect(const HeaderFacts& f) {
  return f.delimiter == ';' ? 2 : 0;
}

void header(std::string& t, const FrameFileHeader& h) {
  const std::string bar(100, '#');
  t += "# Process data:\n# software                      : fiberbridge virtual test (GOM/ZEISS "
       "nodemap layout)\n# stage                         : " +
       std::to_string(h.number) + "\n# time [s]                      : " + number_text(h.time) +
       "\n" + bar + "\n# SIGNALS:\n# force [N]                     : value_element       : " +
       number_text(h.load) +
       "\n# displacement [mm]             : value_element       : " + number_text(h.opening_mm) +
       "\n" + bar + "\n";
  t += "#        ID; x_undef [mm]; y_undef [mm]; z_undef [mm]; u [mm]; v [mm]; w [mm]; epsx [%]; "
       "epsy [%]; epsxy [1]; epseqv [%]\n";
}

void point(std::string& t, const FramePoint& p) {
  if (!p.ok) // a facet that did not correlate is not in the nodemap
    return;
  // Von Mises equivalent of an in-plane, volume-preserving strain state.
  const double eqv =
      2 / std::sqrt(3.0) * std::sqrt(p.exx * p.exx + p.eyy * p.eyy + p.exx * p.eyy + p.exy * p.exy);
  t += std::to_string(p.index + 1) + "; ";
  append_values(t, {p.x, p.y, 0.0, p.u, p.v, 0.0, 100 * p.exx, 100 * p.eyy, p.exy, 100 * eqv},
                "; ");
}

} // namespace

const LayoutEntry& gom_layout() {
  static const LayoutEntry e{Layout::gom, "gom",  "GOM/ZEISS nodemap and native CSV, strains in %",
                             ".csv",      true,   preset,
                             true,        detect, true,
                             header,      point};
  return e;
}

} // namespace fiberbridge::dic
