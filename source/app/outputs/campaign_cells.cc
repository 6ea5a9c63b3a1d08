// The campaign writers' shared cells and look-ups (campaign_out.h).
#include "outputs/campaign_out.h"

#include "fiberbridge/core/format.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace fiberbridge::app::campaign_out {

std::string cell(double v, int precision) {
  return std::isfinite(v) ? fmt(v, precision) : "";
}

std::string text_cell(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos)
    return s;
  std::string q = "\"";
  for (char c : s) {
    if (c == '\n')
      q += ' ';
    else {
      if (c == '"')
        q += '"';
      q += c;
    }
  }
  return q + "\"";
}

std::string html_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<')
      o += "&lt;";
    else if (c == '>')
      o += "&gt;";
    else if (c == '&')
      o += "&amp;";
    else
      o += c;
  }
  return o;
}

std::string group_stem(const CampaignGroup& g) {
  return analysis::group_file_stem(g.material, g.cycles);
}

double q(const CampaignGroup& g, GroupQuantity k) {
  return analysis::quantity_value(g.estimate, k);
}
const analysis::Interval& ci(const CampaignGroup& g, GroupQuantity k) {
  return g.ci[static_cast<std::size_t>(k)];
}

std::string interval_name(const analysis::CampaignOptions& o) {
  using I = analysis::CampaignOptions::Interval;
  return o.interval == I::student_t             ? "student t with the bootstrap standard deviation"
         : o.interval == I::expanded_percentile ? "expanded percentile bootstrap"
                                                : "percentile bootstrap";
}

Json interval_json(const analysis::Interval& i) {
  return Json::array({json_number(i.lo), json_number(i.hi)});
}

std::vector<double> cycles_of(const CampaignResult& r) {
  std::set<double> c;
  for (const auto& g : r.groups)
    c.insert(g.cycles);
  return {c.begin(), c.end()};
}

std::vector<std::string> materials_of(const CampaignResult& r) {
  std::vector<std::string> m;
  for (const auto& g : r.groups)
    if (std::find(m.begin(), m.end(), g.material) == m.end())
      m.push_back(g.material);
  return m;
}

const CampaignGroup* find_group(const CampaignResult& r, const std::string& m, double c) {
  for (const auto& g : r.groups)
    if (g.material == m && g.cycles == c)
      return &g;
  return nullptr;
}

const analysis::CampaignDegradation* find_degradation(const CampaignResult& r, const std::string& m,
                                                      const std::string& p) {
  for (const auto& d : r.degradation)
    if (d.material == m && d.property == p)
      return &d;
  return nullptr;
}

const std::vector<TableRow>& table_rows() {
  static const std::vector<TableRow> rows{
      {"sigma1", GroupQuantity::sigma1}, {"J1", GroupQuantity::J1},
      {"sigma2", GroupQuantity::sigma2}, {"J2", GroupQuantity::J2},
      {"lb", GroupQuantity::l_b},        {"G_ss", GroupQuantity::G_ss},
      {"J_tip", GroupQuantity::J_tip},   {"delta_c", GroupQuantity::delta_c}};
  return rows;
}

const std::vector<TableRow>& degradation_rows() {
  static const std::vector<TableRow> rows{{"sigma1", GroupQuantity::sigma1},
                                          {"sigma2", GroupQuantity::sigma2},
                                          {"J1", GroupQuantity::J1},
                                          {"J2", GroupQuantity::J2}};
  return rows;
}

} // namespace fiberbridge::app::campaign_out
