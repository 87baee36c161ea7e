// What the library compiles for the erased Lagrangian on SE(3) (transported/compiled.hpp).
#include "cartan/transported/along.hpp"
#include "cartan/transported/solve.hpp"
#include "cartan/verify/report.hpp"

CARTAN_TRANSPORTED_COMPILED_ERASED(template, ::cartan::groups::SE3)
CARTAN_TRANSPORTED_SHOOTING_ERASED(template, ::cartan::groups::SE3)
