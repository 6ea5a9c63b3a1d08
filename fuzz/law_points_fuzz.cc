// libFuzzer target: the law `Points` parser (law/law_spec.cc, the scene's Cohesive law/Points and
// the --points option), then the law factory for every type that takes points, and the law built.
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/law_spec.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fiberbridge;
  fuzz::expect_success_or_input_error([&] {
    law::LawSpec spec;
    spec.points = law::parse_points_mm_kPa(fuzz::as_text(data, size), "Cohesive law/Points");
    spec.delta_c = 6 * units::mm;
    for (const char* type : {"bilinear", "trilinear", "table"}) {
      spec.type = type;
      fuzz::expect_success_or_input_error([&] {
        const auto law = law::make_law(spec);
        for (double d : {0.0, 0.05e-3, 1e-3, 5.9e-3, 1.0}) {
          (void)law->envelope(d);
          (void)law->envelope_integral(d);
        }
        (void)law->peak();
      });
    }
  });
  return 0;
}
