// The process edge shared by the four role executables (swarm-sim, swarm-gcs, swarm-leader,
// swarm-member): common flags, the scenario loaded once, and one error policy.
//
//   int main(int argc, char** argv) {
//     RoleOptions opt;
//     CLI::App app{"swarm-member: one robot"};
//     add_role_flags(app, opt, RoleKind::Member);
//     return run_role(app, argc, argv, "member", [&] { ...; return 0; });
//   }
//
// Exit codes: 0 done, 1 runtime failure (a peer died, DDS failed), 2 bad input (flags, scenario,
// map). Errors go to stderr as one line "swarm-<role>: <message>".
#pragma once

#include <functional>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "swarm/comm/link.hpp"
#include "swarm/comm/participant.hpp"
#include "swarm/comm/topology.hpp"
#include "swarm/config/scenario.hpp"

namespace swarm::comm {

enum class RoleKind { Sim, Gcs, Leader, Member };

struct RoleOptions {
  std::string scenario_path;
  std::string run_dir = ".";
  int domain = 0;
  std::string partition = "swarm";
  std::string profile;         // Fast DDS XML profile; empty = default_profile_path()
  int group = -1;              // leader, member
  int index = -1;              // member (1..robots_per_group-1)
  std::string progress = "plain";  // gcs: bar | plain | none
};

void add_role_flags(CLI::App& app, RoleOptions& options, RoleKind kind);

// Everything a role derives from its flags and the scenario.
struct RoleSetup {
  config::World world;
  Topology topology{1, 1};
  LinkTable links;
  DdsOptions dds;
};

// Loads and resolves the scenario, checks the role's ids against it. Throws config::ConfigError.
RoleSetup load_role(const RoleOptions& options, RoleKind kind, const std::string& name);

LinkTable link_table(const swarm::scenario::Scenario& scenario, const Topology& topology);

// Called once a role's work is done and acknowledged (its report sent, its outputs written).
// From then on an abort inside Fast DDS's own threads during teardown is logged and the process
// exits 0: Fast DDS 2.9.1 can hit an assertion in its remote-participant lease check
// (PDP::check_remote_participant_liveliness) while the run's other processes leave, which would
// otherwise fail a run that already finished correctly (seen in 1 of 45 runs). Likewise a
// teardown that hangs (eProsima/Fast-DDS#6502 describes a deadlock there; seen about 1 run in 45)
// is cut short: 10 s after this call the process exits 0 whatever DDS is doing.
void mark_work_done(const std::string& role);

// Parses argv, runs body, and maps exceptions to the exit codes above.
int run_role(CLI::App& app, int argc, char** argv, const std::string& role, const std::function<int()>& body);

}  // namespace swarm::comm
