// The options from their words (principle/options.hpp): the one translation that `cartan solve`,
// cartan.solve and cartan.solve_general call. Its defaults are SolveOptions' own, every word of
// the vocabulary reads back as itself, and bad words and orders are named with the caller's where.
#include <gtest/gtest.h>

#include "cartan/principle/options.hpp"
#include "test_support.hpp"

namespace cartan {
namespace {

using cartan::testing::expect_invalid;

TEST(OptionWords, TheDefaultsAreTheLibrarys) {
  const SolveOptions fresh;
  const SolveOptions o = solve_options(OptionWords{}, "test");
  EXPECT_EQ(o.method, fresh.method);
  EXPECT_EQ(o.continuation, fresh.continuation);
  EXPECT_EQ(o.order, fresh.order);
  EXPECT_EQ(o.tol, fresh.tol);
  EXPECT_EQ(o.max_iterations, fresh.max_iterations);
  EXPECT_EQ(o.samples, fresh.samples);
  EXPECT_FALSE(o.segments || o.lambda_start || o.max_nodes || o.time_limit);
}

TEST(OptionWords, EveryWordReadsBackAsItself) {
  for (const auto& word : enum_words<Method>()) {
    OptionWords w;
    w.method = word;
    EXPECT_EQ(to_string(solve_options(w, "test").method), word);
  }
  for (const auto& word : enum_words<Continuation>()) {
    OptionWords w;
    w.continuation = word;
    EXPECT_EQ(to_string(solve_options(w, "test").continuation), word);
  }
  OptionWords w;
  w.order = 2;
  w.segments = 4;
  w.lambda_start = 0.25;
  w.samples = 7;
  w.max_nodes = 900;
  w.time_limit = 2.5;
  const SolveOptions o = solve_options(w, "test");
  EXPECT_EQ(o.order, SchemeOrder::Second);
  EXPECT_EQ(o.segments, 4);
  EXPECT_EQ(o.lambda_start, 0.25);
  EXPECT_EQ(o.samples, 7);
  EXPECT_EQ(o.max_nodes, 900);
  EXPECT_EQ(o.time_limit, 2.5);
}

TEST(OptionWords, BadWordsAndOrdersAreNamedWithTheCallersWhere) {
  OptionWords w;
  w.method = "guessing";
  expect_invalid([&] { (void)solve_options(w, "cartan.solve"); }, {"cartan.solve: method = \"guessing\" is not one of: auto"});
  w = OptionWords{};
  w.continuation = "t";
  expect_invalid([&] { (void)solve_options(w, "cartan solve"); }, {"cartan solve: continuation = \"t\""});
  w = OptionWords{};
  w.order = 3;
  expect_invalid([&] { (void)solve_options(w, "cartan.solve_general"); }, {"cartan.solve_general: order = 3 must be 1 or 2"});
}

}  // namespace
}  // namespace cartan
