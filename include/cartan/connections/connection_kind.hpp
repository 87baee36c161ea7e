#pragma once
// The left-invariant connections a group is given by name, one spelling for the C++ API, the CLI's
// --connection and Python's GroupManifold(group, connection): Cartan–Schouten of a parameter lambda
// (CS-conn), Levi-Civita of a left-invariant metric, or any bilinear map alpha given by its
// coefficients (manifolds::GroupManifold<G>: cartan_schouten, levi_civita, coefficients).

#include <array>
#include <string_view>
#include <utility>

#include "cartan/enum_names.hpp"

namespace cartan::connections {

enum class ConnectionKind { CartanSchouten, LeviCivita, Coefficients };

}  // namespace cartan::connections

namespace cartan {

template <>
struct EnumNames<connections::ConnectionKind> {
  static constexpr std::string_view what = "connection";
  static constexpr std::array<std::pair<connections::ConnectionKind, std::string_view>, 3> names{
      {{connections::ConnectionKind::CartanSchouten, "cartan-schouten"},
       {connections::ConnectionKind::LeviCivita, "levi-civita"},
       {connections::ConnectionKind::Coefficients, "coefficients"}}};
};

}  // namespace cartan
