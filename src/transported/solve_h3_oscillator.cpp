// solve and validate for the Heisenberg oscillator, compiled once (transported/compiled.hpp).
#include "cartan/transported/solve.hpp"

CARTAN_TRANSPORTED_COMPILED_MODEL(template, ::cartan::groups::Heisenberg, ::cartan::mechanics::H3Oscillator)
