// Degradation and ranking of a campaign with their bootstrap confidence (campaign_statistics.h).
#include "fiberbridge/analysis/campaign_statistics.h"

#include "fiberbridge/core/error.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace fiberbridge::analysis {

double sample_quantile(std::vector<double> v, double q) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty())
    return NAN;
  std::sort(v.begin(), v.end());
  const double h = q * (v.size() - 1);
  const std::size_t lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (h - lo) * (v[hi] - v[lo]);
}

namespace {

GroupQuantity quantity_of_property(const std::string& p) {
  if (p == "sigma1")
    return GroupQuantity::sigma1;
  if (p == "J1")
    return GroupQuantity::J1;
  if (p == "sigma2")
    return GroupQuantity::sigma2;
  if (p == "J2")
    return GroupQuantity::J2;
  return GroupQuantity::l_b;
}

double group_value(const CampaignGroup& g, GroupQuantity q, int sample) {
  if (sample >= 0 && g.has_interval())
    return g.samples.at(static_cast<std::size_t>(sample))[static_cast<std::size_t>(q)];
  return quantity_value(g.estimate, q);
}

std::vector<double> sorted_cycles(const std::vector<CampaignGroup>& groups) {
  std::set<double> c;
  for (const auto& g : groups)
    c.insert(g.cycles);
  return {c.begin(), c.end()};
}

/// Materials in order of first appearance.
std::vector<std::string> materials_of(const std::vector<CampaignGroup>& groups) {
  std::vector<std::string> m;
  for (const auto& g : groups)
    if (std::find(m.begin(), m.end(), g.material) == m.end())
      m.push_back(g.material);
  return m;
}

int n_cycle_counts(const std::vector<CampaignGroup>& groups, const std::string& material) {
  std::set<double> c;
  for (const auto& g : groups)
    if (g.material == material)
      c.insert(g.cycles);
  return static_cast<int>(c.size());
}

int n_samples(const std::vector<CampaignGroup>& groups) {
  int n = 0;
  for (const auto& g : groups)
    n = std::max(n, static_cast<int>(g.samples.size()));
  return n;
}

/// Rows of the table with at least 3 finite values (what a slope needs).
PropertyTable with_regressable_rows(PropertyTable t) {
  std::vector<PropertyRow> keep;
  for (auto& r : t.rows) {
    int n = 0;
    for (double v : r.values)
      n += std::isfinite(v) ? 1 : 0;
    if (n >= 3)
      keep.push_back(std::move(r));
  }
  t.rows = std::move(keep);
  return t;
}

} // namespace

const std::vector<std::string>& campaign_table_properties() {
  static const std::vector<std::string> p{"sigma1", "J1", "sigma2", "J2", "lb"};
  return p;
}

PropertyTable campaign_property_table(const std::vector<CampaignGroup>& groups, int sample,
                                      const std::vector<std::string>& materials) {
  PropertyTable t;
  t.source = sample < 0 ? "campaign (group point estimates)"
                        : "campaign (bootstrap sample " + std::to_string(sample) + ")";
  t.cycles = sorted_cycles(groups);
  for (const auto& mat : materials_of(groups)) {
    if (!materials.empty() && std::find(materials.begin(), materials.end(), mat) == materials.end())
      continue;
    for (const auto& prop : campaign_table_properties()) {
      PropertyRow r;
      r.material = mat;
      r.property = prop;
      r.values.assign(t.cycles.size(), NAN);
      r.half_units.assign(t.cycles.size(), NAN);
      r.cells.assign(t.cycles.size(), "");
      bool any = false;
      for (const auto& g : groups)
        if (g.material == mat) {
          const std::size_t c = static_cast<std::size_t>(
              std::find(t.cycles.begin(), t.cycles.end(), g.cycles) - t.cycles.begin());
          r.values[c] = group_value(g, quantity_of_property(prop), sample);
          any = any || std::isfinite(r.values[c]);
        }
      if (any)
        t.rows.push_back(std::move(r));
    }
  }
  return t;
}

