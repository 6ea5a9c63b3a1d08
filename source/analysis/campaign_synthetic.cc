// A synthetic campaign with a known answer (campaign_synthetic.h).
#include "fiberbridge/analysis/campaign_synthetic.h"

#include "fiberbridge/analysis/synthetic_data.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

namespace fiberbridge::analysis {

using units::kPa;
using units::mm;

std::vector<SyntheticGroupTruth> table1_truth(const PropertyTable& table, double j_tip) {
  std::vector<SyntheticGroupTruth> out;
  for (const auto& r : table.rows) {
    if (r.property != "sigma1")
      continue;
    const PropertyRow* s2 = table.find(r.material, "sigma2");
    if (!s2)
      throw InputError(table.source + ": " + r.material + " has sigma1 but no sigma2 row");
    for (std::size_t c = 0; c < table.cycles.size(); ++c) {
      if (!std::isfinite(r.values[c]) || !std::isfinite(s2->values[c]))
        continue;
      SyntheticGroupTruth t;
      t.material = r.material;
      t.cycles = table.cycles[c];
      t.law = {0.1 * mm, r.values[c] * kPa, 1.0 * mm, s2->values[c] * kPa,
               seed_delta_c_mm(r.material) * mm};
      t.j_tip = j_tip;
      out.push_back(t);
    }
  }
  return out;
}

std::string write_synthetic_campaign(const std::string& dir,
                                     const std::vector<SyntheticGroupTruth>& truth,
                                     const SyntheticCampaignOptions& o) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (!std::filesystem::is_directory(dir))
    throw InputError(dir + ": cannot create the campaign's folder");
  std::mt19937 rng(o.seed);
  std::normal_distribution<double> normal;
  auto factor = [&] { return 1 + o.stress_cv * std::clamp(normal(rng), -2.5, 2.5); };
  std::vector<std::string> header{"file", "material", "specimen", "cycles"};
  if (o.write_delta_c)
    header.push_back("delta_c_mm");
  CsvWriter m(dir + "/manifest.csv", header,
              {"Synthetic campaign (not measured): made by fiberbridge's make_synthetic_rdelta "
               "(fiberbridge synth) from known trilinear laws; see README.md beside this file.",
               "specimen scatter: sigma1, sigma2 times 1 + " + fmt(o.stress_cv) +
                   " z (z standard normal clipped to +-2.5), J_tip 2 %, R noise " +
                   fmt(o.noise_J_m2) + " J/m^2, seed " + std::to_string(o.seed)});
  for (const auto& t : truth)
    for (int k = 1; k <= o.replicates; ++k) {
      law::TrilinearParameters p = t.law;
      p.s1 *= factor();
      p.s2 *= factor();
      const unsigned seed = static_cast<unsigned>(rng());
      const auto law = law::make_trilinear(p);
      const double dmax = o.delta_max_over_dc * p.dc;
      auto data = make_synthetic_rdelta(law, t.j_tip, 1, o.rows, o.noise_J_m2, dmax, seed);
      const std::string name = t.material + "_c" + fmt(t.cycles) + "_s" + std::to_string(k);
      auto lines = describe_synthetic_rdelta(law, t.j_tip, 1, o.rows, o.noise_J_m2, dmax, seed);
      lines.insert(lines.begin(), "specimen " + std::to_string(k) + " of " + t.material + " at " +
                                      fmt(t.cycles) + " cycles; group law sigma1 " +
                                      fmt(t.law.s1 / kPa) + " kPa, sigma2 " + fmt(t.law.s2 / kPa) +
                                      " kPa scattered to " + fmt(p.s1 / kPa) + ", " +
                                      fmt(p.s2 / kPa) + " kPa");
      write_rdelta_csv(dir + "/" + name + ".csv", data, lines);
      std::vector<double> v{t.cycles};
      if (o.write_delta_c)
        v.push_back(t.law.dc / mm);
      m.row({name + ".csv", t.material, "s" + std::to_string(k)}, v);
    }
  m.close();
  return dir + "/manifest.csv";
}

} // namespace fiberbridge::analysis
