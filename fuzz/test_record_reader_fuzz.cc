// libFuzzer target: the test-record reader (analysis/test_record.h read_test_records) with its
// column map (RecordColumnMap::parse, the scene's Test/Columns). Input: a record file; a first
// line "#columns: MAP" (a comment to the reader, so bundled records are valid inputs) is parsed
// as the column map.
#include "fiberbridge/analysis/test_record.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fiberbridge;
  const std::string text = fuzz::as_text(data, size);
  fuzz::expect_success_or_input_error([&] {
    analysis::RecordReadOptions options;
    const std::string key = "#columns: ";
    if (text.rfind(key, 0) == 0)
      options.columns = analysis::RecordColumnMap::parse(
          text.substr(key.size(), text.find('\n') - key.size()), "fuzz/Columns");
    for (const auto& r : analysis::read_test_records(fuzz::as_file(text, ".csv"), options))
      (void)analysis::crack_reading_rows(r);
  });
  return 0;
}
