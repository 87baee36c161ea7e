// solve and validate for the free body on SE(2), compiled once (transported/compiled.hpp).
#include "cartan/transported/solve.hpp"

CARTAN_TRANSPORTED_COMPILED_MODEL(template, ::cartan::groups::SE2, ::cartan::mechanics::SE2FreeBody)
