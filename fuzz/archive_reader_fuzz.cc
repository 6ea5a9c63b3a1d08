// libFuzzer target: the archive reader (core/binary_archive.h) behind --resume records and MPI
// task bytes. The input is the body of an archive: a valid header and checksum are put around it
// (a fuzzer could not forge the checksum, and a file whose checksum fails never reaches the
// typed reads), then it is read as a resume record of a simulation item (a unit name, the
// inputs, JSON blocks, a SimulationResult) and, from the start again, as identify-like lists.
#include "fiberbridge/core/binary_archive.h"
#include "fiberbridge/core/json_archive.h"
#include "fiberbridge/result/result_archive.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fiberbridge;
  BinaryWriter header("fuzz record", 1);
  std::string bytes = header.finish();
  bytes.resize(bytes.size() - sizeof(std::uint64_t)); // the header without its checksum
  bytes += fuzz::as_text(data, size);
  const std::uint64_t h = checksum64(bytes.data(), bytes.size());
  bytes.append(reinterpret_cast<const char*>(&h), sizeof h);
  fuzz::expect_success_or_input_error([&] {
    BinaryReader in(bytes, "fuzz record", 1, "fuzz.rec");
    (void)in.get<std::string>();
    (void)in.get<std::vector<std::pair<std::string, std::string>>>();
    (void)in.get<Json>();
    (void)in.get<result::SimulationResult>();
    in.expect_end();
  });
  fuzz::expect_success_or_input_error([&] {
    BinaryReader in(bytes, "fuzz record", 1, "fuzz.rec");
    (void)in.get<std::vector<std::vector<double>>>();
    (void)in.get<bool>();
    (void)in.get<std::deque<std::pair<double, std::string>>>();
    (void)in.get<result::SteadyStateStatus>();
  });
  return 0;
}
