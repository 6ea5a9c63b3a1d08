// A simulation result in the archive (result/result_archive.h): what crosses MPI ranks and what
// --resume keeps of a simulation comes back exactly, every field, every double bit for bit.
#include "fiberbridge/core/error.h"
#include "fiberbridge/result/result_archive.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace fiberbridge;

namespace {

result::SimulationResult sample() {
  result::SimulationResult r;
  r.model = "fem";
  for (int i = 0; i < 5; ++i) {
    result::RCurvePoint p;
    p.a = 0.1 + i * 1e-3 / 3.0; // not representable in short decimals
    p.load = i == 2 ? result::not_available : 412.123456789012345 * (1 + i * 1e-15);
    p.R_J = 1.0 / 3.0 + i;
    p.time = -0.0;
    r.rcurve.push_back(p);
  }
  r.G_ss = 1082.4750557029999;
  r.reached_steady_state = true;
  r.steady_state_status = result::SteadyStateStatus::resolved;
  r.wall_time_s = 2.5;
  r.n_dofs_or_particles = 3624;
  r.notes = {"a note, with a comma", std::string("\0\xff", 2)};
  r.method = {"J: domain integral"};
  return r;
}

result::SimulationResult round_trip(const result::SimulationResult& r) {
  return from_archive_bytes<result::SimulationResult>(to_archive_bytes(r, "result"), "result");
}

} // namespace

TEST(ResultArchive, RoundTripIsBitExactWithNaN) {
  const auto r = sample();
  const auto back = round_trip(r);
  ASSERT_EQ(back.rcurve.size(), r.rcurve.size());
  EXPECT_EQ(std::memcmp(back.rcurve.data(), r.rcurve.data(),
                        r.rcurve.size() * sizeof(result::RCurvePoint)),
            0)
      << "every double, NaN included, must come back bit for bit";
  EXPECT_EQ(back.model, "fem");
  EXPECT_EQ(back.G_ss, r.G_ss);
  EXPECT_TRUE(back.reached_steady_state);
  EXPECT_EQ(back.steady_state_status, result::SteadyStateStatus::resolved);
  EXPECT_EQ(back.wall_time_s, 2.5);
  EXPECT_EQ(back.n_dofs_or_particles, 3624);
  EXPECT_TRUE(std::isnan(back.rdelta_rel_error_vs_eq2));
  EXPECT_EQ(back.notes, r.notes);
  EXPECT_EQ(back.method, r.method);
}

TEST(ResultArchive, EmptyResultAndEveryStatusComeBack) {
  const result::SimulationResult empty;
  const auto back = round_trip(empty);
  EXPECT_TRUE(back.model.empty());
  EXPECT_TRUE(back.rcurve.empty());
  EXPECT_TRUE(back.notes.empty());
  EXPECT_TRUE(back.method.empty());
  EXPECT_TRUE(std::isnan(back.G_ss));
  for (const auto s :
       {result::SteadyStateStatus::resolved, result::SteadyStateStatus::not_reached,
        result::SteadyStateStatus::zone_unresolved, result::SteadyStateStatus::ledger_open}) {
    result::SimulationResult r;
    r.steady_state_status = s;
    EXPECT_EQ(round_trip(r).steady_state_status, s) << result::to_string(s);
  }
}

TEST(ResultArchive, AnUnknownStatusIsAClearError) {
  // The status goes by name: bytes naming no status (another version, other code) are refused.
  BinaryWriter out("result", 1);
  out.put(std::string("levitating"));
  BinaryReader in(out.finish(), "result", 1, "r.bin");
  try {
    in.get<result::SteadyStateStatus>();
    ADD_FAILURE() << "an unknown status was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("r.bin: 'levitating'"), std::string::npos) << e.what();
  }
}
