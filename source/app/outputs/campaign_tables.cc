// The campaign's tables: Table 1, groups, specimens, degradation and ranking statistics.
#include "outputs/campaign_out.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"

#include <cmath>
#include <map>

namespace fiberbridge::app::campaign_out {

using units::kPa;
using units::mm;

namespace {

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

} // namespace

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

} // namespace fiberbridge::app::campaign_out
