// The DDS domains of the tests that name theirs. Runs without --domain never take 41..48
// (tools/launcher/run_launch.hpp, kAutoDomains); each test that needs a known domain gets one of
// these to itself, so tests that ctest runs at the same time never meet in a domain (a run holds
// its domain with a lock and refuses one in use).
#pragma once

namespace swarm::test::domain {

inline constexpr int kViewAttach = 41;    // integration: swarm view --attach beside a swarm run
inline constexpr int kViewSecure = 43;    // integration: a secure run, watched and attached to
inline constexpr int kSecureRogue = 44;   // integration: a rogue participant beside a secure run
inline constexpr int kOpenRogue = 45;     // integration: the same rogue beside an open run
inline constexpr int kSecureLog = 46;     // integration: every role logs the peers it authenticated
inline constexpr int kLockstep = 47;      // comm: lockstep over real DDS, several participants

}  // namespace swarm::test::domain
