#pragma once
// Internal: the counters behind `dyop::box2d::stats()`, one block per thread.
//
// Box2D 2.4 steps separate worlds on separate threads, so an evaluation counts into its own
// thread's block and never into memory another thread writes: nothing on the evaluation path is
// shared, and nothing serialises the threads. Each field has one writer (its thread), so an
// increment is a relaxed load and store (plain moves on x86-64, no locked instruction); the
// atomics only make `stats()`'s reads from another thread well defined. `stats()` sums the
// blocks of live threads and what ended threads had counted.

#include <atomic>
#include <cstdint>

#include "dyop/box2d.hpp"
#include "dyop/box2d_measurement.hpp"

namespace dyop::box2d::detail {

// One counter written by one thread, read by any.
class Counter {
 public:
  void add(std::uint64_t n = 1) {
    value_.store(value_.load(std::memory_order_relaxed) + n, std::memory_order_relaxed);
  }
  std::uint64_t get() const { return value_.load(std::memory_order_relaxed); }
  void clear() { value_.store(0, std::memory_order_relaxed); }

 private:
  std::atomic<std::uint64_t> value_{0};
};

// `Stats`, field for field, as counters, but for the skips: a skip is counted once, by backend
// and kind (`skipped`), and `stats()` adds it to its backend's `triangle_pairs` (which here
// counts the other evaluations). Why: most evaluations in a falling scene are skips, and one
// increment fewer each shows in its narrow phase (measured: docs/measurements.md, "Choices in the
// code").
struct ThreadCounters {
  std::array<Counter, backend_count> triangle_pairs;
  Counter polygon_pairs;
  Counter circle_pairs;
  Counter edge_pairs;
  Counter exact_pairs;
  Counter manifolds;
  Counter fallbacks;
  std::array<std::array<Counter, skip_count>, backend_count> skipped;  // triangle pairs
  std::array<Counter, skip_count> other_skipped;  // the other families (also in their count)
  Counter internal_edge_pairs;
  Counter recycled;
  Counter contacts;
  // Where the thread records its triangle pairs' answers (`measurement::record_answers`), or
  // nullptr.
  std::vector<measurement::RecordedAnswer>* answers = nullptr;

  ThreadCounters();   // registers the block (see stats.cpp)
  ~ThreadCounters();  // adds it to the ended threads' totals and unregisters it
  ThreadCounters(const ThreadCounters&) = delete;
  ThreadCounters& operator=(const ThreadCounters&) = delete;
};

// The calling thread's block. Inline: every evaluation counts.
inline ThreadCounters& counters() {
  thread_local ThreadCounters mine;
  return mine;
}

}  // namespace dyop::box2d::detail
