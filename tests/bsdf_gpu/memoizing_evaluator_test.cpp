// validation/device_batch's MemoizingEvaluator on the host: an "evaluate" hook computing a known
// function stands in for the device, and a bisection stands in for a check whose every call
// depends on the values before it, so a run answered provisionally strays from the true path.
#include "memoizing_evaluator.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace tr::device_batch {
namespace {

struct Query {
  float x;
};
struct Result {
  float y;
};
using Evaluator = MemoizingEvaluator<Query, Result>;

float f(float x) { return x * x - 2.0f; }

Evaluator::Evaluate host_device(std::size_t* evaluated) {
  return [evaluated](const Query* queries, std::size_t count, Result* results) {
    for (std::size_t i = 0; i < count; ++i) results[i].y = f(queries[i].x);
    *evaluated += count;
  };
}

// The root of f in [1, 2] after `steps` halvings, reading f through `value`.
template <typename Value>
float bisect(int steps, Value value) {
  float lo = 1.0f, hi = 2.0f;
  for (int i = 0; i < steps; ++i) {
    const float mid = 0.5f * (lo + hi);
    (value(mid) < 0.0f ? lo : hi) = mid;
  }
  return 0.5f * (lo + hi);
}

constexpr int kSteps = 12;

TEST(MemoizingEvaluator, ProvisionalZerosConvergeToTheDevicePath) {
  std::size_t evaluated = 0;
  Evaluator memo(host_device(&evaluated), EvaluatorPolicy{"test"});
  float root = 0.0f;
  memo.run_check([&] { root = bisect(kSteps, [&](float x) { return memo.lookup({x}).y; }); });
  EXPECT_EQ(root, bisect(kSteps, f));
  const EvaluatorStats s = memo.stats();
  // A zero reads as "not below zero": a run strays at the first cached value below zero.
  EXPECT_GT(s.max_runs, 2u);
  EXPECT_EQ(s.batches, s.max_runs - 1);
  EXPECT_EQ(s.evaluations, evaluated);
  EXPECT_EQ(s.immediate, 0u);
}

TEST(MemoizingEvaluator, ExactPredictionsNeedOneBatchAndTheObserverSeesThem) {
  std::size_t evaluated = 0, observed = 0, differing = 0;
  Evaluator memo(
      host_device(&evaluated), EvaluatorPolicy{"test"},
      [&](const Query*, const Result* device, const Result* provisional, std::size_t count) {
        observed += count;
        for (std::size_t i = 0; i < count; ++i) differing += device[i].y != provisional[i].y;
      });
  float root = 0.0f;
  memo.run_check([&] {
    root =
        bisect(kSteps, [&](float x) { return memo.lookup({x}, [x] { return Result{f(x)}; }).y; });
  });
  EXPECT_EQ(root, bisect(kSteps, f));
  EXPECT_EQ(memo.stats().max_runs, 2u);
  EXPECT_EQ(memo.stats().batches, 1u);
  EXPECT_EQ(observed, std::size_t(kSteps));
  EXPECT_EQ(differing, 0u);
}

TEST(MemoizingEvaluator, PastTheSpeculativeRunsMissesAreEvaluatedAtOnce) {
  std::size_t evaluated = 0;
  Evaluator memo(host_device(&evaluated), EvaluatorPolicy{"test", 2});
  float root = 0.0f;
  memo.run_check([&] { root = bisect(kSteps, [&](float x) { return memo.lookup({x}).y; }); });
  EXPECT_EQ(root, bisect(kSteps, f));
  const EvaluatorStats s = memo.take_stats();
  EXPECT_EQ(s.max_runs, 3u);
  EXPECT_GT(s.immediate, 0u);
  EXPECT_EQ(s.batches, 2u + s.immediate);
  EXPECT_EQ(memo.stats().batches, 0u);  // take_stats() reset them
}

TEST(MemoizingEvaluator, ACheckStillMissingAfterMaxRunsIsAnError) {
  std::size_t evaluated = 0;
  Evaluator memo(host_device(&evaluated),
                 EvaluatorPolicy{"test", std::numeric_limits<int>::max(), 3});
  auto check = [&] { bisect(kSteps, [&](float x) { return memo.lookup({x}).y; }); };
  EXPECT_THROW(memo.run_check(check), std::runtime_error);
  // The cache was dropped: a short check afterwards starts from nothing.
  memo.take_stats();
  float root = 0.0f;
  memo.run_check([&] { root = bisect(2, [&](float x) { return memo.lookup({x}).y; }); });
  EXPECT_EQ(root, bisect(2, f));
  EXPECT_EQ(memo.stats().evaluations, 2u);
}

TEST(MemoizingEvaluator, RepeatedAndReorderedCallsAreServedFromTheCache) {
  std::size_t evaluated = 0;
  Evaluator memo(host_device(&evaluated), EvaluatorPolicy{"test"});
  // Each run asks for the same 2000 values, the later runs in another order and with extra calls
  // in between, so the tape and the table both answer.
  int run = 0;
  std::vector<float> seen;
  memo.run_check([&] {
    ++run;
    seen.clear();
    for (int i = 0; i < 2000; ++i) {
      const int k = run == 1 ? i : (i * 7) % 2000;
      seen.push_back(memo.lookup({float(k)}).y);
      if (run > 1 && i % 100 == 0) memo.lookup({float(k)});
    }
  });
  EXPECT_EQ(run, 2);
  EXPECT_EQ(evaluated, 2000u);
  for (int i = 0; i < 2000; ++i) EXPECT_EQ(seen[i], f(float((i * 7) % 2000)));
}

}  // namespace
}  // namespace tr::device_batch
