// The MPI schedule of a batch: rank 0 hands out one run at a time to whichever rank asks
// (dynamic scheduling: a slow run holds up no other), and works through the same queue on
// a thread of its own. Only rank 0's main thread calls MPI (MPI_THREAD_FUNNELED).
#ifdef GRAINLAB_HAS_MPI
#include <mpi.h>

#include <chrono>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>

#include "batch_execution.hpp"
#include "grainlab/studies/cluster.hpp"

namespace grainlab::studies {
namespace {

constexpr int kTagReport = 1;  // worker -> rank 0: ready, with the result of its last run if any
constexpr int kTagAssign = 2;  // rank 0 -> worker: the index of its next run, or -1 to stop
// Rank 0 polls for reports this often instead of blocking in MPI_Recv, which in Open MPI
// spins and would take a core from the runs.
constexpr auto kPollInterval = std::chrono::milliseconds(2);

std::string encodeReport(long index, const BatchRunResult& result) {
  return nlohmann::json{{"index", index}, {"status", toString(result.status)}, {"error", result.error},
                        {"wall_seconds", result.wallSeconds}}
      .dump();
}

void work(const std::vector<BatchRun>& runs, const BatchOptions& options, BatchProgress& progress) {
  long index = -1;
  BatchRunResult last;
  while (true) {
    const std::string report = encodeReport(index, last);
    MPI_Send(report.data(), static_cast<int>(report.size()), MPI_CHAR, 0, kTagReport, MPI_COMM_WORLD);
    MPI_Recv(&index, 1, MPI_LONG, 0, kTagAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (index < 0 || static_cast<size_t>(index) >= runs.size()) return;
    last = executeRun(runs[index], options.observer, progress);
  }
}

}  // namespace

void runDistributed(const std::vector<BatchRun>& runs, const std::vector<size_t>& pending, const BatchOptions& options,
                    BatchProgress& progress, std::vector<BatchRunResult>& results, const Cluster& cluster) {
  if (!cluster.isRoot()) {
    work(runs, options, progress);
    return;
  }
  std::mutex queueMutex;
  std::deque<size_t> queue(pending.begin(), pending.end());
  auto take = [&]() -> std::optional<size_t> {
    std::lock_guard lock(queueMutex);
    if (queue.empty()) return std::nullopt;
    const size_t k = queue.front();
    queue.pop_front();
    return k;
  };
  std::thread local([&] {
    while (const std::optional<size_t> k = take()) results[*k] = executeRun(runs[*k], options.observer, progress);
  });

  int working = cluster.size() - 1;
  while (working > 0) {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kTagReport, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) {
      std::this_thread::sleep_for(kPollInterval);
      continue;
    }
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    std::string text(static_cast<size_t>(length), '\0');
    MPI_Recv(text.data(), length, MPI_CHAR, status.MPI_SOURCE, kTagReport, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    const nlohmann::json report = nlohmann::json::parse(text);
    const long done = report.at("index").get<long>();
    if (done >= 0) {
      BatchRunResult& r = results[static_cast<size_t>(done)];
      r.status = parseRunStatus(report.at("status").get<std::string>()).value_or(RunStatus::Failed);
      r.error = report.at("error").get<std::string>();
      r.wallSeconds = report.at("wall_seconds").get<double>();
      progress.finished(runs[done].id + " (rank " + std::to_string(status.MPI_SOURCE) + ")", r.status, r.wallSeconds);
    }
    const std::optional<size_t> next = take();
    const long assign = next ? static_cast<long>(*next) : -1;
    if (next) progress.started(runs[*next].id + " (rank " + std::to_string(status.MPI_SOURCE) + ")");
    MPI_Send(&assign, 1, MPI_LONG, status.MPI_SOURCE, kTagAssign, MPI_COMM_WORLD);
    if (!next) --working;
  }
  local.join();
}

}  // namespace grainlab::studies
#endif
