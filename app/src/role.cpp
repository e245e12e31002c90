#include "swarm/app/role.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <iostream>
#include <thread>

namespace swarm::app {

void add_role_flags(CLI::App& app, RoleOptions& o, RoleKind kind) {
  app.add_option("--scenario", o.scenario_path, "scenario file (protobuf text format)")->required();
  app.add_option("--run-dir", o.run_dir, "run directory for outputs");
  app.add_option("--domain", o.domain, "DDS domain id of the run")->check(CLI::Range(0, 232));
  app.add_option("--partition", o.partition, "DDS partition of the run");
  app.add_option("--profile", o.profile, "Fast DDS XML profile (default: deploy/fastdds_loopback.xml)");
  app.add_option("--security-dir", o.security_dir,
                 "DDS-Security: the folder scripts/make-certs.sh made (this process's certificate is "
                 "NAME.pem there, NAME = sim, gcs, leader-G, member-G-I or members-G-F-L)");
  app.add_option("--dds-log", o.dds_log,
                 "security: print every DDS peer's discovery and authentication, Fast DDS's warnings and "
                 "its security log (default: $SWARM_DDS_LOG)")
      ->envname("SWARM_DDS_LOG")
      ->check(CLI::IsMember({"security"}));
  app.add_option("--discovery-server", o.discovery_server,
                 "HOST:PORT of a Fast DDS discovery server (default: $SWARM_DISCOVERY_SERVER, else simple discovery)");
  if (kind == RoleKind::Leader || kind == RoleKind::Member) {
    app.add_option("--group", o.group, "group id, from 0")->required();
  }
  if (kind == RoleKind::Member) {
    app.add_option("--index", o.indices,
                   "robot index inside the group, from 1 (0 is the leader); several (1,2,3) run that many robot "
                   "agents in this process, each with its own DDS endpoints")
        ->required()
        ->delimiter(',');
  }
  if (kind == RoleKind::Gcs) {
    app.add_option("--progress", o.progress, "progress display")->check(CLI::IsMember({"bar", "plain", "none"}));
    app.add_flag("--resume", o.resume,
                 "a restarted GCS: rebuild the state from RUN_DIR's journal, then rejoin the running mission");
  }
}

std::string process_name(RoleKind kind, int group, const std::vector<int>& indices) {
  const std::string g = std::to_string(group);
  switch (kind) {
    case RoleKind::Sim: return "sim";
    case RoleKind::Gcs: return "gcs";
    case RoleKind::Leader: return "leader-" + g;
    case RoleKind::Member: break;
  }
  return config::member_process_name(group, indices.front(), indices.back());
}

comm::LinkTable link_table(const swarm::scenario::Scenario& s, const comm::Topology& topology) {
  comm::LinkTable t;
  t.tick_seconds = s.tick_seconds();
  t.seed = s.seed();
  auto fill = [](comm::LinkParams& p, const swarm::scenario::Link& l) {
    p.delay_ticks = l.delay_ticks();
    p.jitter_ticks = l.jitter_ticks();
    p.loss = l.loss();
    p.bandwidth_bytes_per_s = l.bandwidth_bytes_per_s();
    p.retransmit_ticks = l.retransmit_ticks();
    p.delay_ms = l.delay_ms();
  };
  t.realtime = s.realtime();
  t.tick_ms = s.tick_ms();
  for (const auto& f : s.faults()) {
    const auto agent = topology.agent_named(f.agent());
    if (agent && f.has_cut_from_tick() && f.has_cut_to_tick()) t.cuts.push_back({*agent, f.cut_from_tick(), f.cut_to_tick()});
  }
  fill(t[comm::LinkClass::SimRobot], s.links().sim_robot());
  fill(t[comm::LinkClass::MemberLeader], s.links().member_leader());
  fill(t[comm::LinkClass::LeaderGcs], s.links().leader_gcs());
  return t;
}

RoleSetup load_role(const RoleOptions& o, RoleKind kind, const std::function<void(config::World&)>& complete_world) {
  RoleSetup setup;
  const auto scenario = config::load_scenario(o.scenario_path);
  const std::string dir = std::filesystem::path(o.scenario_path).parent_path().string();
  setup.world = config::resolve_world(scenario, dir.empty() ? "." : dir);
  if (complete_world) complete_world(setup.world);
  const auto& s = setup.world.scenario;
  setup.topology = comm::Topology(static_cast<int>(s.groups()), static_cast<int>(s.robots_per_group()),
                            config::leader_standbys(s));
  if ((kind == RoleKind::Leader || kind == RoleKind::Member) &&
      (o.group < 0 || o.group >= setup.topology.groups())) {
    throw config::ConfigError("--group " + std::to_string(o.group) + " is outside the scenario's groups 0.." +
                              std::to_string(setup.topology.groups() - 1));
  }
  for (const int index : o.indices) {
    if (kind == RoleKind::Member && (index < 1 || index >= setup.topology.robots_per_group())) {
      throw config::ConfigError("--index " + std::to_string(index) + " is outside 1.." +
                                std::to_string(setup.topology.robots_per_group() - 1) +
                                " (index 0 is the leader, run by swarm-leader)");
    }
  }
  if (kind == RoleKind::Member && std::set<int>(o.indices.begin(), o.indices.end()).size() != o.indices.size()) {
    throw config::ConfigError("--index names one robot twice");
  }
  setup.links = link_table(s, setup.topology);
  setup.dds.domain = o.domain;
  setup.dds.partition = o.partition;
  setup.dds.profile_path = o.profile.empty() ? config::dds_profile_path() : o.profile;
  setup.dds.discovery_server = o.discovery_server;
  setup.dds.security_dir = o.security_dir;
  setup.dds.log_security = o.dds_log == "security";
  setup.dds.identity = process_name(kind, o.group, o.indices);
  // The participant as its peers see it (their start-up logs name it): the process's name.
  setup.dds.name = setup.dds.identity;
  // The agent id (a member process: its first robot's) as the participant id: unique in the run.
  switch (kind) {
    case RoleKind::Sim: setup.dds.participant_id = setup.topology.sim(); break;
    case RoleKind::Gcs: setup.dds.participant_id = setup.topology.gcs(); break;
    case RoleKind::Leader: setup.dds.participant_id = setup.topology.leader(o.group); break;
    case RoleKind::Member: setup.dds.participant_id = setup.topology.robot(o.group, o.indices.front()); break;
  }
  keep_what_the_role_knows(setup, kind);
  return setup;
}

void keep_what_the_role_knows(RoleSetup& setup, RoleKind kind) {
  if (kind == RoleKind::Sim) return;
  if (config::any_map_given(setup.world.scenario)) setup.given_map = setup.world.truth;
  setup.world.truth = planner::OccupancyGrid();
}

void exit_after_work(const std::string& agent) {
  if (const char* a = std::getenv("SWARM_ABORT_AFTER_WORK"); a != nullptr && agent == a) std::abort();
  // A reliable reader acknowledges on its writer's next heartbeat (every 50 ms, the profile's
  // heartbeatPeriod). Leaving at once would leave the writer of what this process read last (the
  // simulator's report, read by the GCS) waiting out its whole acknowledgement timeout: 10 s
  // of every run's end, measured. A few heartbeat periods let the acknowledgements go out.
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  std::_Exit(0);
}

int run_role(CLI::App& app, int argc, char** argv, const std::string& role, const std::function<int()>& body) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "swarm-" << role << ": " << e.what() << "\n";
    return 2;
  }
  try {
    return body();
  } catch (const config::ConfigError& e) {
    std::cerr << "swarm-" << role << ": " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "swarm-" << role << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace swarm::app
