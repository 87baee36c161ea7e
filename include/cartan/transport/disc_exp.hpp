#pragma once
// The transport update of the paper's discrete scheme (disc-exp). On a step of length dt along
// which the trivialised velocity is the constant u, the Cartan–Schouten transport operator moves
// by P_{k+1} = exp(-c dt ad_u) P_k = Ad(exp(-c dt u)) P_k (c = lambda on the left, CS-conn;
// lambda - 1 on the right, CS-conn-right). The solvers carry the group element y_k with
// P_k = Ad(y_k) and update it in the group, never forming a matrix exponential.

#include "cartan/groups/group.hpp"

namespace cartan::transport {

/// y_{k+1} = exp(-c dt u) y_k, so that Ad(y_{k+1}) = exp(-c dt ad_u) Ad(y_k) (disc-exp).
template <groups::LieGroup G>
groups::ElementOf<G> disc_exp_update(double c, double dt, const groups::TangentOf<G>& u, const groups::ElementOf<G>& y) {
  return G::compose(G::exp(groups::TangentOf<G>(-c * dt * u)), y);
}

}  // namespace cartan::transport
