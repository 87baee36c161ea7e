#include "cartan/models/catalogue.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <utility>

#include "cartan/errors.hpp"

namespace cartan::models {

namespace {

/// max|R^T R - I| and |det R - 1| of a rotation block, or "" when within kElementTolerance.
std::string rotation_problem(const Eigen::MatrixXd& r) {
  const Eigen::Index n = r.rows();
  const double orthogonality = (r.transpose() * r - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff();
  const double det = r.determinant();
  if (orthogonality <= kElementTolerance && std::abs(det - 1) <= kElementTolerance) return "";
  return "(max|R^T R - I| = " + format_value(orthogonality) + ", det R = " + format_value(det) + ", tolerance " +
         format_value(kElementTolerance) + ")";
}

template <class Table>
void check_element(const std::vector<double>& numbers, std::string_view where, const std::string& name) {
  using G = typename Table::Group;
  for (double x : numbers) {
    if (!std::isfinite(x)) throw_invalid(where, name, excerpt(numbers), "contains a non-finite number");
  }
  if constexpr (!std::is_same_v<G, groups::Heisenberg>) {
    const Eigen::Index size = G::Element::RowsAtCompileTime;
    const Eigen::MatrixXd m = square_matrix(numbers, size);  // size^2 numbers: row-major
    const bool motion = !std::is_same_v<G, groups::SO3>;  // se2, se3: [[R, t], [0, 1]]
    const Eigen::Index k = motion ? size - 1 : size;
    if (const std::string problem = rotation_problem(m.topLeftCorner(k, k)); !problem.empty()) {
      throw_invalid(where, name, excerpt(numbers),
                    std::string(motion ? "has a rotation block R that is" : "is") + " not orthogonal with determinant 1 " + problem);
    }
    if (motion) {
      Eigen::RowVectorXd bottom = Eigen::RowVectorXd::Zero(size);
      bottom[size - 1] = 1;
      const double deviation = (m.row(size - 1) - bottom).cwiseAbs().maxCoeff();
      if (deviation > kElementTolerance) {
        throw_invalid(where, name, excerpt(numbers),
                      "has bottom row " + excerpt(element_numbers(m.row(size - 1))) + ", not " +
                          excerpt(element_numbers(bottom)) + " (tolerance " + format_value(kElementTolerance) + ")");
      }
    }
  }
}

template <class Table, class L>
ModelInfo info_of(const ModelEntry<Table, L>& entry) {
  using G = typename Table::Group;
  return {Table::name,
          entry.name,
          entry.type_name,
          G::kDim,
          static_cast<std::size_t>(G::Element::SizeAtCompileTime),
          Table::element_what,
          Table::directions,
          entry.default_inertia,
          element_numbers(G::identity()),
          &check_element<Table>};
}

std::string joined(const std::vector<std::string_view>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

}  // namespace

Eigen::MatrixXd square_matrix(const std::vector<double>& numbers, Eigen::Index n) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
  if (numbers.size() == static_cast<std::size_t>(n)) {
    for (Eigen::Index i = 0; i < n; ++i) m(i, i) = numbers[static_cast<std::size_t>(i)];
    return m;
  }
  for (Eigen::Index i = 0; i < n * n; ++i) m(i / n, i % n) = numbers[static_cast<std::size_t>(i)];
  return m;
}

const std::vector<ModelInfo>& model_infos() {
  static const std::vector<ModelInfo> infos =
      std::apply([](const auto&... entries) { return std::vector<ModelInfo>{info_of(entries)...}; }, kModels);
  return infos;
}

std::string group_names() {
  std::vector<std::string_view> names;
  for (const auto& m : model_infos()) {
    if (names.empty() || names.back() != m.group) names.push_back(m.group);
  }
  return joined(names);
}

std::string model_names(std::string_view group) {
  std::vector<std::string_view> names;
  for (const auto& m : model_infos()) {
    if (m.group == group) names.push_back(m.model);
  }
  return joined(names);
}

const ModelInfo& find_model(std::string_view group, std::string_view model, std::string_view where) {
  const ModelInfo* first = nullptr;
  for (const auto& m : model_infos()) {
    if (m.group != group) continue;
    if (first == nullptr) first = &m;
    if (m.model == model) return m;
  }
  if (first == nullptr) throw_invalid(where, "group", quote_input(group), "is not one of: " + group_names());
  if (model.empty()) return *first;
  throw_invalid(where, "model", quote_input(model),
                "is not one of: " + model_names(group) + " (the models of group " + std::string(group) + ")");
}

void rethrow_inertia(const std::invalid_argument& error, const Eigen::Ref<const Eigen::MatrixXd>& matrix,
                     const std::vector<double>& numbers, std::string_view where) {
  // The library's message is "<model>: inertia = <format_value(matrix)> <reason>": keep the reason.
  const std::string message = error.what();
  const std::string value = "inertia = " + format_value(matrix) + " ";
  const auto at = message.find(value);
  const std::string reason = at == std::string::npos ? "is rejected: " + message : message.substr(at + value.size());
  throw_invalid(where, "inertia", excerpt(numbers), reason);
}

void check_inertia(const ModelInfo& model, const std::vector<double>& inertia, std::string_view where) {
  visit_model(model.group, model.model, where, [&]<class Entry>(const Entry&) {
    make_lagrangian<Entry>(inertia, where);
    return 0;
  });
}

template <groups::LieGroup G>
groups::ElementOf<G> element_of(const std::vector<double>& numbers) {
  if constexpr (std::is_same_v<G, groups::Heisenberg>) {
    return groups::Heisenberg::Element(numbers[0], numbers[1], numbers[2]);
  } else {
    constexpr int size = G::Element::RowsAtCompileTime;
    groups::ElementOf<G> g = groups::ElementOf<G>::Identity();
    for (int i = 0; i < size * size; ++i) g(i / size, i % size) = numbers[static_cast<std::size_t>(i)];
    if constexpr (std::is_same_v<G, groups::SO3>) {
      return groups::SO3::from_matrix(g, kElementTolerance);
    } else {
      constexpr int k = size - 1;
      Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
      r.topLeftCorner<k, k>() = g.template topLeftCorner<k, k>();
      r = groups::SO3::from_matrix(r, kElementTolerance);
      g.template topLeftCorner<k, k>() = r.topLeftCorner<k, k>();
      g.row(size - 1).setZero();
      g(size - 1, size - 1) = 1;
      return g;
    }
  }
}

template groups::ElementOf<groups::SO3> element_of<groups::SO3>(const std::vector<double>&);
template groups::ElementOf<groups::Heisenberg> element_of<groups::Heisenberg>(const std::vector<double>&);
template groups::ElementOf<groups::SE2> element_of<groups::SE2>(const std::vector<double>&);
template groups::ElementOf<groups::SE3> element_of<groups::SE3>(const std::vector<double>&);

}  // namespace cartan::models
