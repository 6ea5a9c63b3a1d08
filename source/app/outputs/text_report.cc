// report.txt: the key numbers of a run in a few lines a person reads first (also printed).
#include "fiberbridge/app/outputs/text_report.h"
#include "fiberbridge/app/scene/models.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/summary.h"

#include <sstream>

namespace fiberbridge::app {

namespace {

std::string num(const Json& j, const char* key, int precision = 4) {
  if (!j.contains(key) || !j[key].is_number())
    return "n/a";
  return fmt(j[key].get<double>(), precision); // %g: the stream's default notation
}

/// Per record: plateau by each method, MBT |Delta| and what the reader cleaned.
std::string reduce_report(const Json& b) {
  std::ostringstream r;
  auto plateaus = [](const Json& j) {
    std::string p;
    for (const char* m : {"energy", "MBT", "CC", "MCC"})
      p += std::string(p.empty() ? "" : ", ") + m + " " + num(j[m], "plateau_J_m2");
    return p;
  };
  for (const auto& rec : b["records"]) {
    r << "reduce " << rec["name"].get<std::string>() << ": plateau R " << plateaus(rec)
      << " J/m^2; MBT |Delta| " << num(rec, "MBT_Delta_mm", 3) << " mm, window "
      << num(rec, "smoothing_window_mm", 3) << " mm\n";
    for (const auto& c : rec["cleaning"])
      r << "  cleaned: " << c.get<std::string>() << "\n";
  }
  r << "reduce mean of " << b["mean"]["n_records"].get<int>() << ": plateau R "
    << plateaus(b["mean"]) << " J/m^2\n";
  return r.str();
}

} // namespace

std::string text_report(const Json& s) {
  std::ostringstream r;
  r << "fiberbridge report: " << (s.contains("scene") ? s["scene"].get<std::string>() : "") << "\n";
  if (s.contains("dic")) // the DIC frames reduce read (dic_step.h)
    r << "dic: " << s["dic"]["frames_used"].get<int>() << " of "
      << s["dic"]["frames_read"].get<int>() << " frames used, final a "
      << num(s["dic"], "final_a_mm") << " mm, delta_root " << num(s["dic"], "final_delta_root_mm")
      << " mm, " << s["dic"]["frame_notes"].size() << " frame note(s)\n";
  if (s.contains("reduce"))
    r << reduce_report(s["reduce"]);
  if (s.contains("G_ss_J_m2")) {
    r << "extraction: J_tip " << num(s, "J_tip_J_m2") << " J/m^2, G_ss " << num(s, "G_ss_J_m2")
      << " J/m^2, delta_c " << num(s, "delta_c_mm") << " mm\n";
    r << "  peak bridging stress: Eq. 5/6 " << num(s, "peak_sigma_eq5_kPa") << " kPa, dR/ddelta "
      << num(s, "peak_sigma_dRdd_kPa") << " kPa\n";
  }
  if (s.contains("trilinear")) {
    const auto& t = s["trilinear"];
    r << "trilinear fit: sigma1 " << num(t, "sigma1_kPa") << " kPa at " << num(t, "delta1_mm")
      << " mm, sigma2 " << num(t, "sigma2_kPa") << " kPa at " << num(t, "delta2_mm") << " mm, J1 "
      << num(t, "J1_J_m2") << ", J2 " << num(t, "J2_J_m2") << " J/m^2 (rms residual "
      << num(t, "rms_residual_kPa", 3) << " kPa)\n";
  }
  if (s.contains("fit_correction")) {
    const auto& c = s["fit_correction"];
    if (c.value("converged", false)) {
      const auto& t = c["corrected"];
      r << "fit corrected by simulation (" << c["simulations"].get<int>() << " simulations, "
        << c["forward_runs"].get<int>() << " " << c.value("forward_model", "beam")
        << " runs): sigma1 " << num(t, "sigma1_kPa") << " kPa, sigma2 " << num(t, "sigma2_kPa")
        << " kPa, delta_c " << num(t, "delta_c_mm") << " mm, J_tip " << num(t, "J_tip_J_m2")
        << " J/m^2 (the law handed on; fit_correction.csv)\n";
    } else {
      // The correction's last note is its reason, worded "not corrected: why".
      std::string why = c["notes"].empty() ? std::string("see summary.json")
                                           : c["notes"].back().get<std::string>();
      const std::string lead = "not corrected: ";
      if (why.rfind(lead, 0) == 0)
        why = why.substr(lead.size());
      r << "fit not corrected: " << why << " (the seed's fit is handed on)\n";
    }
  }
  if (s.contains("ranking")) {
    r << "durability ranking (most durable first):";
    for (const auto& m : s["ranking"])
      r << " " << m.get<std::string>();
    r << "\n";
    if (s.contains("rank"))
      for (const auto& c : s["rank"]["consistency"])
        r << "  table check: " << c["material"].get<std::string>() << " at " << c["cycles"]
          << " cycles: " << c["message"].get<std::string>() << "\n";
  }
  if (s.contains("bridging"))
    r << "bridged fibers: " << num(s["bridging"], "rho_b_eq15_peeling_per_mm2", 3)
      << " /mm^2 (Eq. 15, peeling), " << num(s["bridging"], "rho_b_exact_governing_per_mm2", 3)
      << " /mm^2 (exact Eq. 11, " << s["bridging"]["governing_mechanism"].get<std::string>()
      << " governs)\n";
  for (const SimulationModel* sim : built_models()) {
    const std::string model = sim->name;
    if (!s.contains(model))
      continue;
    const auto& m = s[model];
    r << model << ": G_ss " << num(m, "G_ss_J_m2") << " J/m^2 (law: " << num(m, "G_ss_law_J_m2")
      << "), steady state " << (m["reached_steady_state"].get<bool>() ? "reached" : "NOT reached")
      << ", R_J vs Eq. 2 " << num(m, "rdelta_rel_error_vs_eq2", 2) << ", peak load "
      << num(m, "peak_load_N") << " N, " << num(m, "wall_time_s", 3) << " s\n";
    if (m.contains("notes") && !m["notes"].empty())
      r << "  " << m["notes"][0].get<std::string>() << "\n";
  }
  if (s.contains("compare") && s["compare"].contains("closed_loop")) {
    r << "closed loop (law recovered from simulated R(delta_root); L2 error, peak vs true):\n";
    for (const auto& c : s["compare"]["closed_loop"]) {
      if (!c.contains("method")) {
        r << "  " << c["model"].get<std::string>() << ": " << c["diagnosis"].get<std::string>()
          << "\n";
        continue;
      }
      r << "  " << c["model"].get<std::string>() << " " << c["R_source"].get<std::string>()
        << " -> " << c["method"].get<std::string>() << ": " << num(c, "curve_rel_l2", 2) << ", "
        << num(c, "peak_kPa") << " vs " << num(c, "peak_true_kPa") << " kPa\n";
    }
  }
  if (s.contains("wall_time_s"))
    r << "wall time " << num(s, "wall_time_s", 3) << " s\n";
  return r.str();
}

} // namespace fiberbridge::app
