// Runs a set of child processes together and never leaves one behind: the `swarm run` launcher
// (and later `swarm experiment`, several runs at once, one call per run on its own thread).
//
// Each child is fork()ed, put in its own process group (so a terminal's Ctrl-C reaches only the
// supervisor, which then stops the children in order) and given PR_SET_PDEATHSIG = SIGKILL (so
// it dies with the thread that started it even if the supervisor is SIGKILLed), stdin /dev/null,
// stdout + stderr appended to its log file. With echo_stdout its stdout goes through a pipe that
// the supervisor copies, byte for byte, to its own stdout (a '\r' progress bar keeps working) and
// to the log.
//
// Ending: all children exit 0 => ok (services, see ProcessSpec::service, are stopped when the rest
// are done). The first child that exits non-zero or by a signal is the
// failure; the child that ends the run (ProcessSpec::ends_run) gets SIGTERM and up to
// kWindDown to end it, then every other child's process group gets SIGTERM, then SIGKILL after a
// grace period (3 s), and every child is reaped before returning. SIGINT/SIGTERM to the supervisor's process do
// the same (interrupted = true; a second signal skips the grace period), and so does the timeout
// (timed_out = true). On return no child, and no process in a child's group, is left running.
//
//   std::vector<swarm::tools::ProcessSpec> procs = {
//       {"sim", {"/path/bin/swarm-sim", "--run-dir", dir}, dir + "/logs/sim.log"}};
//   auto r = swarm::tools::run_processes(procs, std::chrono::seconds(600));
//   if (!r.ok) std::cerr << r.message << "\n";
//
// Thread-safety: calls from several threads at once are fine (each supervises only its own
// children; SIGINT/SIGTERM reach every call). While a call runs it owns the process's SIGINT,
// SIGTERM and SIGCHLD handlers and restores the previous ones when the last call ends. Do not reap
// children with waitpid(-1) elsewhere meanwhile.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace swarm::tools {

struct ProcessSpec {
  std::string name;               // for messages, e.g. "leader-0"
  std::vector<std::string> argv;  // argv[0] is the executable's path (execv: no PATH search)
  std::string log_path;           // created or truncated; its folder must exist
  bool echo_stdout = false;       // also copy the child's stdout to ours
  // Fault injection: this child is meant to be killed by SIGKILL; that death does not fail the run.
  bool killed_on_purpose = false;
  // ... and started again this long after that death (once), with `restart_argv` (its log goes
  // on, after a line that says so). Empty: not restarted.
  std::optional<std::chrono::milliseconds> restart_after;
  std::vector<std::string> restart_argv;
  // A service for the others (the DDS discovery server): it never ends by itself. Once every
  // other child has exited it gets SIGTERM (SIGKILL after the grace period), and how it ends then
  // does not count; ending before that fails the run like any child.
  bool service = false;
  // The child that ends the run for all (the simulator): when the run must stop early it alone
  // gets SIGTERM first and up to `wind_down` to end the run, so that the others finish their
  // reports and metrics.json is written; then the rest get SIGTERM and SIGKILL as above.
  bool ends_run = false;
};

struct SupervisorResult {
  bool ok = false;          // every child ran and exited 0
  std::string failed_name;  // the first child that failed (or could not start), else ""
  int exit_code = 0;        // its exit status, when it exited (else -1)
  int signal = 0;           // the signal that ended it, when one did (else 0)
  std::string log_path;     // its log
  bool interrupted = false;  // SIGINT or SIGTERM reached the supervisor
  bool timed_out = false;
  std::string message;  // one line for a person, e.g. "process leader-0 failed (exit code 3)"
  std::vector<pid_t> pids;  // the children's pids in spec order (0 = never started); all reaped
};

inline constexpr std::chrono::seconds kDefaultGracePeriod{3};
// How long a run may take to end itself when asked to stop: the GCS waits up to 15 s for the
// reports of robots that may be dead (gcs_node.hpp, finish). A --timeout can therefore be
// overrun by up to this and the grace period; an ender that dies meanwhile ends the wait at once.
inline constexpr std::chrono::seconds kWindDown{25};

// Runs every spec until all have exited (see the file comment). `timeout` <= 0 means none.
// Problems the caller can fix (a log that cannot be created, an executable that cannot be run)
// are a failed result naming the process, never an exception.
[[nodiscard]] SupervisorResult run_processes(
    const std::vector<ProcessSpec>& specs, std::chrono::seconds timeout,
    std::chrono::milliseconds grace_period = kDefaultGracePeriod);

}  // namespace swarm::tools
