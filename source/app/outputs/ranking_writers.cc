#include "fiberbridge/app/outputs/ranking_writers.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/plot.h"

#include <cmath>
#include <iostream>
#include <set>

namespace fiberbridge::app {

void write_ranking(const analysis::RankingOutcome& r, const analysis::RankOptions& o,
                   const std::string& out_dir, ItemReport& report) {
  const auto& table = r.table;
  const auto& rows = r.rows;
  const auto& ranks = r.ranks;
  const auto& issues = r.issues;
  {
    CsvWriter w(out_dir + "/degradation.csv",
                {"material", "property", "slope_per_cycle", "intercept", "r2", "slope_std_error",
                 "normalized_rate_per_cycle", "significant", "printed_slope", "printed_r2"},
                {"degradation statistics per material and property from " + o.table_file});
    for (const auto& r : rows)
      w.row({r.material, r.property},
            {r.fit.slope, r.fit.intercept, r.fit.r2, r.fit.slope_std_error, r.normalized_rate,
             r.significant ? 1.0 : 0.0, r.has_printed ? r.printed_slope : NAN,
             r.has_printed ? r.printed_r2 : NAN});
    w.close();
  }
  Json deg = Json::array();
  for (const auto& r : rows)
    deg.push_back({{"material", r.material},
                   {"property", r.property},
                   {"slope_per_cycle", r.fit.slope},
                   {"intercept", r.fit.intercept},
                   {"r2", r.fit.r2},
                   {"slope_std_error", json_number(r.fit.slope_std_error)},
                   {"normalized_rate_per_cycle", r.normalized_rate},
                   {"significant", r.significant},
                   {"matches_printed", r.matches_printed}});
  Json ranking = Json::array(), ranking_detail = Json::array();
  for (const auto& m : ranks) {
    ranking.push_back(m.material);
    ranking_detail.push_back({{"material", m.material},
                              {"rank", m.rank},
                              {"degradation_score_per_cycle", m.degradation_score},
                              {"significant_properties", m.significant_properties}});
  }
  Json cons = Json::array();
  for (const auto& i : issues) {
    cons.push_back({{"material", i.material}, {"cycles", i.cycles}, {"message", i.message}});
    std::cerr << "warning: " << o.table_file << ": " << i.material << " at " << i.cycles
              << " cycles: " << i.message << "\n";
  }
  report["ranking"] = ranking;
  report["rank"] = {{"table_file", o.table_file},
                    {"rule", "a property degrades when its least-squares slope vs cycles is "
                             "negative with R^2 >= 0.8; materials ranked by the sum of "
                             "significant slope/intercept rates, most durable first"},
                    {"materials", ranking_detail},
                    {"degradation", deg},
                    {"consistency", cons}};
  // One PNG per material: each property normalized by its fitted intercept against cycles.
  std::set<std::string> materials;
  for (const auto& r : rows)
    materials.insert(r.material);
  for (const auto& mat : materials) {
    const std::string csv = "degradation_" + mat + ".csv";
    std::vector<std::string> props;
    for (const auto& r : rows)
      if (r.material == mat)
        props.push_back(r.property);
    std::vector<std::string> header{"cycles"};
    for (const auto& p : props)
      header.push_back(p + "_rel");
    CsvWriter w(out_dir + "/" + csv, header,
                {mat + ": property / fitted intercept vs VPSD cycles"});
    for (std::size_t c = 0; c < table.cycles.size(); ++c) {
      std::vector<double> row{table.cycles[c]};
      for (const auto& r : rows)
        if (r.material == mat) {
          for (const auto& tr : table.rows)
            if (tr.material == mat && tr.property == r.property)
              row.push_back(tr.values[c] / r.fit.intercept);
        }
      w.row(row);
    }
    w.close();
    std::string s = gnuplot_png_preamble("degradation_" + mat + ".png", 800, 500);
    s += "set title '" + mat +
         ": degradation vs moisture cycles'\nset xlabel 'VPSD cycles'\n"
         "set ylabel 'value / fitted value at 0 cycles'\nset key outside right\nplot ";
    for (std::size_t p = 0; p < props.size(); ++p)
      s += std::string(p ? ", " : "") + "'" + csv + "' using 1:" + std::to_string(p + 2) +
           " with linespoints lw 2 title '" + props[p] + "'";
    s += "\n";
    if (run_gnuplot(out_dir, s))
      report.plots.push_back("degradation_" + mat + ".png");
  }
}

} // namespace fiberbridge::app
