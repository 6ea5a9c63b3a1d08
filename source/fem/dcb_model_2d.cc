// The 2D instantiation of DcbModel (a translation unit of its own: each takes about a minute to
// compile, and the two compile in parallel).
#include "dcb_model.templates.h"

namespace fiberbridge::fem::distributed {

template class DcbModel<2>;
template result::SimulationResult run_distributed<2>(const specimen::Specimen&,
                                                     const specimen::Material&,
                                                     const law::TractionLaw&, double,
                                                     const FemParameters&, const std::string&,
                                                     const std::function<void(const std::string&)>&,
                                                     MPI_Comm, DistributedRunInfo&, FemRunDetails&);

} // namespace fiberbridge::fem::distributed
