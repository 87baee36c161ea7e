// solve and validate for the free body on SE(3), compiled once (kernels/lie_group/compiled.hpp).
#include "cartan/methods/lie_group/solve.hpp"

CARTAN_TRANSPORTED_COMPILED_MODEL(template, ::cartan::groups::SE3, ::cartan::mechanics::SE3FreeBody)
