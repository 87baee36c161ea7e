// solve and validate for the oscillator on SO(3), compiled once (transported/compiled.hpp).
#include "cartan/transported/solve.hpp"

CARTAN_TRANSPORTED_COMPILED_MODEL(template, ::cartan::groups::SO3, ::cartan::mechanics::SO3Oscillator)
