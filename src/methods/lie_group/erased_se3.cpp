// What the library compiles for the erased Lagrangian on SE(3) (kernels/lie_group/compiled.hpp).
#include "cartan/kernels/lie_group/along.hpp"
#include "cartan/kernels/lie_group/verify.hpp"
#include "cartan/methods/lie_group/solve.hpp"

CARTAN_TRANSPORTED_COMPILED_ERASED(template, ::cartan::groups::SE3)
CARTAN_TRANSPORTED_SHOOTING_ERASED(template, ::cartan::groups::SE3)
