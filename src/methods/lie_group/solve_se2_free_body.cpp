// solve and validate for the free body on SE(2), compiled once (kernels/lie_group/compiled.hpp).
#include "cartan/methods/lie_group/solve.hpp"

CARTAN_TRANSPORTED_COMPILED_MODEL(template, ::cartan::groups::SE2, ::cartan::mechanics::SE2FreeBody)
