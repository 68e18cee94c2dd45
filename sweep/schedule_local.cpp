#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include "sweep/schedule.hpp"

namespace gearsim::sweep {

void count_finished(Progress& p, const CaseRecord& r, std::chrono::steady_clock::time_point start, const ProgressFn& report) {
  ++p.done;
  p.failed += r.status != CaseStatus::Completed;
  p.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  p.eta_s = p.elapsed_s / static_cast<double>(p.done) * static_cast<double>(p.to_run - p.done);
  p.last = &r;
  if (report) report(p);
}

std::vector<CaseRecord> run_local(const std::vector<CaseJob>& jobs, int parallel, const CaseContext& ctx, const ProgressFn& progress) {
  const auto start = std::chrono::steady_clock::now();
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::vector<CaseRecord> records;
  Progress p;
  p.to_run = jobs.size();
  const auto worker = [&] {
    while (true) {
      if (ctx.stop && ctx.stop() != 0) return;
      const std::size_t i = next++;
      if (i >= jobs.size()) return;
      CaseRecord r = run_case(jobs[i], ctx);
      const std::lock_guard<std::mutex> lock(mutex);
      records.push_back(std::move(r));
      count_finished(p, records.back(), start, progress);
    }
  };
  std::vector<std::thread> threads;
  const std::size_t n = std::min<std::size_t>(static_cast<std::size_t>(std::max(parallel, 1)), std::max<std::size_t>(jobs.size(), 1));
  for (std::size_t t = 0; t < n; ++t) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
  return records;
}

}  // namespace gearsim::sweep
