// The 3D instantiation of DcbModel (a translation unit of its own: each takes about a minute to
// compile, and the two compile in parallel).
#include "dcb_model.templates.h"

FIBERBRIDGE_FEM_INSTANTIATE_DCB_MODEL(3)
