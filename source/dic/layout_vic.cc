// VIC-2D / VIC-3D CSV (Correlated Solutions): quoted headers "x", "y", "u", "v", "exx", "eyy",
// "exy", "sigma"; x, y, u, v in pixels, X, Y, U, V (VIC-3D, calibrated VIC-2D) in mm; blank lines
// between areas of interest; sigma < 0 marks a point that did not correlate.
#include "fiberbridge/dic/layouts.h"

#include <algorithm>

namespace fiberbridge::dic {

namespace {

std::vector<std::string> preset(int col, bool pixels) {
  // VIC writes image columns x, y, u, v (pixels) and, when calibrated, metric X, Y, U, V: the
  // pair the scene's Coordinates names comes first, the other is taken as stated.
  const auto pair = [&](const char* px, const char* mm) {
    return pixels ? std::vector<std::string>{px, mm} : std::vector<std::string>{mm, px};
  };
  switch (col) {
  case col_x:
    return pair("x", "X");
  case col_y:
    return pair("y", "Y");
  case col_u:
    return pair("u", "U");
  case col_v:
    return pair("v", "V");
  case col_eyy:
    return {"eyy"};
  case col_valid:
    return {"sigma"};
  default:
    return {};
  }
}

int detect(const HeaderFacts& f) {
  const bool sigma = std::find(f.header.begin(), f.header.end(), "sigma") != f.header.end();
  return sigma || f.quoted_header ? 1 : 0;
}

void header(std::string& t, const FrameFileHeader&) {
  t += "\"x\", \"y\", \"u\", \"v\", \"exx\", \"eyy\", \"exy\", \"sigma\"\n";
}

void point(std::string& t, const FramePoint& p) {
  // A point that did not correlate: zeros and sigma = -1, as VIC writes it.
  if (!p.ok)
    append_values(t, {p.x, p.y, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0}, ", ");
  else
    append_values(t, {p.x, p.y, p.u, p.v, p.exx, p.eyy, p.exy, p.sigma}, ", ");
}

} // namespace

const LayoutEntry& vic_layout() {
  static const LayoutEntry e{Layout::vic, "vic",  "VIC-2D/3D CSV", ".csv", false, preset,
                             false,       detect, false,           header, point};
  return e;
}

} // namespace fiberbridge::dic
