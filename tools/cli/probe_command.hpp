// `swarm probe`: can a swarm be seen from here? A plain DDS participant (no certificate unless
// given one) joins a domain and partition for a few seconds, subscribes to the simulator's `clock`
// topic, offers a writer on the agents' `done` topic (it never writes on it), and says how many
// clock samples it read and how many of the swarm's endpoints matched its own.
//
//   swarm probe --domain 7 --partition swarm-123-456                 # a `swarm run` on this machine
//   swarm probe --discovery-server 127.0.0.1:11306 --domain 7 ...    # ... one with a discovery server
//   swarm probe --discovery-server discovery:11811 --profile /opt/swarm/share/deploy/fastdds_container.xml
//                                                                   # ... inside a compose network
//
// Exit status: 0 it read clock samples; 1 it read none (no swarm with that domain and partition is
// reachable from here, or a secure swarm refused it); 2 a bad flag, or a DDS participant that
// could not be created (the reason is named).
#pragma once

#include <ostream>
#include <string>

namespace CLI {
class App;
}

namespace swarm::tools {

struct ProbeOptions {
  int domain = 0;                  // DDS domain id (the compose files' default is 0)
  std::string partition = "swarm";  // DDS partition (the compose files' default)
  double seconds = 5.0;            // how long to listen
  std::string discovery_server;    // HOST:PORT; empty = $SWARM_DISCOVERY_SERVER, else simple discovery
  std::string profile;             // Fast DDS XML profile; empty = $SWARM_DDS_PROFILE, else the loopback one
  std::string security_dir;        // DDS-Security files (scripts/make-certs.sh); empty = no certificate
  std::string identity = "probe";  // the certificate's name in security_dir (IDENTITY.pem, IDENTITY.key)
  // Above any run's agent ids (0..robots+1), so the probe never takes a port a role needs, and
  // below 240, the ids a loopback run's simple discovery looks for.
  int participant_id = 200;
};

// Registers `swarm probe` and its flags on `app`; returns the subcommand (test `parsed()`).


// Runs the probe: a summary line on `out`, problems on `err`; the exit status as above.
int probe_command(const ProbeOptions& options, std::ostream& out, std::ostream& err);

}  // namespace swarm::tools
