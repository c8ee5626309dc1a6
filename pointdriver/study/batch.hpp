// Batch runs: every material (parameter set) on every path in one process, spread over threads.
// This is the entry point of the Johnson-Cook fitting (N parameter sets x M paths per objective
// evaluation) and of `pointdriver batch`.
//
// Runs are independent (a Path and an ElasticPlastic are read-only during a run; each run owns its
// state), so they are handed out one at a time to `threads` workers (std::thread, dynamic
// scheduling: runs of very different length balance). Results come back in job order whatever the
// thread count, and are identical to serial runs (each run is the same serial computation).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "pointdriver/driver/driver.hpp"

namespace impact::pointdriver {

/// One run of a batch: a path with a material (the path's own one is not used).
struct BatchJob {
  const Path* path = nullptr;
  const ElasticPlastic* model = nullptr;
};

struct BatchResult {
  std::size_t path = 0;    ///< index into the paths (N x M form; job index for run_batch_jobs)
  std::size_t model = 0;   ///< index into the models (N x M form; job index for run_batch_jobs)
  RunResult result;        ///< how the run ended (an exception in a sink ends it with its message)
  Row last;                ///< the last row sent (the initial row when no step was solved)
  double wall_time = 0.0;  ///< [s], of this run alone
  std::vector<Row> rows;   ///< every row, when BatchOptions::keep_rows
};

struct BatchOptions {
  int threads = 0;         ///< worker threads; 0: std::thread::hardware_concurrency()
  bool keep_rows = false;  ///< keep every row in BatchResult::rows (fitting residuals)
  /// Optional extra sink per job (e.g. a CSV writer), made and called on the worker running the
  /// job. Arguments: the job index and the job. Exceptions end that run, not the batch.
  std::function<RowSink(std::size_t, const BatchJob&)> make_sink;
  /// Optional, called with the job index when a run made by make_sink ends (also unsolved), e.g.
  /// to put its CSV in place; an exception marks the run not completed with its message.
  std::function<void(std::size_t)> close_sink;
};

/// Runs the jobs; result i belongs to job i.
std::vector<BatchResult> run_batch_jobs(const std::vector<BatchJob>& jobs,
                                        const BatchOptions& options = {});

/// Every model on every path: result p * models.size() + m is path p with model m.
std::vector<BatchResult> run_batch(const std::vector<Path>& paths,
                                   const std::vector<ElasticPlastic>& models,
                                   const BatchOptions& options = {});

}  // namespace impact::pointdriver
