// The campaign's outputs (campaign_writers.h): tables, law files, plots, the HTML report and the
// summary block, all from a finished CampaignResult. Every file goes through the atomic core
// writers (a killed run leaves no half-written table; rank > 0 writes nothing).
#include "fiberbridge/app/campaign_writers.h"
#include "fiberbridge/analysis/line_fit.h"

#include "fiberbridge/analysis/cohesive_export.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

namespace fiberbridge::app {

using analysis::CampaignGroup;
using analysis::CampaignResult;
using analysis::GroupQuantity;
using units::kPa;
using units::mm;

namespace {

std::string cell(double v, int precision = 4) {
  return std::isfinite(v) ? fmt(v, precision) : "";
}

/// A text cell: quoted when it holds a comma or a quote (core/csv.h reads such cells back).
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

/// Table 1 rows: property name as in seed_table1.csv and the quantity behind it.
struct TableRow {
  const char* property;
  GroupQuantity quantity;
};
const std::vector<TableRow>& table_rows() {
  static const std::vector<TableRow> rows{
      {"sigma1", GroupQuantity::sigma1}, {"J1", GroupQuantity::J1},
      {"sigma2", GroupQuantity::sigma2}, {"J2", GroupQuantity::J2},
      {"lb", GroupQuantity::l_b},        {"G_ss", GroupQuantity::G_ss},
      {"J_tip", GroupQuantity::J_tip},   {"delta_c", GroupQuantity::delta_c}};
  return rows;
}

/// campaign_table1.csv (with intervals) and campaign_table1_values.csv (seed format, for rank).
void write_table1(const CampaignResult& r, const std::string& dir) {
  const auto cycles = cycles_of(r);
  std::string head = "material,property", values_head = "material,property";
  for (double c : cycles) {
    head += ",c" + fmt(c);
    values_head += ",c" + fmt(c);
  }
  head += ",slope,r2";
  values_head += ",slope,r2";
  for (double c : cycles)
    head += ",c" + fmt(c) + "_lo,c" + fmt(c) + "_hi";
  head += ",slope_lo,slope_hi,slope_p,significant_paper_rule";
  const std::string level = fmt(100 * r.options.confidence) + " %";
  std::string text = "# Table 1 of the campaign " + r.manifest.source +
                     " (format of data/reference/seed_table1.csv), group point estimates.\n"
                     "# Units: sigma in kPa, J in J/m^2, lb and delta_c in mm, rho_b in 1/mm^2 "
                     "(low-high range), G_ss and J_tip in J/m^2.\n"
                     "# <c>_lo, <c>_hi: " +
                     level + " bootstrap interval over whole specimens (" +
                     std::to_string(r.options.bootstrap_samples) + " samples, seed " +
                     std::to_string(r.options.seed) +
                     "); empty for a group of one specimen. slope, r2: least squares on the "
                     "group values (the paper's rule: significant when slope < 0 and r2 >= 0.8); "
                     "slope_lo, slope_hi, slope_p: the bootstrap's interval and two-sided p.\n" +
                     head + "\n";
  std::string values = "# Table 1 of the campaign " + r.manifest.source +
                       ", group point estimates only (the format `fiberbridge rank` reads); "
                       "intervals in campaign_table1.csv.\n" +
                       values_head + "\n";
  for (const auto& mat : materials_of(r)) {
    for (const auto& row : table_rows()) {
      std::string line = text_cell(mat) + "," + row.property;
      std::string lohi;
      int n_values = 0;
      for (double c : cycles) {
        const auto* g = find_group(r, mat, c);
        const double v = g ? q(*g, row.quantity) : NAN;
        n_values += std::isfinite(v) ? 1 : 0;
        line += "," + cell(v);
        lohi += "," + (g ? cell(ci(*g, row.quantity).lo) : "") + "," +
                (g ? cell(ci(*g, row.quantity).hi) : "");
      }
      if (n_values == 0)
        continue;
      const auto* d = find_degradation(r, mat, row.property);
      const bool slope = d && d->has_slope;
      const std::string stats =
          slope ? "," + cell(d->paper.fit.slope) + "," + cell(d->paper.fit.r2, 3) : ",,";
      text += line + stats + lohi + "," + (slope ? cell(d->slope_ci.lo) : "") + "," +
              (slope ? cell(d->slope_ci.hi) : "") + "," + (slope ? cell(d->p_value, 3) : "") + "," +
              (slope ? (d->paper.significant ? "1" : "0") : "") + "\n";
      const bool seed_property =
          std::string(row.property) == "sigma1" || std::string(row.property) == "J1" ||
          std::string(row.property) == "sigma2" || std::string(row.property) == "J2" ||
          std::string(row.property) == "lb";
      if (seed_property && n_values >= 2)
        values += line + stats + "\n";
    }
    // rho_b as the seed prints it: a low-high range per cycle count; the interval columns hold
    // the lower end of the low's interval and the upper end of the high's.
    std::string line = text_cell(mat) + ",rho_b", lohi;
    bool any = false;
    for (double c : cycles) {
      const auto* g = find_group(r, mat, c);
      const double lo = g ? q(*g, GroupQuantity::rho_low) : NAN;
      const double hi = g ? q(*g, GroupQuantity::rho_high) : NAN;
      const bool ok = std::isfinite(lo) && std::isfinite(hi);
      any = any || ok;
      line += "," + (ok ? fmt(lo, 3) + "-" + fmt(hi, 3) : "");
      lohi += "," + (g ? cell(ci(*g, GroupQuantity::rho_low).lo, 3) : "") + "," +
              (g ? cell(ci(*g, GroupQuantity::rho_high).hi, 3) : "");
    }
    if (any) {
      text += line + ",," + lohi + ",,,,\n";
      values += line + ",,\n";
    }
  }
  write_file_atomically(dir + "/campaign_table1.csv", text);
  write_file_atomically(dir + "/campaign_table1_values.csv", values);
}

void write_groups_table(const CampaignResult& r, const std::string& dir) {
  std::string text = "# One row per group (material, cycles): the point estimate and its bootstrap "
                     "interval for every quantity; units in the column names.\n"
                     "material,cycles,n_specimens,seed,bootstrap_samples,failed_samples";
  for (std::size_t k = 0; k < analysis::n_group_quantities; ++k) {
    const std::string key = analysis::quantity_key(static_cast<GroupQuantity>(k));
    text += "," + key + "," + key + "_lo," + key + "_hi";
  }
  text += ",rms_residual_kPa,notes\n";
  for (const auto& g : r.groups) {
    text += text_cell(g.material) + "," + fmt(g.cycles) + "," + std::to_string(g.members.size()) +
            "," + std::to_string(g.seed) + "," + std::to_string(g.samples.size()) + "," +
            std::to_string(g.failed_samples);
    for (std::size_t k = 0; k < analysis::n_group_quantities; ++k) {
      const auto kk = static_cast<GroupQuantity>(k);
      text += "," + cell(q(g, kk), 6) + "," + cell(ci(g, kk).lo, 6) + "," + cell(ci(g, kk).hi, 6);
    }
    std::string notes;
    for (const auto& n : g.notes)
      notes += (notes.empty() ? "" : "; ") + n;
    text += "," + cell(g.estimate.rms_residual / kPa) + "," + text_cell(notes) + "\n";
  }
  write_file_atomically(dir + "/campaign_groups.csv", text);
}

/// The estimator, every estimator's initiation and plateau and the direct-energy band of the
/// plateau of an R(a)-only specimen (empty cells for an R(delta) specimen), each followed by a
/// comma.
std::string ra_methods_cells(const CampaignResult& r, const analysis::CampaignSpecimen& s) {
  const bool ra_only = s.input != analysis::SpecimenInput::rdelta && !s.has_rdelta;
  std::string text = std::string(ra_only ? analysis::to_string(r.estimator) : "") + ",";
  for (const auto& m : s.methods)
    text += (ra_only ? cell(m.initiation) : "") + "," + (ra_only ? cell(m.plateau) : "") + ",";
  return text + (ra_only ? cell(s.plateau_band) : "") + ",";
}

void write_specimens_table(const CampaignResult& r, const std::string& dir) {
  std::string text = "# One row per manifest row: the specimen on its own (its notes say why it "
                     "is named; no specimen is dropped from its group).\n"
                     "manifest_line,file,material,cycles,specimen,input,rows,delta_max_mm,"
                     "J_tip_J_m2,G_ss_J_m2,delta_c_mm,steady_state,l_b_mm,initiation_J_m2,"
                     "plateau_J_m2,estimator,initiation_energy_J_m2,plateau_energy_J_m2,"
                     "initiation_MBT_J_m2,plateau_MBT_J_m2,initiation_CC_J_m2,plateau_CC_J_m2,"
                     "initiation_MCC_J_m2,plateau_MCC_J_m2,initiation_CBBM_J_m2,"
                     "plateau_CBBM_J_m2,energy_plateau_band_J_m2,notes\n";
  std::map<std::size_t, std::vector<std::string>> group_notes;
  for (const auto& g : r.groups)
    for (auto m : g.members)
      for (const auto& n : g.notes)
        if (n.find("'" + r.specimens[m].row.specimen + "' (" + r.specimens[m].row.where()) !=
            std::string::npos)
          group_notes[m].push_back(n);
  for (std::size_t i = 0; i < r.specimens.size(); ++i) {
    const auto& s = r.specimens[i];
    std::string notes;
    for (const auto& n : group_notes[i])
      notes += (notes.empty() ? "" : "; ") + n;
    text += std::to_string(s.row.line) + "," + text_cell(s.row.file_as_written) + "," +
            text_cell(s.row.material) + "," + fmt(s.row.cycles) + "," + text_cell(s.row.specimen) +
            "," + (s.input == analysis::SpecimenInput::rdelta ? "rdelta" : "raw_record") + "," +
            std::to_string(s.curve.delta.size()) + "," +
            (s.curve.delta.empty() ? "" : cell(s.curve.delta.back() / mm)) + "," +
            (s.steady ? cell(s.own.j_tip) : "") + "," + (s.steady ? cell(s.own.G_ss) : "") + "," +
            (s.steady ? cell(s.own.delta_c / mm) : "") + "," + (s.steady ? "1" : "0") + "," +
            cell(s.l_b / mm) + "," + cell(s.initiation) + "," + cell(s.plateau) + "," +
            ra_methods_cells(r, s) + text_cell(notes) + "\n";
  }
  write_file_atomically(dir + "/campaign_specimens.csv", text);
}

void write_statistics_tables(const CampaignResult& r, const std::string& dir) {
  std::string text =
      "# Degradation against moisture cycles per material and property: least squares on the "
      "group values (the paper's rule) beside the bootstrap over specimens.\n"
      "material,property,n_cycle_counts,slope_per_cycle,intercept,r2,significant_paper_rule,"
      "normalized_rate_per_cycle,slope_lo,slope_hi,p_value,bootstrap_samples,note\n";
  for (const auto& d : r.degradation)
    text += text_cell(d.material) + "," + d.property + "," + std::to_string(d.cycles.size()) + "," +
            (d.has_slope ? cell(d.paper.fit.slope, 6) : "") + "," +
            (d.has_slope ? cell(d.paper.fit.intercept, 6) : "") + "," +
            (d.has_slope ? cell(d.paper.fit.r2, 4) : "") + "," +
            (d.has_slope ? (d.paper.significant ? "1" : "0") : "") + "," +
            (d.has_slope ? cell(d.paper.normalized_rate, 4) : "") + "," + cell(d.slope_ci.lo, 6) +
            "," + cell(d.slope_ci.hi, 6) + "," + cell(d.p_value, 3) + "," +
            std::to_string(d.samples_used) + "," + text_cell(d.note) + "\n";
  write_file_atomically(dir + "/campaign_degradation.csv", text);
  text = "# Durability ranking by the paper's rule (sum of significant normalized degradation "
         "rates of sigma1, J1, sigma2, J2; most durable first); reference materials beside.\n"
         "material,rank,degradation_score_per_cycle,significant_properties\n";
  for (const auto& m : r.ranking.ranks) {
    std::string props;
    for (const auto& p : m.significant_properties)
      props += (props.empty() ? "" : " ") + p;
    text += text_cell(m.material) + "," + std::to_string(m.rank) + "," +
            cell(m.degradation_score, 4) + "," + props + "\n";
  }
  for (const auto& m : r.ranking.reference)
    text += text_cell(m) + ",reference,,\n";
  for (const auto& m : r.ranking.not_ranked)
    text += text_cell(m) + ",not ranked,,\n";
  write_file_atomically(dir + "/campaign_ranking.csv", text);
  text = "# How often each pairwise order of the ranking holds over the bootstrap samples (" +
         std::to_string(r.ranking.samples) +
         " samples); first = ahead in the point ranking.\n"
         "first,second,p_first_ahead,p_tie,p_second_ahead\n";
  for (const auto& p : r.ranking.pairs)
    text += text_cell(p.first) + "," + text_cell(p.second) + "," + cell(p.p_first_ahead, 3) + "," +
            cell(p.p_tie, 3) + "," + cell(p.p_second_ahead, 3) + "\n";
  write_file_atomically(dir + "/campaign_ranking_confidence.csv", text);
}

/// Per group with a law: its law CSV (Eq. 6, dR/ddelta, trilinear, band) and the FE cards.
std::vector<std::string> write_group_laws(const CampaignResult& r, bool fe_export,
                                          const std::string& dir) {
  std::vector<std::string> files;
  int id = 0;
  for (const auto& g : r.groups) {
    ++id;
    if (!g.estimate.ok || !g.estimate.has_law)
      continue;
    const auto& e = g.estimate;
    const std::string stem = "campaign_law_" + group_stem(g);
    std::vector<double> grid = g.law_delta;
    if (grid.empty())
      grid = e.laws.delta;
    const auto tri = law::make_trilinear(e.tri);
    CsvWriter w(dir + "/" + stem + ".csv",
                {"delta_mm", "sigma_eq6_kPa", "sigma_dRdd_kPa", "sigma_trilinear_kPa",
                 "band_lo_kPa", "band_hi_kPa"},
                {g.material + " after " + fmt(g.cycles) + " cycles, " +
                 std::to_string(g.members.size()) +
                 " specimens: law by seed Eq. 6 beside sigma = dR/ddelta, the trilinear fit, and "
                 "the bootstrap band of the Eq. 6 law (" +
                 fmt(100 * r.options.confidence) + " %; empty without bootstrap)"});
    for (std::size_t i = 0; i < grid.size(); ++i) {
      const double d = grid[i];
      w.row({d / mm, analysis::interpolate_within(e.laws.delta, e.laws.sigma_eq6, d) / kPa,
             analysis::interpolate_within(e.laws.delta, e.laws.sigma_dRdd, d) / kPa,
             tri.envelope(d) / kPa, g.law_lo.empty() ? NAN : g.law_lo[i] / kPa,
             g.law_hi.empty() ? NAN : g.law_hi[i] / kPa});
    }
    w.close();
    files.push_back(stem + ".csv");
    if (!fe_export)
      continue;
    const auto poly =
        analysis::trilinear_polyline(e.tri.d1, e.tri.s1, e.tri.d2, e.tri.s2, e.tri.dc);
    const std::string title = g.material + " after " + fmt(g.cycles) + " cycles (trilinear fit)";
    try {
      write_file_atomically(dir + "/" + stem + "_lsdyna_mat186.k",
                            "*KEYWORD\n" +
                                analysis::lsdyna_mat_cohesive_general(poly, id, 1000 + id, title) +
                                "*END\n");
      files.push_back(stem + "_lsdyna_mat186.k");
      write_file_atomically(dir + "/" + stem + "_abaqus.inp",
                            analysis::abaqus_cohesive_material(poly, file_name_part(g.material) +
                                                                         "_C" + fmt(g.cycles)));
      files.push_back(stem + "_abaqus.inp");
    } catch (const std::exception&) {
      // A fitted law the codes cannot take (a zero first stress): the CSV says the law; the
      // group's notes are already written. Not worth failing the campaign over.
    }
  }
  return files;
}

std::vector<std::string> write_plots(const CampaignResult& r, const std::string& dir) {
  std::vector<std::string> pngs;
  const std::string level = fmt(100 * r.options.confidence) + " %";
  auto law_plot = [&](const std::string& png, const std::string& title,
                      const std::vector<const CampaignGroup*>& groups, bool label_material) {
    std::string s = gnuplot_png_preamble(png, 1000, 620);
    s += "set title '" + title +
         "'\nset xlabel 'opening delta (mm)'\nset ylabel 'sigma (kPa)'\n"
         "set key top right\nset style fill transparent solid 0.2 noborder\nplot ";
    int k = 0;
    for (const auto* g : groups) {
      const std::string csv = "campaign_law_" + group_stem(*g) + ".csv";
      const std::string name = label_material ? g->material : fmt(g->cycles) + " cycles";
      const std::string lc = " lc " + std::to_string(k + 1);
      if (k)
        s += ", ";
      if (g->has_interval())
        s += "'" + csv + "' using 1:5:6 with filledcurves" + lc + " notitle, ";
      s += "'" + csv + "' using 1:2 with lines lw 2" + lc + " title '" + name + "'";
      ++k;
    }
    s += "\n";
    if (k && run_gnuplot(dir, s))
      pngs.push_back(png);
  };
  for (const auto& mat : materials_of(r)) {
    std::vector<const CampaignGroup*> gs;
    for (const auto& g : r.groups)
      if (g.material == mat && g.estimate.ok && g.estimate.has_law)
        gs.push_back(&g);
    law_plot("campaign_laws_" + file_name_part(mat) + ".png",
             mat + ": laws by Eq. 6 after each cycle count, " + level + " bootstrap bands", gs,
             false);
  }
  {
    std::vector<const CampaignGroup*> gs;
    for (const auto& mat : materials_of(r)) {
      const CampaignGroup* first = nullptr;
      for (const auto& g : r.groups)
        if (g.material == mat && g.estimate.ok && g.estimate.has_law &&
            (!first || g.cycles < first->cycles))
          first = &g;
      if (first)
        gs.push_back(first);
    }
    law_plot("campaign_control_laws.png",
             "Laws of every material at its fewest cycles (controls), " + level + " bands", gs,
             true);
  }
  // Degradation: per material the four law properties against cycles with their intervals and
  // the least-squares line, its slope interval and p in the key.
  for (const auto& mat : materials_of(r)) {
    const std::string csv = "campaign_degradation_" + file_name_part(mat) + ".csv";
    std::vector<std::string> header{"cycles"};
    const std::vector<std::string> props{"sigma1", "sigma2", "J1", "J2"};
    const std::vector<GroupQuantity> qs{GroupQuantity::sigma1, GroupQuantity::sigma2,
                                        GroupQuantity::J1, GroupQuantity::J2};
    for (const auto& p : props) {
      header.push_back(p);
      header.push_back(p + "_lo");
      header.push_back(p + "_hi");
    }
    CsvWriter w(dir + "/" + csv, header,
                {mat + ": group values (kPa, J/m^2) and their bootstrap intervals vs cycles"});
    bool any = false;
    for (const auto& g : r.groups) {
      if (g.material != mat)
        continue;
      std::vector<double> row{g.cycles};
      for (auto kq : qs) {
        row.push_back(q(g, kq));
        row.push_back(ci(g, kq).lo);
        row.push_back(ci(g, kq).hi);
        any = any || std::isfinite(q(g, kq));
      }
      w.row(row);
    }
    w.close();
    if (!any)
      continue;
    const std::string png = "campaign_degradation_" + file_name_part(mat) + ".png";
    std::string s = gnuplot_png_preamble(png, 1100, 800);
    s += "set multiplot layout 2,2 title '" + mat + ": degradation with moisture cycles (" + level +
         " intervals)'\nset xlabel 'cycles'\nset key below font ',9'\nset offsets 2,2,0,0\n";
    for (std::size_t p = 0; p < props.size(); ++p) {
      const auto* d = find_degradation(r, mat, props[p]);
      const int c = 2 + 3 * static_cast<int>(p);
      s += "set ylabel '" + props[p] + (p < 2 ? " (kPa)" : " (J/m^2)") + "'\n";
      s += "plot '" + csv + "' using 1:" + std::to_string(c) + ":" + std::to_string(c + 1) + ":" +
           std::to_string(c + 2) + " with yerrorbars pt 7 title 'groups'";
      if (d && d->has_slope) {
        s += ", " + fmt(d->paper.fit.intercept, 8) + " + " + fmt(d->paper.fit.slope, 8) +
             "*x with lines lw 2 title 'slope " + fmt(d->paper.fit.slope, 3) + " [" +
             cell(d->slope_ci.lo, 3) + ", " + cell(d->slope_ci.hi, 3) + "] p " +
             cell(d->p_value, 2) + ", R^2 " + fmt(d->paper.fit.r2, 2) + "'";
      }
      s += "\n";
    }
    s += "unset multiplot\n";
    if (run_gnuplot(dir, s))
      pngs.push_back(png);
  }
  return pngs;
}

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
       std::to_string(r.options.seed) + ", " + interval_name(r.options) + "). Analysis " +
       fmt(w.seconds, 3) + " s.</p>\n";
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

Json summary_block(const CampaignResult& r, const CampaignWriteOptions& w) {
  Json groups = Json::array();
  for (const auto& g : r.groups) {
    Json specimens = Json::array();
    for (auto m : g.members)
      specimens.push_back(r.specimens[m].row.specimen);
    Json cij = Json::object();
    for (std::size_t k = 0; k < analysis::n_group_quantities; ++k)
      cij[analysis::quantity_key(static_cast<GroupQuantity>(k))] = interval_json(g.ci[k]);
    Json tri = {{"d1_mm", json_number(q(g, GroupQuantity::d1))},
                {"sigma1_kPa", json_number(q(g, GroupQuantity::sigma1))},
                {"d2_mm", json_number(q(g, GroupQuantity::d2))},
                {"sigma2_kPa", json_number(q(g, GroupQuantity::sigma2))},
                {"delta_c_mm", json_number(q(g, GroupQuantity::delta_c))}};
    groups.push_back(
        {{"material", g.material},
         {"cycles", g.cycles},
         {"n_specimens", g.members.size()},
         {"specimens", specimens},
         {"ok", g.estimate.ok},
         // R(a)-only groups: which estimator gave J_tip and G_ss (Campaign/R(a) estimator).
         {"ra_estimator", !g.members.empty() && !r.specimens[g.members.front()].has_rdelta
                              ? Json(analysis::to_string(r.estimator))
                              : Json(nullptr)},
         {"trilinear", tri},
         {"J1_J_m2", json_number(q(g, GroupQuantity::J1))},
         {"J2_J_m2", json_number(q(g, GroupQuantity::J2))},
         {"G_ss_J_m2", json_number(q(g, GroupQuantity::G_ss))},
         {"J_tip_J_m2", json_number(q(g, GroupQuantity::J_tip))},
         {"l_b_mm", json_number(q(g, GroupQuantity::l_b))},
         {"rho_b_per_mm2", Json::array({json_number(q(g, GroupQuantity::rho_low)),
                                        json_number(q(g, GroupQuantity::rho_high))})},
         {"rms_residual_kPa", json_number(g.estimate.rms_residual / kPa)},
         {"ci", cij},
         {"bootstrap",
          {{"samples", g.samples.size()}, {"failed", g.failed_samples}, {"seed", g.seed}}},
         {"notes", g.notes}});
  }
  Json deg = Json::array();
  for (const auto& d : r.degradation)
    deg.push_back(
        {{"material", d.material},
         {"property", d.property},
         {"cycles", d.cycles},
         {"values", d.values},
         {"has_slope", d.has_slope},
         {"slope_per_cycle", json_number(d.has_slope ? d.paper.fit.slope : NAN)},
         {"r2", json_number(d.has_slope ? d.paper.fit.r2 : NAN)},
         {"significant_paper_rule", d.has_slope && d.paper.significant},
         {"normalized_rate_per_cycle", json_number(d.has_slope ? d.paper.normalized_rate : NAN)},
         {"slope_ci", interval_json(d.slope_ci)},
         {"p_value", json_number(d.p_value)},
         {"bootstrap_samples", d.samples_used},
         {"note", d.note}});
  Json ranking = Json::array(), detail = Json::array(), conf = Json::array();
  for (const auto& m : r.ranking.ranks) {
    ranking.push_back(m.material);
    detail.push_back({{"material", m.material},
                      {"rank", m.rank},
                      {"degradation_score_per_cycle", m.degradation_score},
                      {"significant_properties", m.significant_properties}});
  }
  for (const auto& p : r.ranking.pairs)
    conf.push_back({{"first", p.first},
                    {"second", p.second},
                    {"p_first_ahead", json_number(p.p_first_ahead)},
                    {"p_tie", json_number(p.p_tie)},
                    {"p_second_ahead", json_number(p.p_second_ahead)}});
  std::vector<std::string> notes = r.notes;
  for (const auto& n : r.ranking.notes)
    notes.push_back(n);
  return {{"manifest", r.manifest.source},
          {"n_specimens", r.specimens.size()},
          {"n_groups", r.groups.size()},
          {"bootstrap_samples", r.options.bootstrap_samples},
          {"seed", r.options.seed},
          {"confidence", r.options.confidence},
          {"interval", interval_name(r.options)},
          {"wall_time_s", w.seconds},
          {"groups", groups},
          {"degradation", deg},
          {"ranking", ranking},
          {"ranking_detail", detail},
          {"ranking_confidence", conf},
          {"ranking_bootstrap_samples", r.ranking.samples},
          {"reference_materials", r.ranking.reference},
          {"not_ranked", r.ranking.not_ranked},
          {"notes", notes}};
}

} // namespace

void write_campaign_outputs(const CampaignResult& r, const CampaignWriteOptions& w,
                            const std::string& out_dir, Json& summary) {
  write_table1(r, out_dir);
  write_groups_table(r, out_dir);
  write_specimens_table(r, out_dir);
  write_statistics_tables(r, out_dir);
  std::vector<std::string> files{"campaign_table1.csv",
                                 "campaign_table1_values.csv",
                                 "campaign_groups.csv",
                                 "campaign_specimens.csv",
                                 "campaign_degradation.csv",
                                 "campaign_ranking.csv",
                                 "campaign_ranking_confidence.csv"};
  for (const auto& f : write_group_laws(r, w.fe_export, out_dir))
    files.push_back(f);
  auto pngs = write_plots(r, out_dir);
  for (const auto& p : w.simulation_pngs)
    pngs.push_back(p);
  write_html(r, w, pngs, files, out_dir);
  summary["campaign"] = summary_block(r, w);
  add_campaign_simulation_summary(r, w.simulations, summary);
  for (const auto& p : pngs)
    summary["plots"].push_back(p);
}

} // namespace fiberbridge::app
