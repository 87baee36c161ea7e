// solve and validate for the free body on SE(3), compiled once (transported/compiled.hpp).
#include "cartan/transported/solve.hpp"

CARTAN_TRANSPORTED_COMPILED_MODEL(template, ::cartan::groups::SE3, ::cartan::mechanics::SE3FreeBody)
