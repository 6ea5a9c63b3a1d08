// libFuzzer target: the Table 1 reader (analysis/degradation.cc parse_property_table) and the
// ranking chain that `fiberbridge rank` runs on what it read.
#include "fiberbridge/analysis/degradation.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fiberbridge;
  fuzz::expect_success_or_input_error([&] {
    const auto table = analysis::parse_property_table(fuzz::as_text(data, size), "fuzz.csv");
    const auto rows = analysis::analyse_degradation(table);
    (void)analysis::rank_materials(rows);
    (void)analysis::check_row_consistency(table, 0.1, 1.0, &analysis::seed_delta_c_mm);
  });
  return 0;
}
