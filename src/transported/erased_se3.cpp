// The transported solve and verify on SE(3) for the erased Lagrangian, compiled once (compiled.hpp).
#include "cartan/transported/compiled.hpp"

CARTAN_TRANSPORTED_COMPILED(template, ::cartan::groups::SE3)