std::vector<CampaignDegradation> campaign_degradation(const std::vector<CampaignGroup>& groups,
                                                      double confidence) {
  std::vector<CampaignDegradation> out;
  const PropertyTable point = campaign_property_table(groups, -1);
  const int ns = n_samples(groups);
  // Per bootstrap sample, the slopes of every row that has one (one joint draw: sample b of
  // every group; the groups' resamples are independent, so this is a draw of the campaign).
  std::map<std::pair<std::string, std::string>, std::vector<double>> slopes;
  for (int b = 0; b < ns; ++b) {
    const auto t = with_regressable_rows(campaign_property_table(groups, b));
    if (t.rows.empty())
      continue;
    for (const auto& r : analyse_degradation(t))
      slopes[{r.material, r.property}].push_back(r.fit.slope);
  }
  const auto paper_rows = [&] {
    const auto t = with_regressable_rows(point);
    return t.rows.empty() ? std::vector<DegradationRow>{} : analyse_degradation(t);
  }();
  for (const auto& r : point.rows) {
    CampaignDegradation d;
    d.material = r.material;
    d.property = r.property;
    for (std::size_t c = 0; c < point.cycles.size(); ++c)
      if (std::isfinite(r.values[c])) {
        d.cycles.push_back(point.cycles[c]);
        d.values.push_back(r.values[c]);
      }
    const int n_cycles = n_cycle_counts(groups, r.material);
    const auto it = std::find_if(paper_rows.begin(), paper_rows.end(), [&](const auto& p) {
      return p.material == r.material && p.property == r.property;
    });
    if (it == paper_rows.end()) {
      d.note = n_cycles < 3 ? r.material + " has " + std::to_string(n_cycles) +
                                  " cycle count(s): a degradation slope needs at least 3"
                            : "fewer than 3 cycle counts with a value: no slope";
      out.push_back(d);
      continue;
    }
    d.has_slope = true;
    d.paper = *it;
    const auto& s = slopes[{r.material, r.property}];
    d.samples_used = static_cast<int>(s.size());
    if (s.empty()) {
      d.note = "no bootstrap (groups of one specimen or bootstrap off): no interval";
    } else {
      const double alpha = 0.5 * (1 - confidence);
      d.slope_ci = {sample_quantile(s, alpha), sample_quantile(s, 1 - alpha)};
      // Two-sided bootstrap p of "no trend": twice the smaller tail beyond 0, at least
      // 1/(samples + 1) (the resolution of the bootstrap).
      double below = 0, above = 0;
      for (double x : s) {
        below += x <= 0 ? 1 : 0;
        above += x >= 0 ? 1 : 0;
      }
      const double n = static_cast<double>(s.size());
      d.p_value = std::min(1.0, std::max(2 * std::min(below, above) / n, 1 / (n + 1)));
    }
    out.push_back(d);
  }
  return out;
}

CampaignRanking campaign_ranking(const std::vector<CampaignGroup>& groups,
                                 const std::vector<std::string>& reference_materials) {
  CampaignRanking k;
  std::vector<std::string> ranked;
  for (const auto& m : materials_of(groups)) {
    if (std::find(reference_materials.begin(), reference_materials.end(), m) !=
        reference_materials.end()) {
      k.reference.push_back(m);
      continue;
    }
    if (n_cycle_counts(groups, m) < 3) {
      k.not_ranked.push_back(m);
      k.notes.push_back(m + ": fewer than 3 cycle counts, no slope: not ranked");
      continue;
    }
    ranked.push_back(m);
  }
  if (ranked.empty()) {
    k.notes.push_back("no material to rank (each needs at least 3 cycle counts)");
    return k;
  }
  auto rank_of = [&](int sample) {
    const auto t = with_regressable_rows(campaign_property_table(groups, sample, ranked));
    std::map<std::string, int> r;
    if (t.rows.empty())
      return r;
    for (const auto& m : rank_materials(analyse_degradation(t)))
      r[m.material] = m.rank;
    return r;
  };
  {
    const auto t = with_regressable_rows(campaign_property_table(groups, -1, ranked));
    if (!t.rows.empty())
      k.ranks = rank_materials(analyse_degradation(t));
  }
  const int ns = n_samples(groups);
  std::map<std::pair<std::string, std::string>, std::array<int, 3>> counts;
  for (int b = 0; b < ns; ++b) {
    const auto r = rank_of(b);
    if (r.size() != k.ranks.size())
      continue; // a material without a slope in this sample: the order is not defined
    ++k.samples;
    for (std::size_t i = 0; i < k.ranks.size(); ++i)
      for (std::size_t j = i + 1; j < k.ranks.size(); ++j) {
        const int a = r.at(k.ranks[i].material), c = r.at(k.ranks[j].material);
        auto& n = counts[{k.ranks[i].material, k.ranks[j].material}];
        ++n[a < c ? 0 : (a == c ? 1 : 2)];
      }
  }
  for (std::size_t i = 0; i < k.ranks.size(); ++i)
    for (std::size_t j = i + 1; j < k.ranks.size(); ++j) {
      PairConfidence p;
      p.first = k.ranks[i].material;
      p.second = k.ranks[j].material;
      if (k.samples > 0) {
        const auto& n = counts[{p.first, p.second}];
        p.p_first_ahead = static_cast<double>(n[0]) / k.samples;
        p.p_tie = static_cast<double>(n[1]) / k.samples;
        p.p_second_ahead = static_cast<double>(n[2]) / k.samples;
      }
      k.pairs.push_back(p);
    }
  if (ns > 0 && k.samples < ns)
    k.notes.push_back(std::to_string(ns - k.samples) + " of " + std::to_string(ns) +
                      " bootstrap samples left a ranked material without a slope: left out of "
                      "the ranking confidence");
  return k;
}

} // namespace fiberbridge::analysis
