// libFuzzer target: the R(delta) data reader (analysis/rdelta_data.cc), then the replicate
// averaging that every extraction runs on what it read.
#include "fiberbridge/analysis/rdelta_data.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fiberbridge;
  fuzz::expect_success_or_input_error([&] {
    const auto d = analysis::read_rdelta_csv(fuzz::as_file(fuzz::as_text(data, size), ".csv"));
    (void)analysis::average_replicates(d, 41);
  });
  return 0;
}
