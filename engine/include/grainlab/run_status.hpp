#pragma once
// How a run stands, or how it ended: one vocabulary for the engine, the CLI, the studies, the
// server and its database. The strings are those of summary.json and the HTTP API.
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

namespace grainlab {

enum class RunStatus {
  Queued,       ///< waiting for a run slot (server)
  Running,      ///< being simulated (server)
  Completed,    ///< every stage done
  Failed,       ///< stopped by an error (a diverging simulation, a full disk, a limit), which says why
  Cancelled,    ///< stopped on request; not to be continued
  Interrupted,  ///< stopped cleanly or killed; resumable from its checkpoint if it has one
};

/// "queued", "running", "completed", "failed", "cancelled" or "interrupted".
std::string_view toString(RunStatus status);
/// The status a string names; nothing for any other string.
std::optional<RunStatus> parseRunStatus(std::string_view text);
/// The run is not going on (it may still be resumed, which queues it again).
constexpr bool hasEnded(RunStatus s) { return s != RunStatus::Queued && s != RunStatus::Running; }

inline std::ostream& operator<<(std::ostream& os, RunStatus s) { return os << toString(s); }

}  // namespace grainlab
