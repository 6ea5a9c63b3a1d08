#include "fiberbridge/app/identify_resume.h"

#include "fiberbridge/core/binary_archive.h"

#include <cstdio>

namespace fiberbridge::app {

// Every field must be in the record: a field added to these structs without a line below would
// come back empty from a resumed run. The sizes catch that at compile time (they hold for
// libstdc++ on x86-64, the platform of record; elsewhere the check is skipped).
#if defined(__GLIBCXX__) && defined(__x86_64__)
static_assert(sizeof(identify::RecordFit) == 216 && sizeof(identify::ParameterEstimate) == 48 &&
                  sizeof(identify::Identification) == 312,
              "identify.h changed: update identification_to_record/from_record "
              "(source/app/identify_resume.cc) and these sizes");
#endif

namespace {

template <class T>
Json vec(const std::vector<T>& v) {
  return Json(v);
}

} // namespace

Json identification_to_record(const identify::Identification& id) {
  Json recs = Json::array();
  for (const auto& r : id.records)
    recs.push_back({{"name", r.name},
                    {"initial_crack", r.initial_crack},
                    {"initial_compliance", r.initial_compliance},
                    {"E_L", r.E_L},
                    {"peak_load", r.peak_load},
                    {"load_rms_rel", r.load_rms_rel},
                    {"crack_rms", r.crack_rms},
                    {"max_opening_over_a", r.max_opening_over_a},
                    {"min_F", r.min_F},
                    {"opening", vec(r.opening)},
                    {"load", vec(r.load)},
                    {"crack_length", vec(r.crack_length)},
                    {"model_load", vec(r.model_load)},
                    {"model_crack_length", vec(r.model_crack_length)}});
  Json params = Json::array();
  for (const auto& p : id.parameters)
    params.push_back({{"name", p.name}, {"value", p.value}, {"std_error", p.std_error}});
  return {{"law", {id.law.d1, id.law.s1, id.law.d2, id.law.s2, id.law.dc}},
          {"j_tip", id.j_tip},
          {"g_ss", id.g_ss},
          {"j_c_std_error", id.j_c_std_error},
          {"records", std::move(recs)},
          {"load_rms_rel", id.load_rms_rel},
          {"crack_rms", id.crack_rms},
          {"chi2", id.chi2},
          {"n_residuals", id.n_residuals},
          {"evaluations", id.evaluations},
          {"forward_runs", id.forward_runs},
          {"forward_time_s", id.forward_time_s},
          {"wall_time_s", id.wall_time_s},
          {"parameters", std::move(params)},
          {"correlation", id.correlation},
          {"notes", id.notes},
          {"band_delta", vec(id.band_delta)},
          {"band_sigma", vec(id.band_sigma)},
          {"band_lo", vec(id.band_lo)},
          {"band_hi", vec(id.band_hi)}};
}

identify::Identification identification_from_record(const Json& j) {
  identify::Identification id;
  const auto& l = j.at("law");
  id.law = {l.at(0).get<double>(), l.at(1).get<double>(), l.at(2).get<double>(),
            l.at(3).get<double>(), l.at(4).get<double>()};
  id.j_tip = j.at("j_tip").get<double>();
  id.g_ss = j.at("g_ss").get<double>();
  id.j_c_std_error = j.at("j_c_std_error").get<double>();
  for (const auto& r : j.at("records")) {
    identify::RecordFit f;
    f.name = r.at("name").get<std::string>();
    f.initial_crack = r.at("initial_crack").get<double>();
    f.initial_compliance = r.at("initial_compliance").get<double>();
    f.E_L = r.at("E_L").get<double>();
    f.peak_load = r.at("peak_load").get<double>();
    f.load_rms_rel = r.at("load_rms_rel").get<double>();
    f.crack_rms = r.at("crack_rms").get<double>();
    f.max_opening_over_a = r.at("max_opening_over_a").get<double>();
    f.min_F = r.at("min_F").get<double>();
    f.opening = r.at("opening").get<std::vector<double>>();
    f.load = r.at("load").get<std::vector<double>>();
    f.crack_length = r.at("crack_length").get<std::vector<double>>();
    f.model_load = r.at("model_load").get<std::vector<double>>();
    f.model_crack_length = r.at("model_crack_length").get<std::vector<double>>();
    id.records.push_back(std::move(f));
  }
  id.load_rms_rel = j.at("load_rms_rel").get<double>();
  id.crack_rms = j.at("crack_rms").get<double>();
  id.chi2 = j.at("chi2").get<double>();
  id.n_residuals = j.at("n_residuals").get<std::size_t>();
  id.evaluations = j.at("evaluations").get<int>();
  id.forward_runs = j.at("forward_runs").get<int>();
  id.forward_time_s = j.at("forward_time_s").get<double>();
  id.wall_time_s = j.at("wall_time_s").get<double>();
  for (const auto& p : j.at("parameters"))
    id.parameters.push_back({p.at("name").get<std::string>(), p.at("value").get<double>(),
                             p.at("std_error").get<double>()});
  id.correlation = j.at("correlation").get<std::vector<std::vector<double>>>();
  id.notes = j.at("notes").get<std::vector<std::string>>();
  id.band_delta = j.at("band_delta").get<std::vector<double>>();
  id.band_sigma = j.at("band_sigma").get<std::vector<double>>();
  id.band_lo = j.at("band_lo").get<std::vector<double>>();
  id.band_hi = j.at("band_hi").get<std::vector<double>>();
  return id;
}

Fingerprint identify_inputs(SceneContext& ctx, const std::vector<analysis::TestRecord>& records) {
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
