// plain: our own column names x, y, u, v, eyy (and valid, time_s), comma separated; the layout
// of a file nobody's software wrote, and the reader's fallback.
#include "fiberbridge/dic/layouts.h"

namespace fiberbridge::dic {

namespace {

std::vector<std::string> preset(int col, bool) {
  static const char* const names[] = {"x", "y", "u", "v", "eyy", "valid", "time_s"};
  return {names[col]};
}

int detect(const HeaderFacts&) {
  return 0;
}

void header(std::string& t, const FrameFileHeader&) {
  t += "x,y,u,v,eyy,valid\n";
}

void point(std::string& t, const FramePoint& p) {
  if (!p.ok)
    append_values(t, {p.x, p.y, 0.0, 0.0, 0.0, 0.0}, ",");
  else
    append_values(t, {p.x, p.y, p.u, p.v, p.eyy, 1.0}, ",");
}

} // namespace

const LayoutEntry& plain_layout() {
  static const LayoutEntry e{
      Layout::plain, "plain", "x, y, u, v, eyy, valid", ".csv", false, preset, false, detect, false,
      header,        point};
  return e;
}

} // namespace fiberbridge::dic
