// What the library compiles for the erased Lagrangian on SE(2) (transported/compiled.hpp).
#include "cartan/transported/along.hpp"
#include "cartan/transported/solve.hpp"
#include "cartan/verify/report.hpp"

CARTAN_TRANSPORTED_COMPILED_ERASED(template, ::cartan::groups::SE2)
CARTAN_TRANSPORTED_SHOOTING_ERASED(template, ::cartan::groups::SE2)
