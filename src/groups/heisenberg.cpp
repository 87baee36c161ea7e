#include "cartan/groups/heisenberg.hpp"

#include "cartan/errors.hpp"

namespace cartan::groups {

Heisenberg::Tangent Heisenberg::log(const Element& g) { return Tangent(g[0], g[1], g[2] - g[0] * g[1] / 2); }

Heisenberg::MatrixRep Heisenberg::hat(const Tangent& v) {
  MatrixRep x;
  x << 0, v[0], v[2],  //
      0, 0, v[1],      //
      0, 0, 0;
  return x;
}

Heisenberg::Tangent Heisenberg::vee(const MatrixRep& x) { return Tangent(x(0, 1), x(1, 2), x(0, 2)); }

Heisenberg::MatrixRep Heisenberg::matrix(const Element& g) {
  MatrixRep m;
  m << 1, g[0], g[2],  //
      0, 1, g[1],      //
      0, 0, 1;
  return m;
}

Heisenberg::Element Heisenberg::left_translate(const Element& g, const Tangent& v) {
  return Element(v[0], v[1], v[2] + g[0] * v[1]);
}

Heisenberg::Element Heisenberg::right_translate(const Element& g, const Tangent& v) {
  return Element(v[0], v[1], v[2] + g[1] * v[0]);
}

Heisenberg::Tangent Heisenberg::left_trivialise(const Element& g, const Element& x) {
  return Tangent(x[0], x[1], x[2] - g[0] * x[1]);
}

Heisenberg::Tangent Heisenberg::right_trivialise(const Element& g, const Element& x) {
  return Tangent(x[0], x[1], x[2] - g[1] * x[0]);
}

void Heisenberg::validate(const Element& g, std::string_view name) { require_finite(g, "Heisenberg", name); }

}  // namespace cartan::groups
