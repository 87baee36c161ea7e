// solve and validate for the oscillator on SO(3), compiled once (kernels/lie_group/compiled.hpp).
#include "cartan/methods/lie_group/solve.hpp"

CARTAN_TRANSPORTED_COMPILED_MODEL(template, ::cartan::groups::SO3, ::cartan::mechanics::SO3Oscillator)
