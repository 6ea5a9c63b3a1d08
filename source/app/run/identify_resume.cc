#include "fiberbridge/app/run/identify_resume.h"

#include "fiberbridge/core/binary_archive.h"

#include <cstdio>

namespace fiberbridge {

// Every field must be in the record: a field added to these structs without a line below would
// come back empty from a resumed run. The sizes catch that at compile time (they hold for
// libstdc++ on x86-64, the platform of record; elsewhere the check is skipped).
#if defined(__GLIBCXX__) && defined(__x86_64__)
static_assert(sizeof(identify::RecordFit) == 216 && sizeof(identify::ParameterEstimate) == 48 &&
                  sizeof(identify::Identification) == 312,
              "identify.h changed: update BinaryCodec<identify::Identification> "
              "(source/app/run/identify_resume.cc) and these sizes");
#endif

namespace {

// A record's fit and a parameter estimate are written only inside an identification: their
// save/load pairs stay here, beside it.
void save_fit(BinaryWriter& out, const identify::RecordFit& f) {
  out.put(f.name);
  out.put(f.initial_crack);
  out.put(f.initial_compliance);
  out.put(f.E_L);
  out.put(f.peak_load);
  out.put(f.load_rms_rel);
  out.put(f.crack_rms);
  out.put(f.max_opening_over_a);
  out.put(f.min_F);
  out.put(f.opening);
  out.put(f.load);
  out.put(f.crack_length);
  out.put(f.model_load);
  out.put(f.model_crack_length);
}

void load_fit(BinaryReader& in, identify::RecordFit& f) {
  in.get(f.name);
  in.get(f.initial_crack);
  in.get(f.initial_compliance);
  in.get(f.E_L);
  in.get(f.peak_load);
  in.get(f.load_rms_rel);
  in.get(f.crack_rms);
  in.get(f.max_opening_over_a);
  in.get(f.min_F);
  in.get(f.opening);
  in.get(f.load);
  in.get(f.crack_length);
  in.get(f.model_load);
  in.get(f.model_crack_length);
}

} // namespace

void BinaryCodec<identify::Identification>::save(BinaryWriter& out,
                                                 const identify::Identification& id) {
  out.put(id.law); // five doubles (law::TrilinearParameters), as their bytes
  out.put(id.j_tip);
  out.put(id.g_ss);
  out.put(id.j_c_std_error);
  out.put(static_cast<std::uint64_t>(id.records.size()));
  for (const auto& r : id.records)
    save_fit(out, r);
  out.put(id.load_rms_rel);
  out.put(id.crack_rms);
  out.put(id.chi2);
  out.put(static_cast<std::uint64_t>(id.n_residuals));
  out.put(static_cast<std::int32_t>(id.evaluations));
  out.put(static_cast<std::int32_t>(id.forward_runs));
  out.put(id.forward_time_s);
  out.put(id.wall_time_s);
  out.put(static_cast<std::uint64_t>(id.parameters.size()));
  for (const auto& p : id.parameters) {
    out.put(p.name);
    out.put(p.value);
    out.put(p.std_error);
  }
  out.put(id.correlation);
  out.put(id.notes);
  out.put(id.band_delta);
  out.put(id.band_sigma);
  out.put(id.band_lo);
  out.put(id.band_hi);
}

void BinaryCodec<identify::Identification>::load(BinaryReader& in, identify::Identification& id) {
  in.get(id.law);
  in.get(id.j_tip);
  in.get(id.g_ss);
  in.get(id.j_c_std_error);
  // A fit takes at least its name's length and eight numbers: a count beyond the file is
  // caught by the first read past its end.
  id.records.resize(0);
  for (auto n = in.get<std::uint64_t>(); n > 0; --n)
    load_fit(in, id.records.emplace_back());
  in.get(id.load_rms_rel);
  in.get(id.crack_rms);
  in.get(id.chi2);
  id.n_residuals = static_cast<std::size_t>(in.get<std::uint64_t>());
  id.evaluations = in.get<std::int32_t>();
  id.forward_runs = in.get<std::int32_t>();
  in.get(id.forward_time_s);
  in.get(id.wall_time_s);
  id.parameters.resize(0);
  for (auto n = in.get<std::uint64_t>(); n > 0; --n) {
    auto& p = id.parameters.emplace_back();
    in.get(p.name);
    in.get(p.value);
    in.get(p.std_error);
  }
  in.get(id.correlation);
  in.get(id.notes);
  in.get(id.band_delta);
  in.get(id.band_sigma);
  in.get(id.band_lo);
  in.get(id.band_hi);
}

} // namespace fiberbridge

namespace fiberbridge::app {

Fingerprint identify_inputs(const SceneContext& ctx,
                            const std::vector<analysis::TestRecord>& records) {
  Fingerprint fp = scene_fingerprint(ctx.parameters());
  for (std::size_t k = 0; k < records.size(); ++k) {
    const auto& r = records[k];
    std::uint64_t h = 0;
    for (const auto* v : {&r.time, &r.opening, &r.load, &r.crack_length, &r.delta_root}) {
      const std::uint64_t part = checksum64(v->data(), v->size() * sizeof(double));
      h = h * 1099511628211ULL ^ part ^ v->size();
    }
    char b[24];
    std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
    fp.emplace_back("Test record " + std::to_string(k + 1),
                    r.name + ", " + std::to_string(r.opening.size()) + " rows, hash " + b);
  }
  return fp;
}

} // namespace fiberbridge::app
