#include "fiberbridge/law/rigid_law.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/elastic_rise_law.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <memory>
#include <utility>

namespace fiberbridge::law {

std::string rigid_law_insertion_note(const TractionLaw& law) {
  if (!(law.critical_opening() > 0 && law.rigid_at_zero_opening()))
    return "";
  return "rigid " + law.name() +
         " law inserted extrinsically: each new cohesive segment starts at sigma(0+) = " +
         fmt(law.envelope(0) / units::kPa) +
         " kPa (no elastic rise: the area and Eq. 2 are the law's)";
}

void note_rigid_law_insertion(const TractionLaw& law, std::vector<std::string>& notes) {
  if (std::string note = rigid_law_insertion_note(law); !note.empty())
    notes.push_back(std::move(note));
}

TractionLawPtr with_elastic_rise(const TractionLaw& law, double delta_e, const std::string& key) {
  if (!(law.critical_opening() > 0 && law.rigid_at_zero_opening()))
    return nullptr;
  const auto k = law.kinks();
  if (!(delta_e > 0) || (k.size() > 1 && !(delta_e < k[1])))
    throw InputError(key + ": the elastic rise must end before the law's first kink (" +
                     fmt((k.size() > 1 ? k[1] : law.critical_opening()) / units::mm) + " mm)");
  if (const auto* p = dynamic_cast<const PiecewiseLinearLaw*>(&law))
    return std::make_shared<PiecewiseLinearLaw>(p->with_elastic_rise(delta_e));
  return std::make_shared<ElasticRiseLaw>(law, delta_e);
}

} // namespace fiberbridge::law
