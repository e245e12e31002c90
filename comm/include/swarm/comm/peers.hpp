// What a process knows of the other DDS participants of its run while it starts: when simple
// discovery (SPDP) saw each one and, with DDS-Security, whether its authentication handshake
// finished. A start-up that stalls names the peer and the step it is stuck at with this (the
// lockstep's waits print it), instead of only the topic that never matched.
//
//   Participant p(options);                        // tracks its peers from creation on
//   std::string s = describe_peers(p.peers(), p.secure());
//   // "sim: authenticated at 0.41 s; gcs: discovered at 0.04 s, not authenticated 9.96 s later"
//
// Thread-safety: Bus::peers() may be called from any thread.
#pragma once

#include <string>
#include <vector>

namespace swarm::comm {

struct PeerState {
  enum class Step {
    Discovered,     // SPDP saw it; with security, its authentication has not finished
    Authenticated,  // DDS-Security authenticated it (only with security)
    Refused,        // DDS-Security refused it: its identity or handshake failed
    Gone,           // it left, or its participant lease ran out
  };
  std::string name;  // the remote participant's name: its process name (sim, gcs, leader-G, ...)
  Step step = Step::Discovered;
  double discovered_s = 0;  // seconds after this process's participant was made
  double step_s = 0;        // when it reached `step`
  double now_s = 0;         // when this state was read
};

// One line: every peer with its step and times. `secure`: whether authentication is expected
// (without it, Discovered is as far as a peer goes here). Empty peers: "no DDS participant discovered".
std::string describe_peers(const std::vector<PeerState>& peers, bool secure);

}  // namespace swarm::comm
