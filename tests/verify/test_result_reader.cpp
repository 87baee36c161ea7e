// read_result: a valid document is read back; each bad document is rejected with
// std::invalid_argument naming the key (and row) of the first bad value, never another exception.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "result_reader.hpp"
#include "test_support.hpp"

namespace cartan::cli {
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
          {"xi", {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}}};
}

TEST(ResultReader, ReadsAValidDocument) {
  const ResultFile r = read_result(valid_result());
  EXPECT_EQ(r.problem.group, "so3");
  EXPECT_EQ(r.t.size(), 3);
  EXPECT_EQ(r.g.rows(), 3);
  EXPECT_EQ(r.g.cols(), 9);
  EXPECT_EQ(r.mu(2, 2), 4);
  EXPECT_EQ(r.problem.gT[1], -1);
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
    {"t too short", [] { return with("t", {0.0}); }, "t = (an array of 1 entries) must be a list of at least 2"},
    {"t not increasing", [] { return with("t", {0.0, 1.0, 1.0}); }, "t[2] = 1 is not greater than t[1]"},
    {"t not from 0", [] { return with("t", {0.5, 1.0, 2.0}); }, "t[0] = 0.5 must be 0"},
    {"t not to T", [] { return with("t", {0.0, 1.0, 1.5}); }, "t[2] = 1.5 must equal T = 2"},
    {"t with a string", [] { return with("t", {0.0, "1", 2.0}); }, "t[1] = \"1\" must be a number"},
    {"g too few rows", [] { json j = valid_result(); j["g"].erase(0); return j; }, "g = (an array of 2 entries) must have 3 rows"},
    {"g row not a rotation", [] { json j = valid_result(); j["g"][1][8] = 2; return j; }, "g[1] ="},
    {"g row short", [] { json j = valid_result(); j["g"][2] = {1, 0, 0}; return j; }, "g[2] = (an array of 3 entries)"},
    {"v row null", [] { json j = valid_result(); j["v"][1][2] = nullptr; return j; }, "v[1][2] = (null) must be a number"},
    {"mu an object", [] { return with("mu", json::object()); }, "mu = (an object with 0 keys)"},
    {"xi row bool", [] { json j = valid_result(); j["xi"][0] = true; return j; }, "xi[0] = (boolean)"},
    {"long string", [] { return with("group", std::string(1000, 'x')); }, "group = \"xxxxxxxxxx"},
};

TEST(ResultReader, RejectsEachBadDocumentNamingTheValue) {
  for (const auto& c : kBadCases) {
    SCOPED_TRACE(c.what);
    expect_invalid([&] { read_result(c.make()); }, {"cartan verify: ", c.fragment});
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
  const ResultFile r = read_result(j);
  EXPECT_EQ(r.g.cols(), 3);
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
  EXPECT_EQ(read_result(j).problem.inertia.size(), 9u);
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
  const ResultFile r = read_result(k);
  EXPECT_EQ(r.g.cols(), 16);
  EXPECT_EQ(r.v.cols(), 6);
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

}  // namespace
}  // namespace cartan::cli
