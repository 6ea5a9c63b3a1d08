// libFuzzer target: the test-record reader (analysis/test_record.h read_test_records) with its
// column map (RecordColumnMap::parse, the scene's Test/Columns), over every layout the reader
// detects (core/exported_table.h: delimiters, decimal comma, preamble, units rows, quotes,
// thousands separators, text encodings and code pages, data blocks and stacked specimens,
// damaged files) and every cleaning step. Input: a record file; a first line
// "#columns: MAP" (a comment to the reader, so bundled records are valid inputs) is parsed as
// the column map. The seed corpus (scripts/fuzz.sh) holds the shared records and one file per
// layout and per fault class (tests/analysis/data/record_layout_*.csv).
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/core/exported_table.h"
#include "fuzz_input.h"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fiberbridge;
  const std::string text = fuzz::as_text(data, size);
  fuzz::expect_success_or_input_error([&] {
    analysis::RecordReadOptions options;
    const std::string key = "#columns: ";
    if (text.rfind(key, 0) == 0) {
      std::string map = text.substr(key.size(), text.find('\n') - key.size());
      if (!map.empty() && map.back() == '\r')
        map.pop_back();
      options.columns = analysis::RecordColumnMap::parse(map, "fuzz/Columns");
    }
    // The three crack-length sources, chosen by the input's length (deterministic per input).
    options.crack_length = static_cast<analysis::CrackLengthSource>(size % 3);
    // Mostly detected encodings (UTF-8, UTF-16 with or without BOM, the code pages scored with
    // iconv); some inputs forced through a given one, as Test/Encoding does.
    static const char* const encodings[] = {"", "", "", "", "CP1250", "CP932", "UTF-16LE"};
    options.encoding = encodings[(size / 3) % 7];
    for (const auto& r : analysis::read_test_records(fuzz::as_file(text, ".csv"), options)) {
      const auto rows = analysis::crack_reading_rows(r);
      // The hand-over contract (test_record.h): one crack entry per row or none; readings are
      // rows with a finite, strictly increasing crack length; openings and loads finite.
      if (!r.crack_length.empty() && r.crack_length.size() != r.opening.size())
        __builtin_trap();
      for (std::size_t k = 0; k < rows.size(); ++k)
        if (!std::isfinite(r.crack_length[rows[k]]) ||
            (k && !(r.crack_length[rows[k]] > r.crack_length[rows[k - 1]])))
          __builtin_trap();
      for (std::size_t i = 0; i < r.opening.size(); ++i)
        if (!std::isfinite(r.opening[i]) || !std::isfinite(r.load[i]) || r.opening[i] < 0)
          __builtin_trap();
    }
  });
  return 0;
}
