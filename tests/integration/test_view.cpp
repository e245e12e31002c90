// `swarm view RUN_DIR`: the replay page served over HTTP and drawn by headless Chromium (Debian's
// `chromium`, installed by scripts/install-deps.sh). The screenshot must show every robot on the
// cell the record has it on, in its group's colour, and the map's walls where the map has them.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <limits>
#include <cmath>
#include <map>
#include <set>
#include <nlohmann/json.hpp>
#include <chrono>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <thread>

#include "run_swarm.hpp"
#include "swarm/config/scenario.hpp"
#include "swarm/record/record.hpp"
#include "swarm_test/domains.hpp"
#include "swarm_test/files.hpp"

extern char** environ;

namespace swarm::test {
namespace {

// The page's palette (tools/view/page/index.html: PALETTE, CELL), as RGB.
constexpr std::array<std::array<int, 3>, 3> kGroupColour = {{{31, 119, 180}, {255, 127, 14}, {44, 160, 44}}};
constexpr std::array<int, 3> kWall = {51, 51, 51};
constexpr std::array<int, 3> kFree = {255, 255, 255};

// `swarm ARGS` in the background; stopped (SIGTERM) if still running when this goes out of scope.
class BackgroundSwarm {
 public:
  // What it prints goes to `log`.
  BackgroundSwarm(std::vector<std::string> args, const std::string& log) {
    const std::string exe = std::string(SWARM_BIN_DIR) + "/swarm";
    args.insert(args.begin(), exe);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t files;
    ::posix_spawn_file_actions_init(&files);
    ::posix_spawn_file_actions_addopen(&files, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::posix_spawn_file_actions_adddup2(&files, 1, 2);
    if (::posix_spawn(&pid_, exe.c_str(), &files, nullptr, argv.data(), environ) != 0) pid_ = -1;
    ::posix_spawn_file_actions_destroy(&files);
  }
  ~BackgroundSwarm() { (void)stop(); }
  // SIGTERM, then its exit status (-1: it had not started or did not exit normally).
  int stop() {
    if (pid_ > 0) ::kill(pid_, SIGTERM);
    return wait();
  }
  int wait() {
    if (pid_ <= 0) return -1;
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  [[nodiscard]] bool started() const { return pid_ > 0; }

 private:
  pid_t pid_ = -1;
};

// A TCP connection to 127.0.0.1:port whose reads give up after 60 s (a run under a sanitizer may
// take that long to start its first tick): its socket, or -1.
int connect_loopback(int port) {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  timeval limit{60, 0};
  ::setsockopt(s, SOL_SOCKET, SO_RCVTIMEO, &limit, sizeof limit);
  if (::connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0) return s;
  ::close(s);
  return -1;
}

bool answers(int port) {
  const int s = connect_loopback(port);
  if (s >= 0) ::close(s);
  return s >= 0;
}

// Whether something listens on `port` within 60 s (a run under a sanitizer is slow to start).
bool wait_for(int port) {
  for (int k = 0; k < 600; ++k) {
    if (answers(port)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return false;
}

// GET `path` over HTTP/1.1 (the server closes the connection after it): the body, or "" on failure.
std::string http_get(int port, const std::string& path) {
  const int s = connect_loopback(port);
  std::string response;
  if (s >= 0) {
    const std::string request = "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n";
    (void)::send(s, request.data(), request.size(), 0);
    char buffer[65536];
    for (ssize_t n; (n = ::recv(s, buffer, sizeof buffer, 0)) > 0;) response.append(buffer, static_cast<std::size_t>(n));
    ::close(s);
  }
  const std::size_t body = response.find("\r\n\r\n");
  return body == std::string::npos ? "" : response.substr(body + 4);
}

// A WebSocket client written for the test from RFC 6455, apart from the server's library: the
// opening handshake asking for Foxglove's subprotocol, masked text frames out, whole frames in.
class WsClient {
 public:
  explicit WsClient(int port) : fd_(connect_loopback(port)) {
    if (fd_ < 0) return;
    const std::string request = "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                                "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n"
                                "Sec-WebSocket-Protocol: foxglove.websocket.v1\r\n\r\n";
    (void)::send(fd_, request.data(), request.size(), 0);
    while (response_.find("\r\n\r\n") == std::string::npos) {
      char c = 0;
      if (::recv(fd_, &c, 1, 0) != 1) return;
      response_ += c;
    }
  }
  ~WsClient() {
    if (fd_ >= 0) ::close(fd_);
  }
  [[nodiscard]] const std::string& handshake() const { return response_; }

  void send_text(const std::string& text) {
    std::string f;
    f.push_back(static_cast<char>(0x81));
    const std::size_t n = text.size();
    if (n < 126) {
      f.push_back(static_cast<char>(0x80 | n));
    } else {
      f.push_back(static_cast<char>(0x80 | 126));
      f.push_back(static_cast<char>((n >> 8) & 0xFF));
      f.push_back(static_cast<char>(n & 0xFF));
    }
    const std::array<char, 4> mask = {'\x12', '\x34', '\x56', '\x78'};
    f.append(mask.data(), 4);
    for (std::size_t i = 0; i < n; ++i) f.push_back(static_cast<char>(text[i] ^ mask[i % 4]));
    (void)::send(fd_, f.data(), f.size(), 0);
  }

  // The next data frame: (opcode, payload); opcode 8 (close) or -1 when the connection ends.
  std::pair<int, std::string> next() {
    for (;;) {
      std::uint8_t head[2];
      if (!read(head, 2)) return {-1, {}};
      const int op = head[0] & 0x0F;
      std::uint64_t n = head[1] & 0x7F;
      if (n == 126 || n == 127) {
        std::uint8_t ext[8];
        const int bytes = n == 126 ? 2 : 8;
        if (!read(ext, static_cast<std::size_t>(bytes))) return {-1, {}};
        n = 0;
        for (int b = 0; b < bytes; ++b) n = (n << 8) | ext[b];
      }
      std::string payload(n, '\0');
      if (n > 0 && !read(reinterpret_cast<std::uint8_t*>(payload.data()), n)) return {-1, {}};
      if (op == 9 || op == 10) continue;  // ping, pong
      return {op, std::move(payload)};
    }
  }

 private:
  bool read(std::uint8_t* out, std::size_t n) {
    for (std::size_t got = 0; got < n;) {
      const ssize_t k = ::recv(fd_, out + got, n - got, 0);
      if (k <= 0) return false;
      got += static_cast<std::size_t>(k);
    }
    return true;
  }
  int fd_ = -1;
  std::string response_;
};

std::uint64_t le(const std::string& s, std::size_t at, int bytes) {
  std::uint64_t v = 0;
  for (int b = bytes - 1; b >= 0; --b) v = (v << 8) | static_cast<std::uint8_t>(s[at + static_cast<std::size_t>(b)]);
  return v;
}

std::array<int, 3> rgb_at(const cv::Mat& png, double x, double y) {
  const cv::Vec3b p = png.at<cv::Vec3b>(static_cast<int>(y), static_cast<int>(x));
  return {p[2], p[1], p[0]};
}

// Headless Chromium's screenshot of the page on `port` with `query` (600 x 400), read back; empty
// if it failed (its output in DIR/chromium.log).
cv::Mat screenshot(int port, const std::string& query, const std::string& dir, const std::string& name) {
  const std::string png = dir + "/" + name + ".png";
  const std::string chromium = "chromium --headless=new --no-sandbox --disable-gpu --hide-scrollbars "
                               "--window-size=600,400 --virtual-time-budget=5000 --screenshot=" + png +
                               " 'http://127.0.0.1:" + std::to_string(port) + "/?" + query + "' > " + dir +
                               "/chromium.log 2>&1";
  if (std::system(chromium.c_str()) != 0) return {};
  return cv::imread(png, cv::IMREAD_COLOR);
}

// `swarm run ARGS --out DIR/run` to its end, which must be exit 0, and its record (none if not).
std::vector<record::Frame> recorded_run(const std::string& dir, const std::string& args) {
  const CommandResult run = run_swarm("run " + args + " --out " + dir + "/run");
  if (run.exit_code != 0) {
    ADD_FAILURE() << "swarm run " << args << " exited " << run.exit_code << ":\n" << run.output;
    return {};
  }
  return record::read_record(dir + "/run/run.pb");
}

TEST(View, TheReplayPageDrawsTheRobotsAndTheWallsWhereTheRecordHasThem) {
  ASSERT_EQ(::access("/usr/bin/chromium", X_OK), 0) << "chromium is missing: run scripts/install-deps.sh";
  const std::string dir = fresh_dir("view_replay");
  const auto frames = recorded_run(dir, "--map warehouse-5x8 --mission explore,cover");
  ASSERT_FALSE(frames.empty());
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
  BackgroundSwarm viewer({"view", dir + "/run", "--view-port", std::to_string(port)}, dir + "/view.log");
  ASSERT_TRUE(viewer.started());
  ASSERT_TRUE(wait_for(port)) << "swarm view did not answer on port " << port;
  // A second viewer on the same port: exit 2, naming it.
  const CommandResult taken = run_swarm("view " + dir + "/run --view-port " + std::to_string(port));
  EXPECT_EQ(taken.exit_code, 2);
  EXPECT_NE(taken.output.find("cannot listen on 127.0.0.1:" + std::to_string(port)), std::string::npos) << taken.output;

  const int scale = 16;
  const std::string at_tick = "tick=" + std::to_string(poses->tick()) + "&scale=" + std::to_string(scale);
  const cv::Mat shot = screenshot(port, at_tick + "&labels=0&routes=0&frontiers=0&truth=1", dir, "view");
  ASSERT_FALSE(shot.empty()) << "see " << dir << "/chromium.log";
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

  // With the frontiers: each group's frontier cells of its last plan, a dot in its colour at 0.6
  // over the map's white.
  std::map<std::uint32_t, const record::Plan*> plan_of;
  for (const auto& f : frames) {
    if (f.has_plan() && f.plan().tick() <= poses->tick()) plan_of[f.plan().group()] = &f.plan();
  }
  ASSERT_FALSE(plan_of.empty());
  const cv::Mat dots = screenshot(port, at_tick + "&labels=0&routes=0&truth=1", dir, "frontiers");
  ASSERT_FALSE(dots.empty()) << "see " << dir << "/chromium.log";
  std::map<int, int> claims;  // cell index -> how many groups' frontiers hold it
  for (const auto& [g, plan] : plan_of) {
    for (int k = 0; k + 1 < plan->group_frontiers_xy_size(); k += 2) ++claims[world.truth.index({plan->group_frontiers_xy(k), plan->group_frontiers_xy(k + 1)})];
  }
  int checked = 0;
  for (const auto& [g, plan] : plan_of) {
    for (int k = 0; k + 1 < plan->group_frontiers_xy_size(); k += 2) {
      const int x = plan->group_frontiers_xy(k), y = plan->group_frontiers_xy(k + 1);
      const auto i = world.truth.index({x, y});
      if (claims[i] > 1 || robot_on[static_cast<std::size_t>(i)] || !world.truth.is_free({x, y})) continue;
      const auto got = rgb_at(dots, (x + 0.5) * scale, (h.height() - 1 - y + 0.5) * scale);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got[static_cast<std::size_t>(c)], 0.6 * kGroupColour[g][static_cast<std::size_t>(c)] + 0.4 * 255, 2.0)
            << "group " << g << " frontier cell " << x << "," << y;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);

  // The replay's data: a tally per tick the record has poses for (the clock's conflicts, progress
  // and bytes per link class), and no team events in a run without faults.
  const nlohmann::json data = nlohmann::json::parse(http_get(port, "/run.json"));
  ASSERT_EQ(data["tallies"].size(), all.size());
  EXPECT_EQ(data["tallies"].back()["bytes"].size(), 5U);
  EXPECT_GT(data["tallies"].back()["bytes"][1].get<std::uint64_t>(), 0U);  // member_leader
  EXPECT_TRUE(data["events"].empty());
  EXPECT_EQ(data["links"], nlohmann::json({"sim_robot", "member_leader", "leader_gcs", "telemetry", "control"}));

  // With the routes in the cover phase: each robot's route sweeps its region, its cells tinted in
  // its group's colour at 0.18 over white, under the robots, which stay where the record has them.
  std::set<std::uint32_t> routed_groups;
  std::uint32_t routed_at = 0;  // the tick of the cover phase's last division
  for (const auto& f : frames) {
    if (!f.has_route() || f.route().phase() != 1 || f.route().region_cells() == 0) continue;
    routed_groups.insert(f.route().robot() / h.robots_per_group());
    routed_at = std::max(routed_at, f.route().tick());
  }
  ASSERT_FALSE(routed_groups.empty()) << "no cover routes in the record";
  const cv::Mat regions = screenshot(port, "tick=" + std::to_string(routed_at + 1) + "&scale=" + std::to_string(scale) +
                                     "&labels=0&truth=1", dir, "regions");
  ASSERT_FALSE(regions.empty()) << "see " << dir << "/chromium.log";
  for (const std::uint32_t g : routed_groups) {
    int tinted = 0;
    for (int y = 0; y < static_cast<int>(h.height()) * scale; ++y) {
      for (int x = 0; x < static_cast<int>(h.width()) * scale; ++x) {
        const auto got = rgb_at(regions, x, y);
        bool near = true;
        for (int c = 0; c < 3; ++c) near = near && std::abs(got[c] - (0.18 * kGroupColour[g][c] + 0.82 * 255)) <= 2.0;
        tinted += near ? 1 : 0;
      }
    }
    EXPECT_GT(tinted, scale * scale) << "group " << g << ": no region drawn";
  }
  EXPECT_EQ(viewer.stop(), 0);  // SIGTERM: a clean stop

  const CommandResult not_a_run = run_swarm("view " + dir + " --view-port " + std::to_string(port));
  EXPECT_EQ(not_a_run.exit_code, 2);
  EXPECT_NE(not_a_run.output.find("is not a run directory"), std::string::npos) << not_a_run.output;
}

// What a client saw of a live view: (log time, message) per channel it keeps.
struct Followed {
  std::vector<std::pair<std::uint64_t, nlohmann::json>> tf, robots, log, routes, frontiers, status;
};

// Speaks Foxglove's protocol on `ws`: serverInfo, advertise (every channel JSON with a JSON Schema),
// a subscription to every channel; then what comes until `count` /tf frames have, or the
// connection ends.
Followed follow(WsClient& ws, std::size_t count) {
  Followed seen;
  EXPECT_NE(ws.handshake().find("101"), std::string::npos) << ws.handshake();
  EXPECT_NE(ws.handshake().find("foxglove.websocket.v1"), std::string::npos) << ws.handshake();
  const auto info = ws.next();
  if (info.first != 1) return seen;
  EXPECT_EQ(nlohmann::json::parse(info.second)["op"], "serverInfo");
  const auto advertise = ws.next();
  if (advertise.first != 1) return seen;
  const nlohmann::json channels = nlohmann::json::parse(advertise.second);
  EXPECT_EQ(channels["op"], "advertise");
  std::map<std::string, std::uint32_t> id_of;
  nlohmann::json subscriptions = nlohmann::json::array();
  for (const auto& c : channels["channels"]) {
    id_of[c["topic"].get<std::string>()] = c["id"].get<std::uint32_t>();
    EXPECT_EQ(c["encoding"], "json");
    EXPECT_FALSE(nlohmann::json::parse(c["schema"].get<std::string>()).empty());
    subscriptions.push_back({{"id", 100 + c["id"].get<std::uint32_t>()}, {"channelId", c["id"]}});
  }
  for (const char* topic : {"/tf", "/map", "/robots", "/log", "/routes", "/frontiers", "/status"}) {
    EXPECT_TRUE(id_of.count(topic)) << topic;
  }
  ws.send_text(nlohmann::json({{"op", "subscribe"}, {"subscriptions", subscriptions}}).dump());
  while (seen.tf.size() < count) {
    const auto [op, payload] = ws.next();
    if (op != 2) break;  // closed, or nothing more
    EXPECT_GE(payload.size(), 13U);
    if (payload.size() < 13 || payload[0] != '\x01') break;
    const auto sub = static_cast<std::uint32_t>(le(payload, 1, 4));
    const std::pair<std::uint64_t, nlohmann::json> m{le(payload, 5, 8), nlohmann::json::parse(payload.substr(13))};
    if (sub == 100 + id_of["/tf"]) seen.tf.push_back(m);
    if (sub == 100 + id_of["/robots"]) seen.robots.push_back(m);
    if (sub == 100 + id_of["/log"]) seen.log.push_back(m);
    if (sub == 100 + id_of["/routes"]) seen.routes.push_back(m);
    if (sub == 100 + id_of["/frontiers"]) seen.frontiers.push_back(m);
    if (sub == 100 + id_of["/status"]) seen.status.push_back(m);
  }
  return seen;
}

// Every /tf frame of a tick the record holds puts every robot where the record has it; returns
// how many frames were compared.
int compare_with_record(const std::vector<std::pair<std::uint64_t, nlohmann::json>>& seen, const std::string& run_pb) {
  const auto frames = record::read_record(run_pb);
  const record::Header& h = frames.front().header();
  std::map<std::uint32_t, const record::Poses*> poses_at;
  for (const auto& f : frames) {
    if (f.has_poses()) poses_at[f.poses().tick()] = &f.poses();
  }
  const std::uint64_t tick_ns = std::uint64_t{h.scenario().tick_ms()} * 1'000'000U;
  int compared = 0;
  for (const auto& [ns, m] : seen) {
    const auto it = poses_at.find(static_cast<std::uint32_t>(ns / tick_ns));
    if (it == poses_at.end()) continue;  // a tick the record does not hold (before the first pose)
    ++compared;
    const auto& t = m["transforms"];
    EXPECT_EQ(static_cast<int>(t.size()) * 2, it->second->xy_size());
    for (int r = 0; r < static_cast<int>(t.size()) && 2 * r + 1 < it->second->xy_size(); ++r) {
      const auto& at = t[static_cast<std::size_t>(r)]["translation"];
      EXPECT_NEAR(at["x"].get<double>(), h.origin_x() + (it->second->xy(2 * r) + 0.5) * h.resolution(), 1e-9);
      EXPECT_NEAR(at["y"].get<double>(), h.origin_y() + (it->second->xy(2 * r + 1) + 0.5) * h.resolution(), 1e-9);
    }
  }
  return compared;
}

// Every /status of a tick the record holds has the record's tally for it (the simulator's conflict
// and progress counts, the bytes sent per link class); returns how many were compared.
int compare_status_with_record(const std::vector<std::pair<std::uint64_t, nlohmann::json>>& seen, const std::string& run_pb) {
  const auto frames = record::read_record(run_pb);
  std::map<std::uint32_t, const record::Tally*> tally_at;
  for (const auto& f : frames) {
    if (f.has_poses() && f.poses().has_tally()) tally_at[f.poses().tick()] = &f.poses().tally();
  }
  const std::vector<std::string> links = {"sim_robot", "member_leader", "leader_gcs", "telemetry", "control"};
  int compared = 0;
  for (const auto& [ns, m] : seen) {
    const auto it = tally_at.find(m["tick"].get<std::uint32_t>());
    if (it == tally_at.end()) continue;
    ++compared;
    const record::Tally& t = *it->second;
    EXPECT_EQ(m["vertex_conflicts"], t.vertex_conflicts());
    EXPECT_EQ(m["edge_conflicts"], t.edge_conflicts());
    EXPECT_EQ(m["blocked_moves"], t.blocked_moves());
    EXPECT_EQ(m["progress_done"], t.progress_done());
    EXPECT_EQ(m["progress_total"], t.progress_total());
    EXPECT_EQ(t.sent_bytes_size(), static_cast<int>(links.size()));
    if (t.sent_bytes_size() != static_cast<int>(links.size())) continue;
    for (std::size_t l = 0; l < links.size(); ++l) EXPECT_EQ(m["sent_bytes"][links[l]], t.sent_bytes(static_cast<int>(l))) << links[l];
    EXPECT_EQ(m["objects"], nlohmann::json(std::vector<int>(t.objects().begin(), t.objects().end())));
  }
  return compared;
}

// `swarm run ARGS --out DIR/run --view` on `port`, followed over the protocol from its start to
// its end, which must be exit 0 (a failure is reported and nothing is returned).
Followed watch_whole_run(const std::string& dir, int port, std::vector<std::string> args) {
  args.insert(args.begin(), "run");
  args.insert(args.end(), {"--out", dir + "/run", "--view", "--view-port", std::to_string(port)});
  BackgroundSwarm run(std::move(args), dir + "/run.log");
  if (!run.started() || !wait_for(port)) {
    ADD_FAILURE() << "no live view on port " << port << "; see " << dir << "/run.log";
    return {};
  }
  WsClient ws(port);
  Followed seen = follow(ws, std::numeric_limits<std::size_t>::max());
  const int exit_code = run.wait();
  if (exit_code != 0) {
    ADD_FAILURE() << "the run exited " << exit_code << "; see " << dir << "/run.log";
    return {};
  }
  return seen;
}

// The cells of a SceneUpdate entity's cubes or first line, by the map's frame.
std::vector<planner::Cell> entity_cells(const nlohmann::json& e, const record::Header& h) {
  std::vector<planner::Cell> out;
  const auto cell = [&](const nlohmann::json& p) {
    out.push_back({static_cast<int>(std::floor((p["x"].get<double>() - h.origin_x()) / h.resolution())),
                   static_cast<int>(std::floor((p["y"].get<double>() - h.origin_y()) / h.resolution()))});
  };
  for (const auto& c : e["cubes"]) cell(c["pose"]["position"]);
  if (!e["lines"].empty()) {
    for (const auto& p : e["lines"][0]["points"]) cell(p);
  }
  return out;
}

// A collect phase replayed: the simulator's tally gives each object's cell and holder every tick,
// which the page draws: a gold diamond on each object's cell while it lies there, a small one on
// the robot that carries it, nothing once it is delivered.
TEST(View, TheReplayShowsEachObjectLyingCarriedOrGone) {
  ASSERT_EQ(::access("/usr/bin/chromium", X_OK), 0) << "chromium is missing: run scripts/install-deps.sh";
  const std::string dir = fresh_dir("view_objects");
  const auto frames = recorded_run(dir, "--map warehouse-5x8 --mission collect");
  ASSERT_FALSE(frames.empty());
  const record::Header& h = frames.front().header();
  const record::Poses* first = nullptr;    // the phase's first tick: every object lying
  const record::Poses* carried = nullptr;  // the first tick a robot carries one
  const record::Poses* last = nullptr;     // the last tick: every object delivered
  for (const auto& f : frames) {
    if (!f.has_poses() || f.poses().tally().objects_size() == 0) continue;
    const record::Poses& p = f.poses();
    const auto& o = p.tally().objects();
    ASSERT_EQ(o.size() % 3, 0);
    if (first == nullptr) first = &p;
    for (int k = 0; k + 2 < o.size(); k += 3) {
      if (o[k + 2] < 0) continue;
      // Carried: on its robot's cell.
      EXPECT_EQ(o[k], p.xy(2 * o[k + 2])) << "tick " << p.tick();
      EXPECT_EQ(o[k + 1], p.xy(2 * o[k + 2] + 1)) << "tick " << p.tick();
      if (carried == nullptr) carried = &p;
    }
    last = &p;
  }
  ASSERT_NE(first, nullptr) << "no tally has the objects";
  ASSERT_NE(carried, nullptr) << "no object was ever carried";
  for (int k = 0; k + 2 < first->tally().objects_size(); k += 3) EXPECT_EQ(first->tally().objects(k + 2), -1);
  for (int k = 0; k + 2 < last->tally().objects_size(); k += 3) EXPECT_EQ(last->tally().objects(k + 2), -2) << "object " << k / 3;

  const int port = 20000 + (::getpid() + 23) % 20000;
  BackgroundSwarm viewer({"view", dir + "/run", "--view-port", std::to_string(port)}, dir + "/view.log");
  ASSERT_TRUE(viewer.started());
  ASSERT_TRUE(wait_for(port)) << "swarm view did not answer on port " << port;
  const int scale = 16;
  constexpr std::array<int, 3> kGold = {217, 166, 0};
  const auto shot_at = [&](const record::Poses& p) {
    return screenshot(port, "tick=" + std::to_string(p.tick()) + "&scale=" + std::to_string(scale) + "&labels=0&routes=0",
                      dir, "objects-" + std::to_string(p.tick()));
  };
  const auto centre_of = [&](const cv::Mat& m, int x, int y) {
    return rgb_at(m, (x + 0.5) * scale, (static_cast<int>(h.height()) - 1 - y + 0.5) * scale);
  };
  const auto robot_on = [](const record::Poses& p, int x, int y) {
    for (int k = 0; k + 1 < p.xy_size(); k += 2) {
      if (p.xy(k) == x && p.xy(k + 1) == y) return true;
    }
    return false;
  };
  const cv::Mat lying = shot_at(*first);
  ASSERT_FALSE(lying.empty()) << "see " << dir << "/chromium.log";
  for (int k = 0; k + 2 < first->tally().objects_size(); k += 3) {
    const int x = first->tally().objects(k), y = first->tally().objects(k + 1);
    if (!robot_on(*first, x, y)) EXPECT_EQ(centre_of(lying, x, y), kGold) << "object " << k / 3 << " at " << x << "," << y;
  }
  const cv::Mat picked = shot_at(*carried);
  ASSERT_FALSE(picked.empty()) << "see " << dir << "/chromium.log";
  const auto& now = carried->tally().objects();
  for (int k = 0; k + 2 < now.size(); k += 3) {
    if (now[k + 2] < 0) continue;
    EXPECT_EQ(centre_of(picked, now[k], now[k + 1]), kGold) << "carried object " << k / 3;
    // Where it lay, nothing gold, unless another object still lies there.
    const int x0 = first->tally().objects(k), y0 = first->tally().objects(k + 1);
    bool other = false;
    for (int j = 0; j + 2 < now.size(); j += 3) other = other || (j != k && now[j] == x0 && now[j + 1] == y0 && now[j + 2] == -1);
    if (!other && !robot_on(*carried, x0, y0)) EXPECT_NE(centre_of(picked, x0, y0), kGold) << "object " << k / 3 << " still drawn where it lay";
  }
  const cv::Mat done = shot_at(*last);
  ASSERT_FALSE(done.empty()) << "see " << dir << "/chromium.log";
  int gold = 0;
  for (int y = 0; y < done.rows; ++y) {
    for (int x = 0; x < done.cols; ++x) gold += rgb_at(done, x, y) == kGold ? 1 : 0;
  }
  EXPECT_EQ(gold, 0) << "delivered objects are still drawn";
  EXPECT_EQ(viewer.stop(), 0);
}

// `swarm run --view`: a client speaking Foxglove's protocol sees every robot where the record has
// it at that tick, then goes away mid-run without a close; the run's record is byte for byte the
// one of the same run unwatched.
TEST(View, ALiveRunIsWatchedOverFoxglovesProtocolAndNotChangedByIt) {
  const std::string dir = fresh_dir("view_live");
  const CommandResult plain = run_swarm("run --map maze1 --seed 3 --out " + dir + "/plain");
  ASSERT_EQ(plain.exit_code, 0) << plain.output;

  const int port = 20000 + (::getpid() + 7) % 20000;
  BackgroundSwarm run({"run", "--map", "maze1", "--seed", "3", "--out", dir + "/viewed", "--view", "--view-port",
                       std::to_string(port)},
                      dir + "/viewed.log");
  ASSERT_TRUE(run.started());
  ASSERT_TRUE(wait_for(port)) << "no live view on port " << port;
  Followed seen;
  {
    WsClient ws(port);
    seen = follow(ws, 10);
  }  // gone without a close frame, mid-run
  EXPECT_EQ(seen.robots.size(), 1U);
  ASSERT_EQ(run.wait(), 0);
  EXPECT_GE(compare_with_record(seen.tf, dir + "/viewed/run.pb"), 3);
  EXPECT_EQ(slurp(dir + "/viewed/run.pb"), slurp(dir + "/plain/run.pb")) << "the view changed the run";
}

// The live page in headless Chromium during a real-time run: the map file's cells from /map/truth
// pixel by pixel, and every robot drawn from /tf as a whole cell in its group's colour (which cells
// is the protocol test's to check: the page shows whatever tick it was at).
TEST(View, TheLivePageDrawsTheMapAndEveryRobot) {
  ASSERT_EQ(::access("/usr/bin/chromium", X_OK), 0) << "chromium is missing: run scripts/install-deps.sh";
  const std::string dir = fresh_dir("view_live_page");
  const int port = 20000 + (::getpid() + 5) % 20000;
  // Real time at 4 ticks a second: its exploration (about 40 ticks) outlasts the page's loading.
  BackgroundSwarm run({"run", "--map", "warehouse-5x8", "--realtime", "--tick-ms", "250", "--out", dir + "/run",
                       "--view", "--view-port", std::to_string(port)},
                      dir + "/run.log");
  ASSERT_TRUE(run.started());
  ASSERT_TRUE(wait_for(port)) << "no live view on port " << port;
  {
    // The view has robots to show once the simulator's clock reaches it (discovery takes longer on
    // a loaded machine): wait for the first /tf as a protocol client.
    WsClient ws(port);
    ASSERT_EQ(follow(ws, 1).tf.size(), 1U) << "no /tf from the live view";
  }
  const int scale = 16;
  const std::string png = dir + "/live.png";
  const std::string url = "http://127.0.0.1:" + std::to_string(port) + "/?scale=" + std::to_string(scale) +
                          "&labels=0&truth=1&settle=1&routes=0&frontiers=0&objects=0";
  const std::string chromium = "chromium --headless=new --no-sandbox --disable-gpu --hide-scrollbars "
                               "--window-size=600,400 --virtual-time-budget=3000 --screenshot=" + png + " '" + url +
                               "' > " + dir + "/chromium.log 2>&1";
  // The page draws the robots once the first /tf has reached it; a loaded machine may take a
  // screenshot before that, so up to four, until one shows any robot.
  const auto any_robot = [&](const cv::Mat& m) {
    for (int y = 0; y < m.rows; ++y) {
      for (int x = 0; x < m.cols; ++x) {
        if (rgb_at(m, x, y) == kGroupColour[0]) return true;
      }
    }
    return false;
  };
  cv::Mat shot;
  for (int attempt = 0; attempt < 4 && (shot.empty() || !any_robot(shot)); ++attempt) {
    ASSERT_EQ(std::system(chromium.c_str()), 0) << "see " << dir << "/chromium.log";
    shot = cv::imread(png, cv::IMREAD_COLOR);
  }
  (void)run.stop();
  ASSERT_FALSE(shot.empty());
  auto scenario = config::load_scenario(source_path("scenarios/default.pbtxt"));
  scenario.set_map("warehouse-5x8");
  scenario.clear_start();
  const planner::OccupancyGrid truth = config::resolve_world(scenario, ".").truth;
  const int w = truth.width(), h = truth.height();
  ASSERT_GE(shot.cols, w * scale);
  ASSERT_GE(shot.rows, h * scale);
  // Per group, the pixels of its colour: 3 robots, each a whole cell.
  std::array<int, 3> pixels{};
  std::vector<std::uint8_t> robot_cell(truth.size(), 0);
  for (int y = 0; y < h * scale; ++y) {
    for (int x = 0; x < w * scale; ++x) {
      const auto c = rgb_at(shot, x, y);
      for (std::size_t g = 0; g < kGroupColour.size(); ++g) {
        if (c != kGroupColour[g]) continue;
        ++pixels[g];
        robot_cell[static_cast<std::size_t>(truth.index({x / scale, h - 1 - y / scale}))] = 1;
      }
    }
  }
  for (std::size_t g = 0; g < pixels.size(); ++g) EXPECT_EQ(pixels[g], 3 * scale * scale) << "group " << g;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (robot_cell[static_cast<std::size_t>(truth.index({x, y}))]) continue;
      EXPECT_EQ(rgb_at(shot, (x + 0.5) * scale, (h - 1 - y + 0.5) * scale), truth.is_occupied({x, y}) ? kWall : kFree)
          << "cell " << x << "," << y;
    }
  }
}

// A robot killed during a watched run is marked lost when the clock says so: its /robots entity
// grey and "NAME (lost)", and a /log line with the tick; a leader killed too, its standby
// "NAME (leads group G)" from the tick the clock names it. Over the whole run: /status has the
// record's tallies, /routes the robots' routes on free cells, /frontiers the groups' frontiers.
TEST(View, ALiveViewMarksARobotLostWhenItDies) {
  const std::string dir = fresh_dir("view_lost");
  const Followed seen = watch_whole_run(dir, 20000 + (::getpid() + 11) % 20000,
                                        {"--map", "maze1", "--kill", "member-1-2@60", "--kill", "leader-2@40"});
  ASSERT_FALSE(seen.tf.empty());
  ASSERT_GE(seen.robots.size(), 2U) << seen.tf.size() << " /tf, " << seen.log.size() << " /log, " << seen.status.size() << " /status frames";
  const nlohmann::json& last = seen.robots.back().second["entities"];
  for (const auto& e : last) {
    const std::string id = e["id"].get<std::string>();
    const std::string want = id == "member-1-2" || id == "leader-2" ? id + " (lost)" : id == "member-2-1" ? id + " (leads group 2)" : id;
    EXPECT_EQ(e["texts"][0]["text"], want) << id;
  }
  bool logged = false, took_over = false;
  for (const auto& [ns, m] : seen.log) {
    const std::string text = m["message"].get<std::string>();
    if (text.rfind("member-1-2 lost at tick ", 0) == 0) logged = std::stoi(text.substr(24)) >= 60;
    if (text.rfind("member-2-1 leads group 2 from tick ", 0) == 0) took_over = std::stoi(text.substr(35)) > 40;
  }
  EXPECT_TRUE(logged);
  EXPECT_TRUE(took_over);
  EXPECT_GE(compare_with_record(seen.tf, dir + "/run/run.pb"), 3);
  EXPECT_GE(compare_status_with_record(seen.status, dir + "/run/run.pb"), 3);

  // The record holds the same news for the replay: both robots lost, and the take-over.
  const auto frames = record::read_record(dir + "/run/run.pb");
  const record::Header& h = frames.front().header();
  std::set<std::string> events;
  for (const auto& f : frames) {
    if (f.has_event()) events.insert(record::Event::Kind_Name(f.event().kind()) + " " + std::to_string(f.event().robot()));
  }
  EXPECT_EQ(events, (std::set<std::string>{"ROBOT_LOST 5", "ROBOT_LOST 6", "TAKE_OVER 7"}));

  // Routes: every robot had one, on free cells of the map; frontiers: every group planned on some.
  const auto scenario = [&] {
    auto s = h.scenario();
    return config::resolve_world(s, ".").truth;
  }();
  std::set<std::string> routed, planned;
  for (const auto& [ns, m] : seen.routes) {
    for (const auto& e : m["entities"]) {
      const std::string id = e["id"].get<std::string>();
      const std::vector<planner::Cell> cells = entity_cells(e, h);
      if (id.rfind("route/", 0) == 0 && cells.size() >= 2) routed.insert(id);
      for (const planner::Cell c : cells) EXPECT_TRUE(scenario.is_free(c)) << id << " at " << c.x << "," << c.y;
    }
  }
  for (const auto& [ns, m] : seen.frontiers) {
    for (const auto& e : m["entities"]) {
      if (e["id"].get<std::string>().rfind("frontiers/", 0) == 0 && !e["cubes"].empty()) planned.insert(e["id"]);
    }
  }
  EXPECT_EQ(routed.size(), 9U);
  EXPECT_EQ(planned, (std::set<std::string>{"frontiers/0", "frontiers/1", "frontiers/2"}));
}

// A watched cover phase: /routes has the GCS's whole route for every robot (plan/NAME), the one the
// record has as that robot's route in the phase's last division (region_cells > 0; the other
// routes recorded are the traffic layer's windows, which /routes shows as route/NAME).
TEST(View, ALiveViewShowsTheToursTheGcsPlanned) {
  const std::string dir = fresh_dir("view_plans");
  const Followed seen = watch_whole_run(dir, 20000 + (::getpid() + 19) % 20000,
                                        {"--map", "warehouse-5x8", "--mission", "explore,cover"});
  ASSERT_FALSE(seen.tf.empty());
  const auto frames = record::read_record(dir + "/run/run.pb");
  const record::Header& h = frames.front().header();
  const std::vector<std::string> names = record::robot_names(h);
  std::map<std::string, std::vector<planner::Cell>> recorded, shown;
  for (const auto& f : frames) {
    if (!f.has_route() || f.route().phase() != 1 || f.route().region_cells() == 0) continue;
    std::vector<planner::Cell>& cells = recorded[names.at(f.route().robot())];
    cells.clear();
    for (int k = 0; k + 1 < f.route().xy_size(); k += 2) cells.push_back({f.route().xy(k), f.route().xy(k + 1)});
  }
  for (const auto& [ns, m] : seen.routes) {
    for (const auto& e : m["entities"]) {
      const std::string id = e["id"].get<std::string>();
      if (id.rfind("plan/", 0) == 0) shown[id.substr(5)] = entity_cells(e, h);
    }
  }
  ASSERT_EQ(recorded.size(), names.size());
  for (const auto& [name, cells] : recorded) EXPECT_EQ(shown[name], cells) << name << ": " << shown[name].size() << " cells shown, " << cells.size() << " recorded";
}

// `swarm view --attach`: the same view of a swarm it did not start (as a deployment's), found by
// its domain and partition, read-only; it keeps serving after the swarm ends, until a signal.
TEST(View, AttachedToARunningSwarmItFollowsTheRobots) {
  const std::string dir = fresh_dir("view_attach");
  const int port = 20000 + (::getpid() + 13) % 20000;
  const std::string domain = std::to_string(domain::kViewAttach);
  const std::string partition = "view-attach-" + std::to_string(::getpid());
  const std::string scenario = source_path("scenarios/default.pbtxt");
  BackgroundSwarm viewer({"view", "--attach", "--scenario", scenario, "--domain", domain, "--partition", partition,
                          "--view-port", std::to_string(port)},
                         dir + "/view.log");
  ASSERT_TRUE(viewer.started());
  ASSERT_TRUE(wait_for(port)) << "no view on port " << port;
  WsClient ws(port);
  BackgroundSwarm run({"run", "--scenario", scenario, "--domain", domain, "--partition", partition, "--discovery", "simple",
                       "--out", dir + "/run"},
                      dir + "/run.log");
  const Followed seen = follow(ws, 10);
  ASSERT_EQ(run.wait(), 0) << "see " << dir << "/run.log";
  EXPECT_EQ(seen.robots.size(), 1U);
  EXPECT_GE(compare_with_record(seen.tf, dir + "/run/run.pb"), 3) << "see " << dir << "/view.log";
  EXPECT_EQ(viewer.stop(), 0);

  const CommandResult no_scenario = run_swarm("view --attach --domain " + domain);
  EXPECT_EQ(no_scenario.exit_code, 2);
  EXPECT_NE(no_scenario.output.find("--scenario"), std::string::npos) << no_scenario.output;
  const CommandResult neither = run_swarm("view");
  EXPECT_EQ(neither.exit_code, 2);
}

// A secure run (DDS-Security) watched live: `swarm run --secure --view` gives its viewer the
// run's read-only certificate, and `swarm view --attach --security-dir RUN_DIR/security` joins the
// running swarm with it. The certificate only subscribes: a writer with it is refused.
TEST(View, ASecureRunIsWatchedWithAReadOnlyCertificate) {
  const std::string dir = fresh_dir("view_secure");
  const int port = 20000 + (::getpid() + 17) % 20000;
  const std::string domain = std::to_string(domain::kViewSecure);
  const std::string partition = "view-secure-" + std::to_string(::getpid());
  // Real time, so that the attached viewer (which starts once the run's certificates exist) sees it.
  BackgroundSwarm run({"run", "--map", "maze1", "--secure", "--realtime", "--tick-ms", "100", "--domain", domain,
                       "--partition", partition, "--discovery", "simple", "--out", dir + "/run", "--view",
                       "--view-port", std::to_string(port)},
                      dir + "/run.log");
  ASSERT_TRUE(run.started());
  ASSERT_TRUE(wait_for(port)) << "no live view on port " << port << "; see " << dir << "/run.log";
  const std::string certs = dir + "/run/security";
  ASSERT_TRUE(std::filesystem::exists(certs + "/swarm-view.pem"));
  const int attached_port = port + 1;
  BackgroundSwarm viewer({"view", "--attach", "--scenario", dir + "/run/scenario.pbtxt", "--domain", domain,
                          "--partition", partition, "--security-dir", certs, "--view-port", std::to_string(attached_port)},
                         dir + "/view.log");
  ASSERT_TRUE(wait_for(attached_port)) << "no attached view on port " << attached_port;
  Followed seen, attached;
  {
    WsClient ws(port);
    seen = follow(ws, 10);
  }
  {
    WsClient ws(attached_port);
    attached = follow(ws, 10);
  }
  ASSERT_EQ(run.wait(), 0) << "see " << dir << "/run.log";
  EXPECT_GE(compare_with_record(seen.tf, dir + "/run/run.pb"), 3) << "swarm run --secure --view";
  EXPECT_GE(compare_with_record(attached.tf, dir + "/run/run.pb"), 3) << "see " << dir << "/view.log";
  EXPECT_EQ(viewer.stop(), 0);

  // Read-only: `swarm probe` makes a writer, which the viewer's grant refuses.
  const CommandResult writer = run_swarm("probe --seconds 0.5 --domain 40 --security-dir " + certs + " --identity swarm-view");
  EXPECT_EQ(writer.exit_code, 2) << writer.output;
  const CommandResult no_certificate =
      run_swarm("view --attach --scenario " + dir + "/run/scenario.pbtxt --security-dir " + dir + " --view-port " +
                std::to_string(attached_port));
  EXPECT_EQ(no_certificate.exit_code, 2);
  EXPECT_NE(no_certificate.output.find("swarm-view.pem"), std::string::npos) << no_certificate.output;
}

}  // namespace
}  // namespace swarm::test
