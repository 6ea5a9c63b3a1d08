// libFuzzer target: the CSV reader (core/csv.cc): CsvTable::parse and every column through
// numeric() and text().
#include "fiberbridge/core/csv.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fiberbridge;
  fuzz::expect_success_or_input_error([&] {
    const CsvTable t = CsvTable::parse(fuzz::as_text(data, size), "fuzz.csv");
    for (const auto& name : t.header()) {
      (void)t.text(name);
      fuzz::expect_success_or_input_error([&] { (void)t.numeric(name); });
    }
    for (std::size_t r = 0; r < t.n_rows(); ++r)
      (void)t.line_of_row(r);
  });
  return 0;
}
