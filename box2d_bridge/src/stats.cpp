#include "stats.hpp"

#include <algorithm>
#include <mutex>
#include <vector>

namespace dyop::box2d {
namespace detail {
namespace {

// Adds `from`'s counts to `to`.
void add_to(Stats& to, const ThreadCounters& from) {
  for (int m = 0; m < backend_count; ++m) {
    to.triangle_pairs[m] += from.triangle_pairs[m].get();
    for (int s = 0; s < skip_count; ++s) {
      const std::uint64_t skips = from.skipped[m][s].get();
      to.triangle_pairs[m] += skips;
      to.skipped[s] += skips;
    }
  }
  to.polygon_pairs += from.polygon_pairs.get();
  to.circle_pairs += from.circle_pairs.get();
  to.edge_pairs += from.edge_pairs.get();
  to.exact_pairs += from.exact_pairs.get();
  to.manifolds += from.manifolds.get();
  to.fallbacks += from.fallbacks.get();
  for (int s = 0; s < skip_count; ++s) to.skipped[s] += from.other_skipped[s].get();
  to.internal_edge_pairs += from.internal_edge_pairs.get();
  to.recycled += from.recycled.get();
  to.contacts += from.contacts.get();
}

void clear(ThreadCounters& c) {
  for (Counter& x : c.triangle_pairs) x.clear();
  c.polygon_pairs.clear();
  c.circle_pairs.clear();
  c.edge_pairs.clear();
  c.exact_pairs.clear();
  c.manifolds.clear();
  c.fallbacks.clear();
  for (auto& by_kind : c.skipped) {
    for (Counter& x : by_kind) x.clear();
  }
  for (Counter& x : c.other_skipped) x.clear();
  c.internal_edge_pairs.clear();
  c.recycled.clear();
  c.contacts.clear();
}

// The blocks of the live threads and the totals of the ended ones. Touched when a thread first
// counts or ends, and by `stats()` / `reset_stats()`: never by an evaluation.
struct AllThreads {
  std::mutex lock;
  std::vector<ThreadCounters*> live;
  Stats ended;
};

AllThreads& all_threads() {
  static AllThreads all;
  return all;
}

}  // namespace

ThreadCounters::ThreadCounters() {
  AllThreads& all = all_threads();
  const std::lock_guard<std::mutex> hold(all.lock);
  all.live.push_back(this);
}

ThreadCounters::~ThreadCounters() {
  AllThreads& all = all_threads();
  const std::lock_guard<std::mutex> hold(all.lock);
  add_to(all.ended, *this);
  all.live.erase(std::find(all.live.begin(), all.live.end(), this));
}

}  // namespace detail

const char* name(Skip s) {
  switch (s) {
    case Skip::Bounds:
      return "bounds";
    case Skip::WarmAxis:
      return "warm-axis";
  }
  return "unknown";
}

Stats stats() {
  detail::AllThreads& all = detail::all_threads();
  const std::lock_guard<std::mutex> hold(all.lock);
  Stats sum = all.ended;
  for (const detail::ThreadCounters* c : all.live) detail::add_to(sum, *c);
  return sum;
}

void reset_stats() {
  detail::AllThreads& all = detail::all_threads();
  const std::lock_guard<std::mutex> hold(all.lock);
  all.ended = Stats{};
  for (detail::ThreadCounters* c : all.live) detail::clear(*c);
}

}  // namespace dyop::box2d

namespace dyop::box2d {

void measurement::record_answers(std::vector<RecordedAnswer>* into) {
  detail::counters().answers = into;
}

}  // namespace dyop::box2d
