#pragma once
// Rows of an image computed on every hardware thread, progress reported from the calling thread.
#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "scene/generation_progress.hpp"

namespace glintlab {

/// Calls row(y, worker) once for every y < rows; `worker` < workers is the calling thread's index
/// into per-thread scratch. Rows are independent, so the result does not depend on the thread count.
/// Reports progress in rows as `what`; rethrows the first exception a row threw.
inline void for_each_row(int rows, int workers, const std::function<void(int y, int worker)>& row,
                         const std::string& what) {
  constexpr int kChunk = 8;
  std::atomic<int> next{0}, done{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto work = [&](int worker, bool report) {
    try {
      for (int y0; (y0 = next.fetch_add(kChunk)) < rows;) {
        const int y1 = std::min(rows, y0 + kChunk);
        for (int y = y0; y < y1; ++y) row(y, worker);
        const int now = done.fetch_add(y1 - y0) + (y1 - y0);
        if (report) report_generation_progress(what, now, rows);
      }
    } catch (...) {
      const std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next = rows;  // the others stop at their next chunk
    }
  };
  report_generation_progress(what, 0, rows);
  std::vector<std::thread> threads;
  for (int w = 1; w < workers; ++w) threads.emplace_back(work, w, false);
  work(0, true);
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
  report_generation_progress(what, rows, rows);
}

/// The threads worth starting for `rows` rows: the hardware's, at most one per 64 rows.
inline int row_workers(int rows) {
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::clamp(rows / 64, 1, std::min(hardware, 64));
}

}  // namespace glintlab
