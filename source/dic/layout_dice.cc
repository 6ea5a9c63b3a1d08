// DICe solution files (Sandia): a `***` comment block (which states the coordinates), then
// SUBSET_ID, COORDINATE_X/Y, DISPLACEMENT_X/Y, SIGMA, ..., VSG_STRAIN_XX/YY/XY, comma or space
// delimited, pixels with y down, SIGMA = -1 for a failed subset.
#include "fiberbridge/dic/layouts.h"

#include <algorithm>

namespace fiberbridge::dic {

namespace {

std::vector<std::string> preset(int col, bool) {
  switch (col) {
  case col_x:
    return {"COORDINATE_X"};
  case col_y:
    return {"COORDINATE_Y"};
  case col_u:
    return {"DISPLACEMENT_X"};
  case col_v:
    return {"DISPLACEMENT_Y"};
  case col_eyy:
    return {"VSG_STRAIN_YY"};
  case col_valid:
    return {"SIGMA"};
  default:
    return {};
  }
}

int detect(const HeaderFacts& f) {
  const bool named = std::find(f.header.begin(), f.header.end(), "COORDINATE_X") != f.header.end();
  return f.dice_banner || named ? 3 : 0;
}

void header(std::string& t, const FrameFileHeader& h) {
  t += "***\n*** Digital Image Correlation Engine (DICe) solution file layout, written by the "
       "fiberbridge virtual test\n*** (FEM displacements at the subset centroids plus noise, "
       "not image correlation)\n***\n*** Reference image: frame 0 (undeformed)\n"
       "*** Deformed image: frame " +
       std::to_string(h.number) + " (t = " + number_text(h.time) +
       " s)\n*** Coordinates: " + (h.pixels ? "px" : "mm") + (h.y_down ? ", y down" : ", y up") +
       "\n*** Strain: virtual strain gauge, window " + number_text(h.strain_window_mm) +
       " mm\n***\n";
  t += "SUBSET_ID,COORDINATE_X,COORDINATE_Y,DISPLACEMENT_X,DISPLACEMENT_Y,SIGMA,VSG_STRAIN_XX,"
       "VSG_STRAIN_YY,VSG_STRAIN_XY\n";
}

void point(std::string& t, const FramePoint& p) {
  t += std::to_string(p.index) + ",";
  if (!p.ok)
    append_values(t, {p.x, p.y, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0}, ",");
  else
    append_values(t, {p.x, p.y, p.u, p.v, p.sigma, p.exx, p.eyy, p.exy}, ",");
}

} // namespace

const LayoutEntry& dice_layout() {
  static const LayoutEntry e{
      Layout::dice, "dice", "DICe solution files", ".txt", false, preset, false, detect, false,
      header,       point};
  return e;
}

} // namespace fiberbridge::dic
