// The result file (cartan/api/result_file.hpp): a valid document is read back; each bad document
// is rejected with std::invalid_argument naming the key (and row) of the first bad value, never
// another exception; what the writer writes the reader reads back unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cartan/api/result_file.hpp"
#include "test_support.hpp"
#include "verify_command.hpp"

namespace cartan::api {
namespace {

using cartan::testing::expect_invalid;
using nlohmann::json;

/// A valid so3 result with three samples (g0 = I, gT = rotation by pi/2 about z).
json valid_result() {
  const json identity = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const json quarter = {0, -1, 0, 1, 0, 0, 0, 0, 1};
  return {{"status", "converged"}, {"group", "so3"}, {"model", "free-rigid-body"}, {"method", "shooting"},
          {"order", 1}, {"lambda", 0.5}, {"T", 2.0}, {"N", 2}, {"tol", 1e-10}, {"inertia", {2, 3, 4}},
          {"g0", identity}, {"gT", quarter}, {"t", {0.0, 1.0, 2.0}}, {"g", {identity, identity, quarter}},
          {"v", {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}}, {"mu", {{0, 0, 4}, {0, 0, 4}, {0, 0, 4}}},
          {"xi", {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}}, {"message", "converged"}, {"branch", "direct"},
          {"terminal_error", 0.0}, {"xi_terminal", 0.0}, {"iterations", {{"outer", 0}, {"inner", 3}, {"sweeps", 4}}},
          {"solve_time_s", 0.01}};
}

constexpr std::string_view kWhere = "cartan verify";

ResultRecord read_result(const json& j) { return read_solution(j, kWhere); }

/// What `cartan verify` does with a document: read it as a solution, then the library's checks
/// (api::verify, which first checks that the problem is well posed: api::check).
void read_and_verify(const json& j) { (void)cli::verify(read_solution(j, kWhere)); }

TEST(ResultReader, ReadsAValidDocument) {
  const ResultRecord r = read_result(valid_result());
  const auto& p = std::get<GroupProblem>(r.problem);
  EXPECT_EQ(p.group, "so3");
  EXPECT_EQ(r.result.samples.t.size(), 3);
  EXPECT_EQ(r.result.samples.points.rows(), 3);
  EXPECT_EQ(r.result.samples.points.cols(), 9);
  EXPECT_EQ(r.result.samples.mu(2, 2), 4);
  EXPECT_EQ(p.gT[1], -1);
  EXPECT_EQ(r.result.sweeps, 4);
  EXPECT_TRUE(r.result.lie_kernel);
  // Without the diagnostics (a trajectory computed elsewhere): unknown (NaN), no iterations.
  json bare = valid_result();
  for (const char* key : {"message", "branch", "terminal_error", "xi_terminal", "iterations", "solve_time_s"}) bare.erase(key);
  const ResultRecord b = read_result(bare);
  EXPECT_TRUE(std::isnan(b.result.terminal_error) && std::isnan(b.result.action));
  EXPECT_EQ(b.result.sweeps, 0);
  EXPECT_EQ(b.result.message, "");
}

struct BadCase {
  const char* what;
  json (*make)();
  const char* fragment;
};

json with(const char* key, json value) {
  json j = valid_result();
  j[key] = std::move(value);
  return j;
}
json without(const char* key) {
  json j = valid_result();
  j.erase(key);
  return j;
}

const BadCase kBadCases[] = {
    {"not an object", [] { return json::array({1, 2}); }, "result file = (an array of 2 entries)"},
    {"null", [] { return json(); }, "must be a JSON object"},
    {"missing tol", [] { return without("tol"); }, "tol = (missing)"},
    {"missing xi", [] { return without("xi"); }, "xi = (missing)"},
    {"status not a string", [] { return with("status", 3); }, "status = 3 must be a string"},
    {"unknown group", [] { return with("group", "se4"); }, "group = \"se4\" is not one of: so3, heisenberg, se2, se3"},
    {"model of another group", [] { json j = with("group", "heisenberg"); return j; }, "model = \"free-rigid-body\""},
    {"unknown method", [] { return with("method", "magic"); }, "method = \"magic\""},
    {"order 3", [] { return with("order", 3); }, "order = 3 must be 1 or 2 (the schemes) or 4 (collocation)"},
    {"fractional order", [] { return with("order", 1.5); }, "order = 1.5 must be an integer"},
    {"lambda a string", [] { return with("lambda", "0.5"); }, "lambda = \"0.5\" must be a number"},
    {"T negative", [] { return with("T", -2.0); }, "T = -2 must be positive"},
    {"N zero", [] { return with("N", 0); }, "N = 0 must be at least 1"},
    {"N huge", [] { return with("N", 1e300); }, "is out of range"},
    {"tol zero", [] { return with("tol", 0); }, "tol = 0 must be positive"},
    {"inertia short", [] { return with("inertia", {2, 3}); }, "inertia = 2,3 must have 3 numbers (the diagonal) or 9"},
    {"inertia negative", [] { return with("inertia", {2, -3, 4}); }, "is not positive definite"},
    {"inertia ragged", [] { return with("inertia", {{2}, 3, 4}); }, "inertia[1] = 3 must be a row of 1 numbers"},
    {"inertia asymmetric", [] { return with("inertia", {{2, 0, 0}, {0.5, 3, 0}, {0, 0, 4}}); }, "is not symmetric"},
    {"inertia an object", [] { return with("inertia", json::object({{"a", 1}})); }, "inertia = (an object with 1 keys)"},
    {"g0 not a rotation", [] { return with("g0", {1, 0, 0, 0, 1, 0, 0, 0, 2}); }, "g0 ="},
    {"gT a reflection", [] { return with("gT", {-1, 0, 0, 0, 1, 0, 0, 0, 1}); }, "gT ="},
    {"t too short", [] {
       json j = valid_result();
       for (const char* key : {"g", "v", "mu", "xi"}) j[key].erase(j[key].begin() + 1, j[key].end());
       j["t"] = {0.0};
       return j;
     }, "t = (an array of 1 entries) must be a list of at least 2"},
    {"t not increasing", [] { return with("t", {0.0, 1.0, 1.0}); }, "t[2] = 1 is not greater than t[1]"},
    {"t not from 0", [] { return with("t", {0.5, 1.0, 2.0}); }, "t[0] = 0.5 must be 0"},
    {"t not to T", [] { return with("t", {0.0, 1.0, 1.5}); }, "t[2] = 1.5 must equal T = 2"},
    {"t with a string", [] { return with("t", {0.0, "1", 2.0}); }, "t[1] = \"1\" must be a number"},
    {"t as rows", [] { return with("t", {{0.0, 1.0}, {2.0, 3.0}}); }, "t = (an array of 2 entries) must be a list of times"},
    {"g too few rows", [] { json j = valid_result(); j["g"].erase(0); return j; }, "g = (an array of 2 entries) must have 3 rows"},
    {"g row not a rotation", [] { json j = valid_result(); j["g"][1][8] = 2; return j; }, "g[1] ="},
    {"g row short", [] { json j = valid_result(); j["g"][2] = {1, 0, 0}; return j; }, "g[2] = (an array of 3 entries)"},
    {"v row null", [] { json j = valid_result(); j["v"][1][2] = nullptr; return j; }, "v[1][2] = nan is not finite"},
    {"v row text", [] { json j = valid_result(); j["v"][1][2] = "1"; return j; }, "v[1][2] = \"1\" must be a number"},
    {"missing sweeps", [] { json j = valid_result(); j["iterations"].erase("sweeps"); return j; }, "iterations.sweeps = (missing)"},
    {"iterations a number", [] { return with("iterations", 3); }, "iterations = 3 must be an object"},
    {"message a number", [] { return with("message", 1); }, "message = 1 must be a string"},
    {"side right", [] { return with("side", "right"); }, "side = \"right\" must be \"left\""},
    {"unknown connection", [] { return with("connection", "flat"); }, "connection = \"flat\" is not one of"},
    {"mu an object", [] { return with("mu", json::object()); }, "mu = (an object with 0 keys)"},
    {"xi row bool", [] { json j = valid_result(); j["xi"][0] = true; return j; }, "xi[0] = (boolean)"},
    {"long string", [] { return with("group", std::string(1000, 'x')); }, "group = \"xxxxxxxxxx"},
};

TEST(ResultReader, RejectsEachBadDocumentNamingTheValue) {
  for (const auto& c : kBadCases) {
    SCOPED_TRACE(c.what);
    expect_invalid([&] { read_and_verify(c.make()); }, {"cartan verify: ", c.fragment});
  }
}

// Values a parser never produces but a caller may build: non-finite numbers.
TEST(ResultReader, RejectsNonFiniteNumbers) {
  expect_invalid([] { read_result(with("lambda", std::numeric_limits<double>::quiet_NaN())); }, "lambda = nan is not finite");
  json j = valid_result();
  j["v"][1][0] = std::numeric_limits<double>::infinity();
  expect_invalid([&] { read_result(j); }, "v[1][0] = inf is not finite");
}

TEST(ResultReader, ReadsHeisenbergResults) {
  json j = valid_result();
  j["group"] = "heisenberg";
  j["model"] = "oscillator";
  j["g0"] = {0, 0, 0};
  j["gT"] = {1, 0.5, 0.8};
  j["g"] = {{0, 0, 0}, {0.5, 0.2, 0.1}, {1, 0.5, 0.8}};
  const ResultRecord r = read_result(j);
  EXPECT_EQ(r.result.samples.points.cols(), 3);
  j["g"][1] = {0, 0, 0, 0, 0, 0, 0, 0, 0};  // so3 width in a heisenberg file
  expect_invalid([&] { read_result(j); }, "g[1] = (an array of 9 entries) must be a list of 3 numbers");
}

TEST(ResultReader, ReadsSE2AndSE3ResultsWithAFullInertia) {
  json j = valid_result();
  j["group"] = "se2";
  j["model"] = "free-body";
  j["inertia"] = {{1, 0.1, 0}, {0.1, 1, 0}, {0, 0, 0.5}};
  const json motion = {0, -1, 2, 1, 0, 3, 0, 0, 1};
  j["gT"] = motion;
  j["g"][2] = motion;
  EXPECT_EQ(std::get<GroupProblem>(read_result(j).problem).inertia.size(), 9u);
  j["g"][1] = {1, 0, 0, 0, 1, 0, 0, 0.5, 1};  // bottom row not [0 0 1]
  expect_invalid([&] { read_result(j); }, "g[1] = 1,0,0,0,1,0,0,0.5,1 has bottom row 0,0.5,1");

  json k = valid_result();
  k["group"] = "se3";
  k["model"] = "free-body";
  k["inertia"] = {1, 1, 1, 2, 3, 4};
  const json identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  k["g0"] = k["gT"] = identity;
  k["g"] = {identity, identity, identity};
  const json zero6 = {0, 0, 0, 0, 0, 0};
  k["v"] = k["mu"] = k["xi"] = {zero6, zero6, zero6};
  const ResultRecord r = read_result(k);
  EXPECT_EQ(r.result.samples.points.cols(), 16);
  EXPECT_EQ(r.result.samples.v.cols(), 6);
  k["v"][0] = {0, 0, 0};  // so3 width in an se3 file
  expect_invalid([&] { read_result(k); }, "v[0] = (an array of 3 entries) must be a list of 6 numbers");
}

// A deeply nested value where a number belongs is described, not dumped (no recursion).
TEST(ResultReader, DeeplyNestedValuesAreDescribedNotDumped) {
  json nested = 1.0;
  for (int i = 0; i < 10000; ++i) {
    json outer = json::array();
    outer.push_back(std::move(nested));
    nested = std::move(outer);
  }
  json j = valid_result();
  j["lambda"] = std::move(nested);
  expect_invalid([&] { read_result(j); }, "lambda = (an array of 1 entries) must be a number");
}

// What the writer writes, the reader reads back: every field, bit for bit (the JSON text holds
// the shortest round-trip form of each double), null for NaN both ways.
TEST(ResultFile, TheWriterAndTheReaderAgree) {
  const ResultRecord r = read_result(valid_result());
  ResultRecord changed = r;
  changed.result.action = std::numeric_limits<double>::quiet_NaN();
  changed.result.terminal_error = 1.0 / 3.0;
  changed.result.collocation = CollocationReport{17, 2.5e-9, std::numeric_limits<double>::quiet_NaN()};
  const json written = result_json(changed);
  EXPECT_TRUE(written["action"].is_null());
  EXPECT_FALSE(written.contains("group_defect"));
  EXPECT_EQ(written["side"], "left");
  const ResultRecord back = read_result_text(result_text(changed), kWhere);
  EXPECT_TRUE(std::isnan(back.result.action));
  EXPECT_EQ(back.result.terminal_error, 1.0 / 3.0);
  EXPECT_EQ(back.result.collocation->mesh_size, 17);
  EXPECT_EQ(back.result.samples.points, r.result.samples.points);
  EXPECT_EQ(back.result.samples.aux, r.result.samples.aux);
  EXPECT_EQ(std::get<GroupProblem>(back.problem).inertia, std::get<GroupProblem>(r.problem).inertia);
  EXPECT_EQ(result_json(back), written);
}

// The general kernel's records: a group with a Levi-Civita connection (Xi, n^2 numbers a row, the
// action along the samples) and a manifold (q, frame0).
TEST(ResultFile, GeneralRecordsTravel) {
  ResultRecord r = read_result(valid_result());
  auto& p = std::get<GroupProblem>(r.problem);
  p.connection = connections::ConnectionKind::LeviCivita;
  p.metric = {1, 2, 3};
  p.inertia = {2, 0, 0, 0, 3, 0, 0, 0, 4};
  r.result.lie_kernel = false;
  r.result.samples.aux = Eigen::MatrixXd::Constant(3, 9, 0.25);
  const json written = result_json(r);
  EXPECT_TRUE(written.contains("Xi") && !written.contains("xi") && written.contains("action"));
  EXPECT_EQ(written["inertia"].size(), 3u);  // n x n: as rows
  const ResultRecord back = read_result(written);
  EXPECT_FALSE(back.result.lie_kernel);
  ResultRecord coefficients = r;  // a record built by hand: its alpha is checked, not read out of bounds
  std::get<GroupProblem>(coefficients.problem).connection = connections::ConnectionKind::Coefficients;
  std::get<GroupProblem>(coefficients.problem).alpha = {1, 2};
  expect_invalid([&] { (void)result_json(coefficients); }, "alpha = 1,2 must have n^3 = 27 numbers");
  std::get<GroupProblem>(coefficients.problem).alpha.assign(27, 0.5);
  EXPECT_EQ(read_result(result_json(coefficients)).result.samples.aux, r.result.samples.aux);
  EXPECT_EQ(std::get<GroupProblem>(back.problem).metric, p.metric);
  EXPECT_EQ(back.result.samples.aux, r.result.samples.aux);

  ResultRecord m;
  ManifoldProblem sphere;
  sphere.mass = {1, 2};
  sphere.gravity = 0.5;
  sphere.q0 = {1, 0, 0};
  sphere.qT = {0, 1, 0};
  sphere.T = 2.0;
  sphere.N = 2;
  m.problem = sphere;
  m.result.samples.t = Eigen::Vector3d(0, 1, 2);
  m.result.samples.points = Eigen::MatrixXd::Constant(3, 3, 0.5);
  m.result.samples.v = m.result.samples.mu = Eigen::MatrixXd::Ones(3, 2);
  m.result.samples.aux = Eigen::MatrixXd::Zero(3, 4);
  m.result.frame0 = Eigen::MatrixXd::Identity(2, 3);
  const ResultRecord n = read_result(result_json(m));
  ASSERT_TRUE(n.on_manifold());
  EXPECT_EQ(std::get<ManifoldProblem>(n.problem).mass, (std::vector<double>{1, 2}));
  EXPECT_EQ(*n.result.frame0, *m.result.frame0);
  json bad = result_json(m);
  bad["model"] = "top";
  expect_invalid([&] { read_result(bad); }, "model = \"top\" is not a model of sphere");
}

// read_result (Python's cartan.load) reads what a failed solve leaves: no rows, or rows with
// null; a Lagrangian defined in Python by its name. read_solution (`cartan verify`) refuses them.
TEST(ResultFile, FailedResultsAndPythonModelsAreReadNotVerified) {
  json empty = valid_result();
  empty["status"] = "max-iterations";
  for (const char* key : {"t", "g", "v", "mu", "xi"}) empty[key] = json::array();
  EXPECT_EQ(api::read_result(empty, kWhere).result.samples.t.size(), 0);
  expect_invalid([&] { read_result(empty); }, "t = (an array of 0 entries) must be a list of at least 2 times");

  json nulls = valid_result();
  nulls["mu"][1][0] = nullptr;
  EXPECT_TRUE(std::isnan(api::read_result(nulls, kWhere).result.samples.mu(1, 0)));

  json python = valid_result();
  python["model"] = "python:MyBody";
  python["inertia"] = json::array();
  const ResultRecord r = api::read_result(python, kWhere);
  EXPECT_TRUE(std::get<GroupProblem>(r.problem).inertia.empty());
  expect_invalid([&] { read_and_verify(python); }, "model = \"python:MyBody\"");
  python["inertia"] = {1, 2};
  expect_invalid([&] { api::read_result(python, kWhere); }, "inertia = 1,2 must have 3 numbers");
}

}  // namespace
}  // namespace cartan::api
