// `swarm view RUN_DIR`: the replay page served over HTTP and drawn by headless Chromium (Debian's
// `chromium`, installed by scripts/install-deps.sh). The screenshot must show every robot on the
// cell the record has it on, in its group's colour, and the map's walls where the map has them.
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <thread>

#include "run_swarm.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/record/record.hpp"

extern char** environ;

namespace swarm::test {
namespace {

// The page's palette (tools/view/page/index.html: PALETTE, CELL), as RGB.
constexpr std::array<std::array<int, 3>, 3> kGroupColour = {{{31, 119, 180}, {255, 127, 14}, {44, 160, 44}}};
constexpr std::array<int, 3> kWall = {51, 51, 51};
constexpr std::array<int, 3> kFree = {255, 255, 255};

// `swarm view` in the background; stopped (SIGTERM) when this goes out of scope.
class Viewer {
 public:
  Viewer(const std::string& run_dir, int port) {
    const std::string exe = std::string(SWARM_BIN_DIR) + "/swarm";
    const std::string port_text = std::to_string(port);
    std::vector<std::string> args = {exe, "view", run_dir, "--view-port", port_text};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (::posix_spawn(&pid_, exe.c_str(), nullptr, nullptr, argv.data(), environ) != 0) pid_ = -1;
  }
  ~Viewer() { (void)stop(); }
  // The exit status after SIGTERM (-1: it had not started or did not exit normally).
  int stop() {
    if (pid_ <= 0) return -1;
    ::kill(pid_, SIGTERM);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  [[nodiscard]] bool started() const { return pid_ > 0; }

 private:
  pid_t pid_ = -1;
};

bool answers(int port) {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const bool ok = ::connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
  ::close(s);
  return ok;
}

bool wait_for(int port) {
  for (int k = 0; k < 100; ++k) {
    if (answers(port)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return false;
}

std::array<int, 3> rgb_at(const cv::Mat& png, double x, double y) {
  const cv::Vec3b p = png.at<cv::Vec3b>(static_cast<int>(y), static_cast<int>(x));
  return {p[2], p[1], p[0]};
}

TEST(View, TheReplayPageDrawsTheRobotsAndTheWallsWhereTheRecordHasThem) {
  ASSERT_EQ(::access("/usr/bin/chromium", X_OK), 0) << "chromium is missing: run scripts/install-deps.sh";
  const std::string dir = fresh_dir("view_replay");
  const CommandResult run = run_swarm("run --map warehouse-5x8 --mission explore,cover --out " + dir + "/run");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto frames = record::read_record(dir + "/run/run.pb");
  const record::Header& h = frames.front().header();
  const config::World world = config::resolve_world(h.scenario(), ".");
  const record::Poses* poses = nullptr;  // a tick in the middle of the run
  std::vector<const record::Poses*> all;
  for (const auto& f : frames) {
    if (f.has_poses()) all.push_back(&f.poses());
  }
  ASSERT_GT(all.size(), 10U);
  poses = all[all.size() / 2];

  const int port = 20000 + ::getpid() % 20000;
  Viewer viewer(dir + "/run", port);
  ASSERT_TRUE(viewer.started());
  ASSERT_TRUE(wait_for(port)) << "swarm view did not answer on port " << port;
  // A second viewer on the same port: exit 2, naming it.
  const CommandResult taken = run_swarm("view " + dir + "/run --view-port " + std::to_string(port));
  EXPECT_EQ(taken.exit_code, 2);
  EXPECT_NE(taken.output.find("cannot listen on 127.0.0.1:" + std::to_string(port)), std::string::npos) << taken.output;

  const int scale = 16;
  const std::string png = dir + "/view.png";
  const std::string url = "http://127.0.0.1:" + std::to_string(port) + "/?tick=" + std::to_string(poses->tick()) +
                          "&scale=" + std::to_string(scale) + "&labels=0&routes=0&truth=1";
  const std::string chromium = "chromium --headless=new --no-sandbox --disable-gpu --hide-scrollbars "
                               "--window-size=600,400 --virtual-time-budget=5000 --screenshot=" + png + " '" + url +
                               "' > " + dir + "/chromium.log 2>&1";
  ASSERT_EQ(std::system(chromium.c_str()), 0) << "see " << dir << "/chromium.log";
  const cv::Mat shot = cv::imread(png, cv::IMREAD_COLOR);
  ASSERT_FALSE(shot.empty());
  ASSERT_GE(shot.cols, static_cast<int>(h.width()) * scale);
  ASSERT_GE(shot.rows, static_cast<int>(h.height()) * scale);

  const int robots = static_cast<int>(h.groups() * h.robots_per_group());
  std::vector<std::uint8_t> robot_on(world.truth.size(), 0);
  for (int r = 0; r < robots; ++r) {
    const int x = poses->xy(2 * r), y = poses->xy(2 * r + 1);
    robot_on[static_cast<std::size_t>(world.truth.index({x, y}))] = 1;
    const auto want = kGroupColour[static_cast<std::size_t>(r / static_cast<int>(h.robots_per_group()))];
    EXPECT_EQ(rgb_at(shot, (x + 0.5) * scale, (h.height() - 1 - y + 0.5) * scale), want) << "robot " << r << " at " << x << "," << y;
  }
  int walls = 0;
  for (int y = 0; y < static_cast<int>(h.height()); ++y) {
    for (int x = 0; x < static_cast<int>(h.width()); ++x) {
      if (robot_on[static_cast<std::size_t>(world.truth.index({x, y}))]) continue;
      const auto want = world.truth.is_occupied({x, y}) ? kWall : kFree;
      walls += world.truth.is_occupied({x, y});
      EXPECT_EQ(rgb_at(shot, (x + 0.5) * scale, (h.height() - 1 - y + 0.5) * scale), want) << "cell " << x << "," << y;
    }
  }
  EXPECT_GT(walls, 20);
  EXPECT_EQ(viewer.stop(), 0);  // SIGTERM: a clean stop

  const CommandResult not_a_run = run_swarm("view " + dir + " --view-port " + std::to_string(port));
  EXPECT_EQ(not_a_run.exit_code, 2);
  EXPECT_NE(not_a_run.output.find("is not a run directory"), std::string::npos) << not_a_run.output;
}

}  // namespace
}  // namespace swarm::test
