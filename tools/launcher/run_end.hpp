// The last word on a run that did not end cleanly: every run directory ends with a metrics.json.
//
// When the run was stopped early (an interrupt, the --timeout, a process that failed), the
// simulator is asked to end it first (supervisor.hpp, ProcessSpec::ends_run) and the GCS then
// writes metrics.json as at max_ticks; record_early_end writes why into it ("ended") and marks it
// incomplete. When the GCS could not write it (it died, or the simulator did), it writes a
// partial one instead from what the run record holds up to its last whole frame:
//
//   {"schema_version": 6, "partial": true, "complete": false, "ended": "process gcs failed ...",
//    "ticks_run": 18, "phases": [{"name": "explore", "start_tick": 0, ...}], "record": "...", ...}
//
// read_metrics refuses a partial file with a message that says so (record/metrics.hpp).
#pragma once

#include <string>

#include "supervisor.hpp"
#include "swarm/proto/scenario.pb.h"

namespace swarm::tools {

// Why a run that `r` describes ended early, in one line ("" when r.ok).
[[nodiscard]] std::string early_end_reason(const SupervisorResult& r);

// Writes `reason` into RUN_DIR/metrics.json (see above). Never throws: a run directory that cannot
// be written is reported in the returned text ("" when all went well).
std::string record_early_end(const std::string& run_dir, const swarm::scenario::Scenario& scenario,
                             const std::string& reason);

}  // namespace swarm::tools
