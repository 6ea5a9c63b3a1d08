// The campaign's degradation per material, as the plots read it.
#include "outputs/campaign_out.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"

namespace fiberbridge::app::campaign_out {

using units::kPa;

void write_degradation_by_material(const CampaignResult& r, const std::string& dir) {
  for (const auto& mat : materials_of(r)) {
    const std::string csv = "campaign_degradation_" + file_name_part(mat) + ".csv";
    std::vector<std::string> header{"cycles"};
    for (const auto& d : degradation_rows()) {
      header.push_back(d.property);
      header.push_back(std::string(d.property) + "_lo");
      header.push_back(std::string(d.property) + "_hi");
    }
    CsvWriter w(dir + "/" + csv, header,
                {mat + ": group values (kPa, J/m^2) and their bootstrap intervals vs cycles"});
    for (const auto& g : r.groups) {
      if (g.material != mat)
        continue;
      std::vector<double> row{g.cycles};
      for (const auto& d : degradation_rows()) {
        row.push_back(q(g, d.quantity));
        row.push_back(ci(g, d.quantity).lo);
        row.push_back(ci(g, d.quantity).hi);
      }
      w.row(row);
    }
    w.close();
  }
}

} // namespace fiberbridge::app::campaign_out
