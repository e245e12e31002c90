#include "probe_command.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <memory>
#include <thread>

#include "cli_numbers.hpp"
#include "command.hpp"
#include "observer_dds.hpp"
#include "swarm/comm/endpoint.hpp"
#include "swarm/comm/participant.hpp"
#include "swarm/comm/topology.hpp"
#include "swarm/config/scenario.hpp"

namespace swarm::tools {

Command add_probe(CLI::App& app) {
  auto options = std::make_shared<ProbeOptions>();
  ProbeOptions& o = *options;
  CLI::App* c = app.add_subcommand(
      "probe",
      "Can a swarm be seen from here? Listen to its clock topic for S seconds as a plain DDS participant "
      "and say how many samples arrived (exit 0: some, 1: none)");
  c->add_option("--domain", o.domain, "DDS domain id of the swarm")->capture_default_str()->check(number({0, 232}));
  c->add_option("--partition", o.partition, "DDS partition of the swarm")->capture_default_str();
  c->add_option("--seconds", o.seconds, "How long to listen")->capture_default_str()->check(number({0.1, 3600.0}));
  c->add_option("--discovery-server", o.discovery_server,
                "HOST:PORT of the swarm's Fast DDS discovery server (default: $SWARM_DISCOVERY_SERVER, else "
                "simple discovery)");
  c->add_option("--profile", o.profile,
                "Fast DDS XML profile (default: $SWARM_DDS_PROFILE, else deploy/fastdds_loopback.xml; in a "
                "container: deploy/fastdds_container.xml)");
  c->add_option("--security-dir", o.security_dir,
                "DDS-Security: a folder made by scripts/make-certs.sh holding this probe's certificate "
                "(default: none, as an outsider)");
  c->add_option("--identity", o.identity, "The certificate's name in --security-dir")->capture_default_str();
  c->add_option("--participant-id", o.participant_id,
                "RTPS participant id (fixes the ports; -1 = Fast DDS picks)")
      ->capture_default_str()
      ->check(number({-1, 239}));
  return {c, [options](std::ostream& out, std::ostream& err) { return probe_command(*options, out, err); }};
}

int probe_command(const ProbeOptions& o, std::ostream& out, std::ostream& err) {
  int samples = 0;
  int writers = 0;  // the most clock writers matched at once
  int readers = 0;  // the most readers the done writer matched at once
  try {
    comm::DdsOptions dds = observer_dds("swarm-probe", o.domain, o.partition, o.profile, o.discovery_server);
    dds.participant_id = o.participant_id;
    dds.security_dir = o.security_dir;
    dds.identity = o.identity;
    comm::Participant participant(dds);
    std::atomic<int> received{0};
    comm::Reader<msgs::Clock> clock(participant, comm::topic::kClock, [&](msgs::Clock&&) { ++received; });
    // With the agents' heartbeat QoS, so that an open swarm's simulator would match it. Never written.
    comm::Writer<msgs::Done> done(participant, comm::topic::kDone, comm::EndpointKind::Heartbeat);
    const auto until = std::chrono::steady_clock::now() +
                       std::chrono::milliseconds(static_cast<long long>(o.seconds * 1000.0));
    while (std::chrono::steady_clock::now() < until) {
      writers = std::max(writers, clock.matched());
      readers = std::max(readers, done.matched());
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    samples = received.load();
  } catch (const std::exception& e) {
    err << "swarm probe: " << e.what() << "\n";
    return 2;
  }
  out << "swarm probe: domain " << o.domain << ", partition " << o.partition << ", " << o.seconds
      << " s: " << samples << " clock samples from " << writers << " clock writers; " << readers
      << " done readers matched this probe's writer\n";
  if (samples > 0) return 0;
  err << "swarm probe: saw no clock sample. Is a swarm running with domain " << o.domain << " and partition '"
      << o.partition << "'? Does it use a discovery server (--discovery-server HOST:PORT)? A secure swarm "
      << "admits only participants with a certificate of its CA (--security-dir).\n";
  return 1;
}

}  // namespace swarm::tools
