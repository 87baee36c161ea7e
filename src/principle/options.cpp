// The options from their words (cartan/principle/options.hpp).
#include "cartan/principle/options.hpp"

#include "cartan/enum_names.hpp"

namespace cartan {

SolveOptions solve_options(const OptionWords& words, std::string_view where) {
  SolveOptions o;
  o.method = parse_enum<Method>(words.method, where);
  o.continuation = parse_enum<Continuation>(words.continuation, where);
  o.order = scheme_order(words.order, where);
  o.tol = words.tol;
  o.max_iterations = words.max_iterations;
  o.segments = words.segments;
  o.lambda_start = words.lambda_start;
  o.samples = words.samples;
  o.max_nodes = words.max_nodes;
  o.time_limit = words.time_limit;
  return o;
}

}  // namespace cartan
