// campaign_report.html.
#include "outputs/campaign_out.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/plot.h"

#include <cmath>

namespace fiberbridge::app::campaign_out {

namespace {

std::string html_table(const std::vector<std::string>& head,
                       const std::vector<std::vector<std::string>>& rows) {
  std::string s = "<table><tr>";
  for (const auto& h : head)
    s += "<th>" + html_escape(h) + "</th>";
  s += "</tr>\n";
  for (const auto& r : rows) {
    s += "<tr>";
    for (const auto& c : r)
      s += "<td>" + c + "</td>";
    s += "</tr>\n";
  }
  return s + "</table>\n";
}

std::string with_interval(double v, const analysis::Interval& i, int precision = 3) {
  if (!std::isfinite(v))
    return "";
  std::string s = fmt(v, precision);
  if (std::isfinite(i.lo) && std::isfinite(i.hi))
    s += " <span class=ci>[" + fmt(i.lo, precision) + ", " + fmt(i.hi, precision) + "]</span>";
  return s;
}

} // namespace

void write_html(const CampaignResult& r, const CampaignWriteOptions& w,
                const std::vector<std::string>& pngs, const std::vector<std::string>& files,
                const std::string& dir) {
  const std::string level = fmt(100 * r.options.confidence) + " %";
  std::string h = "<!DOCTYPE html>\n<html><head><meta charset='utf-8'><title>fiberbridge "
                  "campaign</title>\n<style>body{font-family:sans-serif;max-width:1200px;margin:"
                  "auto}table{border-collapse:collapse;margin:8px 0}td,th{border:1px solid #bbb;"
                  "padding:2px 6px;text-align:right}th{background:#eee}.ci{color:#666;font-size:"
                  "85%}img{max-width:100%}li{margin:2px 0}</style></head><body>\n";
  h += "<h1>Durability campaign</h1>\n<p>Manifest <code>" + html_escape(r.manifest.source) +
       "</code>: " + std::to_string(r.specimens.size()) + " specimens in " +
       std::to_string(r.groups.size()) + " groups. Intervals: " + level +
       " bootstrap over whole "
       "specimens within each group (" +
       std::to_string(r.options.bootstrap_samples) + " samples, seed " +
       std::to_string(r.options.seed) + ", " + interval_name(r.options) +
       "); groups of records with delta_root add the chain's accuracy in quadrature (G_ss " +
       fmt(100 * r.options.chain_u_G_ss) + " %, J_tip " + fmt(100 * r.options.chain_u_J_tip) +
       " %, standard; summary.json's ci_chain_accuracy_half_width). Analysis " + fmt(w.seconds, 3) +
       " s.</p>\n";
  // Table 1
  const auto cycles = cycles_of(r);
  std::vector<std::string> head{"material", "property"};
  for (double c : cycles)
    head.push_back(fmt(c) + " cycles");
  head.insert(head.end(), {"slope/cycle [interval]", "R^2", "p", "paper's rule"});
  std::vector<std::vector<std::string>> rows;
  for (const auto& mat : materials_of(r))
    for (const auto& tr : table_rows()) {
      std::vector<std::string> row{html_escape(mat), tr.property};
      bool any = false;
      for (double c : cycles) {
        const auto* g = find_group(r, mat, c);
        const double v = g ? q(*g, tr.quantity) : NAN;
        any = any || std::isfinite(v);
        row.push_back(g ? with_interval(v, ci(*g, tr.quantity)) : "");
      }
      if (!any)
        continue;
      const auto* d = find_degradation(r, mat, tr.property);
      if (d && d->has_slope) {
        row.push_back(with_interval(d->paper.fit.slope, d->slope_ci));
        row.push_back(fmt(d->paper.fit.r2, 2));
        row.push_back(cell(d->p_value, 2));
        row.push_back(d->paper.significant ? "<b>degrades</b>" : "-");
      } else
        row.insert(row.end(), {"", "", "", d ? html_escape(d->note) : ""});
      rows.push_back(row);
    }
  h += "<h2>Table 1 (group values [" + level + " interval])</h2>\n" + html_table(head, rows);
  // Ranking
  h += "<h2>Ranking (the paper's rule) and its confidence</h2>\n<p>";
  for (std::size_t i = 0; i < r.ranking.ranks.size(); ++i)
    h += (i ? " &gt; " : "") + html_escape(r.ranking.ranks[i].material) + " (" +
         std::to_string(r.ranking.ranks[i].rank) + ")";
  if (!r.ranking.reference.empty()) {
    h += "; reported beside, not ranked: ";
    for (const auto& m : r.ranking.reference)
      h += html_escape(m) + " ";
  }
  h += "</p>\n";
  rows.clear();
  for (const auto& p : r.ranking.pairs)
    rows.push_back({html_escape(p.first) + " ahead of " + html_escape(p.second),
                    cell(p.p_first_ahead, 3), cell(p.p_tie, 3), cell(p.p_second_ahead, 3)});
  h += html_table({"order", "holds", "tie", "reversed"}, rows) + "<p>Fractions of " +
       std::to_string(r.ranking.samples) + " bootstrap samples.</p>\n";
  if (!w.simulations.empty()) {
    rows.clear();
    for (const auto& s : w.simulations)
      rows.push_back({html_escape(s.material), fmt(s.cycles), s.model,
                      s.ran ? cell(s.misfit_rel, 3) : html_escape(s.failure),
                      cell(s.within_scatter, 3), cell(s.G_ss, 4), cell(s.wall_time_s, 3)});
    h += "<h2>The laws back in the specimen (Fig. 10)</h2>\n" +
         html_table({"material", "cycles", "model", "misfit (RMS / G_B)",
                     "within 2 std of the specimens", "simulated G_ss (J/m^2)", "time (s)"},
                    rows);
  }
  // Plots
  h += "<h2>Plots</h2>\n";
  for (const auto& p : pngs)
    h += "<p><img src='" + p + "' alt='" + p + "'></p>\n";
  if (pngs.empty())
    h += "<p>No plots (gnuplot not found): the CSV files hold the numbers.</p>\n";
  // Notes
  std::vector<std::string> notes = r.notes;
  for (const auto& n : r.ranking.notes)
    notes.push_back(n);
  for (const auto& g : r.groups)
    for (const auto& n : g.notes)
      notes.push_back(n);
  h += "<h2>Notes</h2>\n<ul>\n";
  for (const auto& n : notes)
    h += "<li>" + html_escape(n) + "</li>\n";
  if (notes.empty())
    h += "<li>none</li>\n";
  h += "</ul>\n<h2>Files</h2>\n<ul>\n";
  for (const auto& f : files)
    h += "<li><a href='" + f + "'>" + f + "</a></li>\n";
  h += "</ul>\n</body></html>\n";
  write_file_atomically(dir + "/campaign_report.html", h);
}

} // namespace fiberbridge::app::campaign_out
