#include "pointdriver/study/batch.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <thread>

namespace impact::pointdriver {

namespace {

void run_one(std::size_t index, const BatchJob& job, const BatchOptions& options,
             BatchResult& out) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  try {
    RowSink extra;
    if (options.make_sink) extra = options.make_sink(index, job);
    out.result = run_path(*job.path, *job.model, [&](const Row& row) {
      out.last = row;
      if (options.keep_rows) out.rows.push_back(row);
      if (extra) extra(row);
    });
    if (extra && options.close_sink) options.close_sink(index);
  } catch (const std::exception& e) {
    out.result.completed = false;
    out.result.error = e.what();
  }
  out.wall_time = std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace

std::vector<BatchResult> run_batch_jobs(const std::vector<BatchJob>& jobs,
                                        const BatchOptions& options) {
  std::vector<BatchResult> results(jobs.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) results[i].path = results[i].model = i;
  int threads =
      options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::clamp(threads, 1, static_cast<int>(std::max<std::size_t>(jobs.size(), 1)));
  std::atomic<std::size_t> next{0};
  const auto worker = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < jobs.size();) {
      run_one(i, jobs[i], options, results[i]);
    }
  };
  if (threads == 1) {
    worker();
    return results;
  }
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(threads - 1));
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  return results;
}

std::vector<BatchResult> run_batch(const std::vector<Path>& paths,
                                   const std::vector<ElasticPlastic>& models,
                                   const BatchOptions& options) {
  std::vector<BatchJob> jobs;
  jobs.reserve(paths.size() * models.size());
  for (const auto& p : paths) {
    for (const auto& m : models) jobs.push_back({&p, &m});
  }
  std::vector<BatchResult> results = run_batch_jobs(jobs, options);
  for (std::size_t i = 0; i < results.size(); ++i) {
    results[i].path = i / models.size();
    results[i].model = i % models.size();
  }
  return results;
}

}  // namespace impact::pointdriver
