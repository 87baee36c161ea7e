#pragma once
// Invariant connections (invariant_connection.hpp), the Cartan–Schouten family
// (cartan_schouten.hpp: CS-conn, CS-conn-right, tor-cur-lie-alg) and parallel transport as
// ordered exponentials (parallel_transport.hpp: cor-parr, parr-tran-Cartan-lambda), bound once for
// every group as the nested class `<Group>.Connection` and static methods of the group class.

#include <string>

#include "bind_group.hpp"
#include "cartan/connections/cartan_schouten.hpp"
#include "cartan/transport/parallel_transport.hpp"

namespace cartan::python {

groups::Side parse_side(const std::string& side, std::string_view where);
transport::TransportMethod parse_transport_method(const std::string& method, std::string_view where);

/// A Python callable u(t) as the velocity function the transport templates take; its values
/// are checked like any other argument ("<where>: u(t) = ... must have shape (n,)").
template <groups::LieGroup G>
auto velocity_function(const py::object& u, const std::string& where) {
  return [u, where](double t) { return to_eigen<groups::TangentOf<G>>(u(t), where, "u(" + format_value(t) + ")"); };
}

/// P(s -> t), or P(s -> t_k) at every node as a (steps + 1, n, n) array when `nodes` is set.
template <class Final, class Nodes>
py::array_t<double> final_or_nodes(bool nodes, const Final& final_value, const Nodes& all_nodes) {
  if (nodes) return to_numpy(all_nodes());
  return to_numpy(final_value());
}

template <groups::LieGroup G>
void bind_connection(GroupClass<G>& group, const std::string& group_name) {
  using Connection = connections::InvariantConnection<G>;
  const std::string where = group_name + ".Connection";
  const Args<G> a{where};
  py::class_<Connection> cls(group, "Connection",
                             "An invariant affine connection given by its bilinear map on the algebra (left or right).");
  cls.def(py::init([where](const std::string& side, const py::object& table) {
            return Connection::from_table(
                parse_side(side, where), to_eigen<Eigen::Matrix<double, G::kDim, G::kDim * G::kDim>>(table, where, "table"));
          }),
          py::arg("side"), py::arg("table"),
          "From a (n, n*n) table whose column i*n + j holds nabla_{E_i} E_j.");
  cls.def_property_readonly("side", [](const Connection& c) { return std::string(to_string(c.side())); });
  cls.def_property_readonly("coefficients", [](const Connection& c) {
    return to_numpy(std::vector<groups::AlgebraMatrixOf<G>>(c.coefficients().begin(), c.coefficients().end()));
  }, "Array (n, n, n): coefficients[i] is the matrix of w -> nabla_{E_i} w.");
  cls.def("nabla", [a](const Connection& c, const py::object& u, const py::object& w) {
    return to_numpy(c.nabla(a.tangent(u, "nabla", "u"), a.tangent(w, "nabla", "w")));
  }, py::arg("u"), py::arg("w"), "The bilinear map nabla_u w.");
  cls.def("torsion", [a](const Connection& c, const py::object& v, const py::object& w) {
    return to_numpy(c.torsion(a.tangent(v, "torsion", "v"), a.tangent(w, "torsion", "w")));
  }, py::arg("v"), py::arg("w"), "T(v, w) on invariant fields (cur-tor-left).");
  cls.def("curvature", [a](const Connection& c, const py::object& u, const py::object& v, const py::object& w) {
    return to_numpy(c.curvature(a.tangent(u, "curvature", "u"), a.tangent(v, "curvature", "v"),
                                a.tangent(w, "curvature", "w")));
  }, py::arg("u"), py::arg("v"), py::arg("w"), "R(u, v) w on invariant fields (cur-tor-left).");
  cls.def("is_cartan", [](const Connection& c) { return c.is_cartan(); },
          "True when the bilinear map is skew (geodesics through e are one-parameter subgroups).");
  cls.def("transport", [where](const Connection& c, const py::object& u, double s, double t, int steps,
                               const std::string& method, bool nodes) {
    const auto f = velocity_function<G>(u, where + ".transport");
    const transport::TransportMethod m = parse_transport_method(method, where + ".transport");
    return final_or_nodes(nodes, [&] { return transport::transport_operator(c, f, s, t, steps, m); },
                          [&] { return transport::transport_operator_nodes(c, f, s, t, steps, m); });
  }, py::arg("u"), py::arg("s"), py::arg("t"), py::arg("steps") = 100, py::arg("method") = "magnus4",
     py::arg("nodes") = false,
     "P(s -> t) = Texp(-int_s^t nabla_u(r) dr) (cor-parr) for the trivialised velocity u(r), a callable "
     "returning an algebra vector; method lie-euler | magnus2 | magnus4.");
  cls.def("transport_sampled", [where](const Connection& c, const py::object& u_nodes, double s, double t,
                                       const std::string& method, const py::object& u_midpoints, bool nodes) {
    const std::string w = where + ".transport_sampled";
    transport::Samples<groups::TangentOf<G>> samples{to_eigen_list<groups::TangentOf<G>>(u_nodes, w, "u_nodes"), {}, s, t};
    if (!u_midpoints.is_none()) samples.midpoints = to_eigen_list<groups::TangentOf<G>>(u_midpoints, w, "u_midpoints");
    const transport::TransportMethod m = parse_transport_method(method, w);
    return final_or_nodes(nodes, [&] { return transport::transport_operator(c, samples, m); },
                          [&] { return transport::transport_operator_nodes(c, samples, m); });
  }, py::arg("u_nodes"), py::arg("s"), py::arg("t"), py::arg("method") = "magnus2",
     py::arg("u_midpoints") = py::none(), py::arg("nodes") = false,
     "P(s -> t) from samples u(t_k) on a uniform grid (and u(t_k + h/2) for magnus4).");

  group.def_static("cartan_schouten", [group_name](double lambda, const std::string& side) {
    return connections::cartan_schouten<G>(lambda, parse_side(side, group_name + ".cartan_schouten"));
  }, py::arg("lam"), py::arg("side") = "left",
     "The Cartan-Schouten connection of parameter lam: left map lam ad (CS-conn), right map (lam - 1) ad "
     "(CS-conn-right).");
  group.def_static("cartan_schouten_transport", [group_name](double lambda, const py::object& u, double s, double t,
                                                             int steps, const std::string& method,
                                                             const std::string& side, bool nodes) {
    const std::string w = group_name + ".cartan_schouten_transport";
    const auto f = velocity_function<G>(u, w);
    const transport::TransportMethod m = parse_transport_method(method, w);
    const groups::Side sd = parse_side(side, w);
    return final_or_nodes(nodes, [&] { return transport::cartan_schouten_transport<G>(lambda, sd, f, s, t, steps, m); },
                          [&] { return transport::cartan_schouten_transport_nodes<G>(lambda, sd, f, s, t, steps, m); });
  }, py::arg("lam"), py::arg("u"), py::arg("s"), py::arg("t"), py::arg("steps") = 100, py::arg("method") = "magnus4",
     py::arg("side") = "left", py::arg("nodes") = false,
     "P(s -> t) of the Cartan-Schouten connection (parr-tran-Cartan-lambda) computed in the group: P = Ad(Y).");
}

}  // namespace cartan::python
