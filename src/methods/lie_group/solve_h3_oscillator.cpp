// solve and validate for the Heisenberg oscillator, compiled once (kernels/lie_group/compiled.hpp).
#include "cartan/methods/lie_group/solve.hpp"

CARTAN_TRANSPORTED_COMPILED_MODEL(template, ::cartan::groups::Heisenberg, ::cartan::mechanics::H3Oscillator)
