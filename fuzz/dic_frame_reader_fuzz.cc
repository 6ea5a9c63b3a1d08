// libFuzzer target: the DIC frame reader (dic/frame.h) in every layout of the table (GOM's native
// CSV with its stage block and units line, DICe's stated coordinates, the duplicate-point check
// included) and with a column map, and what the analysis does with a frame that reads (crack
// coordinates, point spacing, the crack-plane profile, the tip rule and the extensometer). Input: a
// frame file; a first line
// "#columns: MAP" (a comment to the reader, so bundled frames are valid inputs) is parsed as the
// frame column map.
#include "fiberbridge/dic/crack_tip.h"
#include "fiberbridge/dic/extensometer.h"
#include "fiberbridge/dic/frame.h"
#include "fuzz_input.h"

#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fiberbridge;
  const std::string text = fuzz::as_text(data, size);
  // Every layout of the table (dic/layouts.h: GOM's nodemap and native CSV among them) and auto.
  std::vector<dic::Layout> all{dic::Layout::automatic};
  for (const auto* e : dic::layouts())
    all.push_back(e->id);
  for (const auto layout : all)
    for (const bool pixels : {false, true})
      fuzz::expect_success_or_input_error([&] {
        dic::FrameReadOptions o;
        o.layout = layout;
        o.pixel_coordinates = pixels;
        const std::string key = "#columns: ";
        if (text.rfind(key, 0) == 0)
          o.columns = dic::FrameColumnMap::parse(
              text.substr(key.size(), text.find('\n') - key.size()), "fuzz/Columns");
        const dic::RawFrame raw = dic::parse_frame(text, "fuzz", o);
        dic::FrameGeometry g;
        g.pixels = pixels;
        g.pixel_size = 0.05e-3;
        const dic::PlaneFrame f = dic::to_crack_coordinates(raw, g);
        if (f.s.size() > 5000)
          return; // the spacing search is quadratic in small samples; keep each run short
        const double h = dic::point_spacing(f);
        (void)dic::locate_tip(dic::crack_plane_profile(f, h), {}, h);
        (void)dic::read_extensometer(f, 4 * h, h);
      });
  return 0;
}
