#pragma once
// `grainlab serve`: the REST + WebSocket service that queues runs, streams them live and keeps
// them in SQLite. The HTTP API is in docs/http-api.md, the stream in docs/stream-protocol.md.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "grainlab/run.hpp"

namespace grainlab::server {

/// What the server asks of a run: the scene, where to keep its checkpoints, and whether to
/// start it or continue it from its checkpoint (POST /api/runs/{id}/resume).
struct RunRequest {
  const Scene& scene;
  CheckpointPolicy checkpoint;
  bool resume = false;
  /// Where the run keeps its stages' ends (runScene's stageDirectory), for runs that start from
  /// them (start_from.run_id).
  std::string stageDirectory;
};

/// Runs one scene to the end, reporting to the observer. The server uses grainlab::runScene
/// (or resumeRun); tests inject their own.
using RunFunction = std::function<RunSummary(const RunRequest&, RunObserver&)>;

struct ServeOptions {
  std::string host = "127.0.0.1";       ///< address to bind; loopback unless told otherwise
  unsigned short port = 8080;           ///< 0 picks a free port (printed on stderr)
  std::string db = "data/grainlab.db";  ///< SQLite file; its parent directory is created
  std::string webRoot = "web";          ///< static files served at /
  int maxConcurrentRuns = 0;            ///< runs simulated at once; 0 = the machine's cores
  int maxQueuedRuns = 64;               ///< runs waiting beyond that; more get 429
  int maxParticles = 50000;             ///< per run (explicit plus generated); more get 503
  /// A scene estimated to run longer than this (s, RunCost::certainSeconds) gets 400 naming
  /// the field that drives its cost.
  double maxRunSeconds = 24 * 3600.0;
  std::size_t maxBodyBytes = 8u << 20;  ///< request body limit; larger bodies get 413
  int ioThreads = 2;                    ///< threads serving HTTP and WebSocket I/O
  double framesPerSecond = 20;          ///< live particle frames per run, at most
  int replayFrameEvery = 4;             ///< store a replay frame every N samples (and the last)
  /// Where each run keeps its checkpoint (run-ID.bin); empty = "<db>.checkpoints" beside the
  /// database. A run that stops early (server stopped or killed, wall-time limit) can be
  /// resumed from it. Its stages' ends are kept in run-ID/stages/ there, and the specimen a
  /// run started from in run-ID/specimen.checkpoint (start_from.run_id).
  std::string checkpointDir;
  /// On start-up, resume the runs that were interrupted and have a checkpoint (else they are
  /// only listed on stderr, for POST /api/runs/{id}/resume or the dashboard).
  bool resumeInterrupted = false;
  /// Who may use the server (docs/security.md). Tokens are read from these files, else from
  /// GRAINLAB_TOKEN and GRAINLAB_READ_ONLY_TOKEN; never from the command line. Bound to a
  /// non-loopback address with no token given, the server makes one and prints a login URL.
  std::string tokenFile;
  std::string readOnlyTokenFile;            ///< a token that may read and watch, not change
  std::vector<std::string> allowedHosts;    ///< Host names besides loopback and --host ("*": any)
  std::vector<std::string> allowedOrigins;  ///< page origins besides the server's own ("*": any)
  /// POST /api/sweeps/import reads only under this folder; empty = the endpoint is off.
  std::string importRoot;
  /// Replaces grainlab::runScene (tests); empty = the real engine.
  RunFunction runFunction;
};

/// Serves until SIGINT or SIGTERM, then stops the runs (they end `interrupted`), flushes the
/// database and returns 0. Returns non-zero with a message on stderr if it cannot start
/// (port in use, database unusable).
int serve(const ServeOptions& options);

}  // namespace grainlab::server
