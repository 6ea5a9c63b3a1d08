// libFuzzer target: the tabulated-law reader (law/piecewise_linear_law.cc read_law_table_csv, the
// scene's Cohesive law/Table file), and the law built from it.
#include "fiberbridge/law/piecewise_linear_law.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fiberbridge;
  fuzz::expect_success_or_input_error([&] {
    const auto law = law::read_law_table_csv(fuzz::as_file(fuzz::as_text(data, size), ".csv"));
    for (double d : {0.0, 0.05e-3, 1e-3, 5.9e-3, 1.0}) {
      (void)law.envelope(d);
      (void)law.envelope_integral(d);
    }
    (void)law.peak();
  });
  return 0;
}
