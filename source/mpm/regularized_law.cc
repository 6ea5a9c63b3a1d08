#include "fiberbridge/mpm/regularized_law.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/law/elastic_rise_law.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <memory>

namespace fiberbridge::mpm {

law::TractionLawPtr regularize_rigid_law(const law::TractionLaw& law, double delta_e) {
  if (!law.rigid_at_zero_opening())
    return nullptr;
  const auto k = law.kinks();
  if (!(delta_e > 0) || (k.size() > 1 && !(delta_e < k[1])))
    throw InputError("MPM/Rigid law rise fraction: the elastic rise must end before the law's "
                     "first kink");
  if (const auto* p = dynamic_cast<const law::PiecewiseLinearLaw*>(&law))
    return std::make_shared<law::PiecewiseLinearLaw>(p->with_elastic_rise(delta_e));
  return std::make_shared<law::ElasticRiseLaw>(law, delta_e);
}

} // namespace fiberbridge::mpm
