// The host half of validation/device_batch (README.md): calls that a check makes one at a time,
// answered from a cache of values a device computes in batches. A call whose query is not cached
// is recorded and answered provisionally (zeros, or the caller's prediction); between runs of the
// check every recorded query is evaluated in one batch, and the check runs again until a run finds
// every value cached, so the last run rests on device values alone. This takes the check to be
// deterministic given its values, so each run follows the true path at least one call further.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace tr::device_batch {

struct EvaluatorPolicy {
  std::string label;  // names the client in errors
  // Runs that answer a miss provisionally; every later run evaluates each miss at once (one
  // device submission each), so it completes on device values: for checks that may keep
  // asking for new values run after run (an adaptive quadrature refining where the values say).
  int speculative_runs = std::numeric_limits<int>::max();
  // A check still missing values after this many runs is an error.
  int max_runs = std::numeric_limits<int>::max();
};

struct EvaluatorStats {
  std::size_t evaluations = 0;  // queries evaluated on the device
  std::size_t batches = 0;      // calls of the evaluate hook
  std::size_t immediate = 0;    // of them, misses evaluated at once (past speculative_runs)
  std::size_t max_runs = 0;     // the most runs one check needed
  double device_seconds = 0.0;  // in the evaluate hook
};

// Query and Result are trivially copyable; a query is keyed by its bytes, so padding must be
// zeroed by whoever builds it.
template <typename Query, typename Result>
class MemoizingEvaluator {
  static_assert(std::is_trivially_copyable_v<Query> && sizeof(Query) % 4 == 0);
  static_assert(std::is_trivially_copyable_v<Result>);

 public:
  // Computes results[0, count) of queries[0, count) on the device.
  using Evaluate = std::function<void(const Query* queries, std::size_t count, Result* results)>;
  // Sees every evaluated batch: the device's results beside the provisional answers the runs
  // were given meanwhile (in immediate mode, those the caller would have given).
  using Observe = std::function<void(const Query* queries, const Result* device,
                                     const Result* provisional, std::size_t count)>;

  MemoizingEvaluator(Evaluate evaluate, EvaluatorPolicy policy, Observe observe = nullptr)
      : evaluate_(std::move(evaluate)), observe_(std::move(observe)), policy_(std::move(policy)) {}

  // The device's value of q. On a miss, records q and returns provisional() (a callable giving a
  // Result), or in immediate mode evaluates q at once.
  template <typename Provisional>
  Result lookup(const Query& q, Provisional&& provisional);
  // A miss answers zeros.
  Result lookup(const Query& q) {
    return lookup(q, [] { return Result{}; });
  }

  // Runs `check` until a run finds every value cached (see EvaluatorPolicy). The cache holds one
  // check's values: it starts empty and is dropped afterwards, which bounds the memory.
  void run_check(const std::function<void()>& check);

  // What was measured since the last call; resets it.
  EvaluatorStats take_stats() { return std::exchange(stats_, EvaluatorStats()); }
  const EvaluatorStats& stats() const { return stats_; }

 private:
  static constexpr uint32_t kNone = 0xffffffffu;
  static constexpr uint64_t kEmptySlot = ~uint64_t(0);

  static uint64_t hash_of(const Query& q);
  static bool same(const Query& a, const Query& b) { return std::memcmp(&a, &b, sizeof(a)) == 0; }
  uint32_t find(const Query& q) const;              // among the evaluated queries
  void index(std::size_t first, std::size_t last);  // adds queries_[first, last) to table_
  void evaluate_pending();
  void forget();

  Evaluate evaluate_;
  Observe observe_;
  EvaluatorPolicy policy_;
  EvaluatorStats stats_;
  // Every query of the current check and its result (provisional from `evaluated_` on), and an
  // open-addressing table (linear probing, load <= 1/2) of the evaluated ones' positions: a slot
  // holds the upper 32 bits of the query's hash << 32 | its position, the tag sparing most probes
  // a look at the query. Misses join the table only once evaluated, in one pass over the batch: a
  // query repeated before then is recorded (and evaluated) twice, which costs less than a probe
  // per miss while the table is empty or far behind.
  std::vector<Query> queries_;
  std::vector<Result> results_;
  std::size_t evaluated_ = 0;
  std::vector<uint64_t> table_;
  // A check calls in much the same order on every run: the positions the previous run visited
  // (its tape) are tried in order first, without hashing.
  std::vector<uint32_t> tape_, previous_tape_;
  std::vector<uint32_t> tape_index_;  // position -> its first call in previous_tape_
  std::size_t cursor_ = 0;            // the next call of previous_tape_ to try
  bool immediate_ = false;
};

template <typename Query, typename Result>
uint64_t MemoizingEvaluator<Query, Result>::hash_of(const Query& q) {
  // FNV-1a over the words, then the splitmix64 finalizer.
  uint32_t words[sizeof(Query) / 4];
  std::memcpy(words, &q, sizeof(q));
  uint64_t h = 1469598103934665603ull;
  for (uint32_t w : words) h = (h ^ w) * 1099511628211ull;
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ull;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebull;
  return h ^ (h >> 31);
}

