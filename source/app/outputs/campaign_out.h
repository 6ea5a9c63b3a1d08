#pragma once
// What the campaign's writers share (outputs/campaign_*.cc): cells, the groups' values and
// intervals, the materials and cycle counts in the order the tables list them, and Table 1's rows.
#include "fiberbridge/analysis/campaign_run.h"
#include "fiberbridge/app/outputs/campaign_writers.h"
#include "fiberbridge/core/summary.h"

#include <string>
#include <vector>

namespace fiberbridge::app::campaign_out {

using analysis::CampaignGroup;
using analysis::CampaignResult;
using analysis::GroupQuantity;

/// A number cell, empty when not finite.
std::string cell(double v, int precision = 4);
/// A text cell: quoted when it holds a comma or a quote (core/csv.h reads such cells back).
std::string text_cell(const std::string& s);
std::string html_escape(const std::string& s);
/// campaign_law_<stem>.csv and the other per-group files' stem.
std::string group_stem(const CampaignGroup& g);
/// A group's point estimate and interval of one quantity.
double q(const CampaignGroup& g, GroupQuantity k);
const analysis::Interval& ci(const CampaignGroup& g, GroupQuantity k);
std::string interval_name(const analysis::CampaignOptions& o);
Json interval_json(const analysis::Interval& i);
/// The cycle counts (ascending) and the materials (in manifest order) of the groups.
std::vector<double> cycles_of(const CampaignResult& r);
std::vector<std::string> materials_of(const CampaignResult& r);
const CampaignGroup* find_group(const CampaignResult& r, const std::string& m, double c);
const analysis::CampaignDegradation* find_degradation(const CampaignResult& r, const std::string& m,
                                                      const std::string& p);

/// Table 1 rows: property name as in seed_table1.csv and the quantity behind it.
struct TableRow {
  const char* property;
  GroupQuantity quantity;
};
const std::vector<TableRow>& table_rows();
/// The law properties each material's degradation tabulates and plots, in column order.
const std::vector<TableRow>& degradation_rows();

// The writers, one output each (outputs/campaign_writers.cc calls them in this order).
/// campaign_table1.csv (with intervals) and campaign_table1_values.csv (seed format, for rank).
void write_table1(const CampaignResult& r, const std::string& dir);
/// campaign_groups.csv.
void write_groups_table(const CampaignResult& r, const std::string& dir);
/// campaign_specimens.csv.
void write_specimens_table(const CampaignResult& r, const std::string& dir);
/// campaign_degradation.csv, campaign_ranking.csv, campaign_ranking_confidence.csv.
void write_statistics_tables(const CampaignResult& r, const std::string& dir);
/// Per group with a law: its law CSV (Eq. 6, dR/ddelta, trilinear, band) and the FE cards;
/// returns the files written.
std::vector<std::string> write_group_laws(const CampaignResult& r, bool fe_export,
                                          const std::string& dir);
/// campaign_degradation_<material>.csv: per material the group values of the four law
/// properties and their intervals against cycles (the degradation plots read them).
void write_degradation_by_material(const CampaignResult& r, const std::string& dir);
/// The PNGs: each material's laws with their bands, the controls' laws, each material's
/// degradation (from campaign_degradation_<material>.csv); returns those gnuplot made.
std::vector<std::string> write_plots(const CampaignResult& r, const std::string& dir);
/// campaign_report.html.
void write_html(const CampaignResult& r, const CampaignWriteOptions& w,
                const std::vector<std::string>& pngs, const std::vector<std::string>& files,
                const std::string& dir);
/// The summary block `campaign`.
Json summary_block(const CampaignResult& r, const CampaignWriteOptions& w);

} // namespace fiberbridge::app::campaign_out
