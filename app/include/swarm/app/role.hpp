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
#include <vector>

#include <CLI/CLI.hpp>

#include "swarm/comm/link.hpp"
#include "swarm/comm/participant.hpp"
#include "swarm/comm/topology.hpp"
#include "swarm/config/scenario.hpp"

namespace swarm::app {

enum class RoleKind { Sim, Gcs, Leader, Member };

struct RoleOptions {
  std::string scenario_path;
  std::string run_dir = ".";
  int domain = 0;
  std::string partition = "swarm";
  std::string profile;         // Fast DDS XML profile; empty = config::dds_profile_path()
  std::string discovery_server;  // HOST:PORT; empty = comm::default_discovery_server()
  std::string security_dir;      // DDS-Security files (scripts/make-certs.sh); empty = none
  std::string dds_log;           // "security": comm::DdsOptions::log_security
  int group = -1;              // leader, member
  std::vector<int> indices;    // member: the robots this process runs (1..robots_per_group-1)
  std::string progress = "plain";  // gcs: bar | plain | none
  bool resume = false;             // gcs: a restarted process: replays its journal, then rejoins
};

void add_role_flags(CLI::App& app, RoleOptions& options, RoleKind kind);

// Everything a role derives from its flags and the scenario.
struct RoleSetup {
  // The simulator's world.truth is the map file's cells; every other role's is empty (a deployed
  // robot has no map file): it knows world.frame and learns the rest from its scans.
  config::World world;
  // The map file's cells when some phase gives the robots the map (config::map_given), else empty.
  planner::OccupancyGrid given_map;
  comm::Topology topology{1, 1};
  comm::LinkTable links;
  comm::DdsOptions dds;
};

// Loads and resolves the scenario, checks the role's ids against it. Throws config::ConfigError.
// `complete_world` runs on the world while it still holds the map file's cells, before the role
// keeps only what it may know (the task registry's resolve_mission: tasks::load_role).
RoleSetup load_role(const RoleOptions& options, RoleKind kind,
                    const std::function<void(config::World&)>& complete_world = {});

// Leaves a role other than the simulator only what it may know of the map: the frame always, the
// cells as given_map when the scenario gives the robots the map. load_role applies it.
void keep_what_the_role_knows(RoleSetup& setup, RoleKind kind);

// The process's name in a run, which its log, its certificate and `swarm run` use: "sim", "gcs",
// "leader-G", "member-G-I", or "members-G-F-L" for a member process of robots F..L.
std::string process_name(RoleKind kind, int group, const std::vector<int>& indices);

comm::LinkTable link_table(const swarm::scenario::Scenario& scenario, const comm::Topology& topology);

// Ends the process once its work is done and acknowledged (its report sent, its outputs written),
// with exit status 0 and WITHOUT tearing down Fast DDS: Fast DDS 2.9.1 can abort in its
// remote-participant lease check (PDP::check_remote_participant_liveliness) or deadlock
// (eProsima/Fast-DDS#6502) while the run's other processes leave (seen about 1 run in 45). A
// process that dies by a signal must fail the run (tools/launcher/supervisor.hpp), so the teardown, which
// has nothing left to do for a finished role, is skipped rather than its crash excused. Shared
// memory segments of an exited participant are reclaimed by Fast DDS (checked: /dev/shm does not
// grow over runs).
//
// Test hook: with $SWARM_ABORT_AFTER_WORK set to this agent's name (e.g. member-0-1) the process
// aborts here instead, as Fast DDS's teardown might: the run must then fail, naming the process
// and the signal (tests/integration/test_bad_input.cpp).
[[noreturn]] void exit_after_work(const std::string& agent);

// Parses argv, runs body, and maps exceptions to the exit codes above.
int run_role(CLI::App& app, int argc, char** argv, const std::string& role, const std::function<int()>& body);

}  // namespace swarm::app