template <typename Query, typename Result>
uint32_t MemoizingEvaluator<Query, Result>::find(const Query& q) const {
  if (table_.empty()) return kNone;
  const std::size_t mask = table_.size() - 1;
  const uint64_t hash = hash_of(q);
  const uint32_t tag = uint32_t(hash >> 32);
  for (std::size_t slot = hash & mask;; slot = (slot + 1) & mask) {
    const uint64_t e = table_[slot];
    if (e == kEmptySlot) return kNone;
    if (uint32_t(e >> 32) == tag && same(queries_[uint32_t(e)], q)) return uint32_t(e);
  }
}

template <typename Query, typename Result>
void MemoizingEvaluator<Query, Result>::index(std::size_t first, std::size_t last) {
  // Hashes first, then inserts with the slot of a later query prefetched: the table is far larger
  // than the caches.
  constexpr std::size_t kAhead = 16;
  std::vector<uint64_t> hashes(last - first);
  for (std::size_t p = first; p < last; ++p) hashes[p - first] = hash_of(queries_[p]);
  const std::size_t mask = table_.size() - 1;
  for (std::size_t i = 0; i < hashes.size(); ++i) {
    if (i + kAhead < hashes.size()) __builtin_prefetch(&table_[hashes[i + kAhead] & mask], 1);
    const uint32_t position = uint32_t(first + i);
    const uint32_t tag = uint32_t(hashes[i] >> 32);
    for (std::size_t slot = hashes[i] & mask;; slot = (slot + 1) & mask) {
      uint64_t& e = table_[slot];
      if (e == kEmptySlot) {
        e = uint64_t(tag) << 32 | position;
        break;
      }
      // A duplicate keeps the first.
      if (uint32_t(e >> 32) == tag && same(queries_[uint32_t(e)], queries_[position])) break;
    }
  }
}

template <typename Query, typename Result>
template <typename Provisional>
Result MemoizingEvaluator<Query, Result>::lookup(const Query& q, Provisional&& provisional) {
  if (cursor_ < previous_tape_.size()) {
    const uint32_t p = previous_tape_[cursor_];
    if (same(queries_[p], q)) {
      ++cursor_;
      tape_.push_back(p);
      return results_[p];
    }
  }
  uint32_t p = find(q);
  if (p != kNone) {
    // Calls were added or dropped since the previous run: continue its tape after this call.
    if (p < tape_index_.size() && tape_index_[p] != kNone) cursor_ = tape_index_[p] + 1;
    tape_.push_back(p);
    return results_[p];
  }
  if (queries_.size() + 1 >= kNone)
    throw std::runtime_error(policy_.label + ": too many queries in one check");
  p = uint32_t(queries_.size());
  queries_.push_back(q);
  results_.push_back(provisional());
  tape_.push_back(p);
  if (immediate_) {
    ++stats_.immediate;
    evaluate_pending();
  }
  return results_[p];
}

template <typename Query, typename Result>
void MemoizingEvaluator<Query, Result>::evaluate_pending() {
  const std::size_t count = queries_.size() - evaluated_;
  auto start = std::chrono::steady_clock::now();
  std::unique_ptr<Result[]> device(new Result[count]);  // uninitialized: the device writes all
  evaluate_(queries_.data() + evaluated_, count, device.get());
  stats_.device_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats_.evaluations += count;
  ++stats_.batches;
  if (observe_) observe_(queries_.data() + evaluated_, device.get(), &results_[evaluated_], count);
  std::copy(device.get(), device.get() + count, results_.begin() + evaluated_);
  const std::size_t first = evaluated_;
  evaluated_ = queries_.size();
  if (2 * evaluated_ > table_.size()) {
    std::size_t size = 1024;
    while (size < 4 * evaluated_) size *= 2;
    table_.assign(size, kEmptySlot);
    index(0, evaluated_);
  } else {
    index(first, evaluated_);
  }
}

template <typename Query, typename Result>
void MemoizingEvaluator<Query, Result>::forget() {
  queries_.clear();
  results_.clear();
  evaluated_ = 0;
  table_.clear();
  tape_.clear();
  previous_tape_.clear();
  tape_index_.clear();
}

template <typename Query, typename Result>
void MemoizingEvaluator<Query, Result>::run_check(const std::function<void()>& check) {
  forget();
  try {
    for (int run = 1;; ++run) {
      std::swap(tape_, previous_tape_);
      tape_.clear();
      cursor_ = 0;
      tape_index_.assign(queries_.size(), kNone);
      for (std::size_t i = previous_tape_.size(); i-- > 0;)
        tape_index_[previous_tape_[i]] = uint32_t(i);
      immediate_ = run > policy_.speculative_runs;
      check();
      if (evaluated_ == queries_.size()) {
        stats_.max_runs = std::max(stats_.max_runs, std::size_t(run));
        break;
      }
      if (run >= policy_.max_runs)
        throw std::runtime_error(policy_.label + ": a check still asked for new values after " +
                                 std::to_string(policy_.max_runs) + " runs");
      evaluate_pending();
    }
  } catch (...) {
    forget();
    throw;
  }
  forget();
}

}  // namespace tr::device_batch
