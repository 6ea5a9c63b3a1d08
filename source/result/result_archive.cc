#include "fiberbridge/result/result_archive.h"

#include "fiberbridge/core/error.h"

#include <stdexcept>

namespace fiberbridge {

// R-curve rows go as their bytes: only doubles, so every column and its NaN come back as they
// were. A column of another type would need a codec of its own.
static_assert(sizeof(result::RCurvePoint) % sizeof(double) == 0 &&
                  std::is_trivially_copyable_v<result::RCurvePoint>,
              "RCurvePoint holds more than doubles: give it a BinaryCodec (result_archive.h)");

void BinaryCodec<result::SteadyStateStatus>::save(BinaryWriter& out,
                                                  const result::SteadyStateStatus& s) {
  out.put(result::to_string(s));
}

void BinaryCodec<result::SteadyStateStatus>::load(BinaryReader& in, result::SteadyStateStatus& s) {
  const auto name = in.get<std::string>();
  try {
    s = result::steady_state_status_from_string(name);
  } catch (const std::invalid_argument&) {
    throw InputError(in.source() + ": '" + name +
                     "' is not a steady-state status of this version of fiberbridge");
  }
}

// Every field, in declaration order (rcurve.h). A field added there and not here comes back as
// its default from another rank or a resumed run: the size check below is the reminder (it holds
// for libstdc++ on x86-64, the platform of record; elsewhere it is skipped).
#if defined(__GLIBCXX__) && defined(__x86_64__)
static_assert(sizeof(result::SimulationResult) == 144,
              "SimulationResult changed: update its BinaryCodec (result_archive.cc) and this size");
#endif

void BinaryCodec<result::SimulationResult>::save(BinaryWriter& out,
                                                 const result::SimulationResult& r) {
  out.put(r.model);
  out.put(r.rcurve);
  out.put(r.G_ss);
  out.put(r.reached_steady_state);
  out.put(r.steady_state_status);
  out.put(r.wall_time_s);
  out.put(static_cast<std::int64_t>(r.n_dofs_or_particles));
  out.put(r.rdelta_rel_error_vs_eq2);
  out.put(r.notes);
  out.put(r.method);
}

void BinaryCodec<result::SimulationResult>::load(BinaryReader& in, result::SimulationResult& r) {
  in.get(r.model);
  in.get(r.rcurve);
  in.get(r.G_ss);
  in.get(r.reached_steady_state);
  in.get(r.steady_state_status);
  in.get(r.wall_time_s);
  r.n_dofs_or_particles = static_cast<long>(in.get<std::int64_t>());
  in.get(r.rdelta_rel_error_vs_eq2);
  in.get(r.notes);
  in.get(r.method);
}

} // namespace fiberbridge
