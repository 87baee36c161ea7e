#pragma once
// The vocabulary's names in the Lie-group kernel's namespace (principle/vocabulary.hpp defines them).

#include "cartan/principle/vocabulary.hpp"

namespace cartan::transported {

using ::cartan::Continuation;
using ::cartan::kCollocationOrder;
using ::cartan::kDefaultMaxIterations;
using ::cartan::kDefaultTol;
using ::cartan::kVariationalOrder;
using ::cartan::Method;

}  // namespace cartan::transported
