// The transported solve and verify on SO(3) for the erased Lagrangian, compiled once (compiled.hpp).
#include "cartan/transported/compiled.hpp"

CARTAN_TRANSPORTED_COMPILED(template, ::cartan::groups::SO3)
