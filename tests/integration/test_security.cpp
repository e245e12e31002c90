// DDS-Security over real DDS (`swarm run --secure`): a participant without a certificate of the
// run's CA, in the run's domain and partition, reads nothing and its writes reach nobody. The same
// rogue, against the same run without --secure, does read the clock: the control that shows it
// would have seen the traffic.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "run_swarm.hpp"
#include "swarm/comm/endpoint.hpp"
#include "swarm/comm/participant.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm_test/domains.hpp"

namespace swarm::test {
namespace {

struct RogueView {
  int clock_samples = 0;
  int matched_writers = 0;  // the most clock writers it ever matched
  int matched_readers = 0;  // the most readers its own "done" writer ever matched
};

// Runs `swarm run` (real time, so it lasts seconds) with `flags` while a plain participant joins
// its domain and partition, subscribes to the clock and offers to write Done messages.
RogueView run_with_a_rogue(const std::string& name, const std::string& flags, int domain) {
  const std::string dir = fresh_dir(name);
  const std::string partition = "rogue-test-" + name;
  CommandResult result;
  std::thread run([&] {
    result = run_swarm("run --map small --groups 1 --robots-per-group 2 --realtime --tick-ms 20 --max-ticks 250 "
                       "--domain " + std::to_string(domain) + " --partition " + partition + " " + flags +
                       " --out " + dir + "/run");
  });
  RogueView view;
  {
    // Participant id 200: far above the run's (its agent ids 0..3), so no port is shared.
    comm::Participant rogue(
        comm::DdsOptions{.domain = domain, .partition = partition, .name = "rogue",
                         .profile_path = config::dds_profile_path(), .participant_id = 200});
    std::atomic<int> samples{0};
    comm::Reader<msgs::Clock> clock(rogue, "clock", [&](msgs::Clock&&) { ++samples; });
    comm::Writer<msgs::Done> done(rogue, "done");
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(12);
    while (std::chrono::steady_clock::now() < until) {
      view.matched_writers = std::max(view.matched_writers, clock.matched());
      view.matched_readers = std::max(view.matched_readers, done.matched());
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    view.clock_samples = samples.load();
  }
  run.join();
  EXPECT_EQ(result.exit_code, 0) << result.output;
  return view;
}

TEST(Security, ARogueParticipantSeesNothingOfASecureRun) {
  const RogueView secure = run_with_a_rogue("secure", "--secure", domain::kSecureRogue);
  EXPECT_EQ(secure.clock_samples, 0);
  EXPECT_EQ(secure.matched_writers, 0);
  EXPECT_EQ(secure.matched_readers, 0);
  EXPECT_TRUE(std::filesystem::exists(std::string(SWARM_TEST_RUNS_DIR) + "/secure/run/security/gcs.pem"));

  // The control: without --secure the same rogue reads the clock.
  const RogueView open = run_with_a_rogue("insecure", "--discovery simple", domain::kOpenRogue);
  EXPECT_GT(open.clock_samples, 0);
  EXPECT_GT(open.matched_writers, 0);
}

// With SWARM_DDS_LOG=security every role logs, by name, each peer it authenticated: what a
// stalled secure start-up is diagnosed from (a peer discovered but never authenticated).
TEST(Security, EachRoleLogsEveryPeerItAuthenticated) {
  const std::string dir = fresh_dir("secure-log");
  ::setenv("SWARM_DDS_LOG", "security", 1);
  const CommandResult r = run_swarm("run --secure --map small --groups 1 --robots-per-group 2 --max-ticks 20 "
                                    "--domain " + std::to_string(domain::kSecureLog) + " --partition secure-log --out " + dir + "/run");
  ::unsetenv("SWARM_DDS_LOG");
  ASSERT_EQ(r.exit_code, 3) << r.output;  // ran to its 20 ticks: incomplete, as meant
  const std::vector<std::string> roles = {"sim", "gcs", "leader-0", "member-0-1"};
  for (const std::string& role : roles) {
    std::ifstream in(dir + "/run/logs/" + role + ".log");
    ASSERT_TRUE(in) << "no log of " << role;
    std::stringstream log;
    log << in.rdbuf();
    for (const std::string& peer : roles) {
      if (peer == role) continue;
      EXPECT_NE(log.str().find(role + ": DDS security: peer " + peer + " ("), std::string::npos)
          << role << " does not log " << peer << " authenticated:\n" << log.str();
    }
    EXPECT_EQ(log.str().find("refused"), std::string::npos) << log.str();
  }
}

}  // namespace
}  // namespace swarm::test
