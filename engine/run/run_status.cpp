#include "grainlab/run_status.hpp"

#include "grainlab/name_table.hpp"

namespace grainlab {
namespace {

constexpr NameTable<RunStatus, 6> kNames{{
    {RunStatus::Queued, "queued"},
    {RunStatus::Running, "running"},
    {RunStatus::Completed, "completed"},
    {RunStatus::Failed, "failed"},
    {RunStatus::Cancelled, "cancelled"},
    {RunStatus::Interrupted, "interrupted"},
}};

}  // namespace

std::string_view toString(RunStatus status) { return nameIn(kNames, status); }

std::optional<RunStatus> parseRunStatus(std::string_view text) { return valueIn(kNames, text); }

}  // namespace grainlab
