// The 3D instantiation of the distributed engine (a translation unit of its own: each takes
// about a minute to compile, and the two compile in parallel).
#include "distributed_dcb.templates.h"

namespace fiberbridge::fem::distributed {

template result::SimulationResult run_distributed<3>(const specimen::Specimen&,
                                                     const specimen::Material&,
                                                     const law::TractionLaw&, double,
                                                     const FemParameters&, const std::string&,
                                                     const std::function<void(const std::string&)>&,
                                                     MPI_Comm, DistributedRunInfo&, FemRunDetails&);

} // namespace fiberbridge::fem::distributed
