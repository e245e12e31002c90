#include "traffic_over_time.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "plot.hpp"
#include "view_data.hpp"

namespace swarm::tools {

namespace {
constexpr const char* kOnRobot = "sim_robot";
}  // namespace

TrafficOverTime traffic_over_time(const std::vector<record::Frame>& frames, double bin_seconds) {
  if (frames.empty() || !frames.front().has_header()) throw std::runtime_error("the run record has no Header frame");
  const double tick_s = frames.front().header().scenario().tick_ms() / 1000.0;
  if (!(tick_s > 0) || !(bin_seconds > 0)) throw std::runtime_error("the run record has no tick length");
  TrafficOverTime t;
  t.bin_seconds = bin_seconds;
  t.links = link_names();
  t.bytes_per_s.assign(t.links.size(), {});
  std::vector<std::uint64_t> last(t.links.size(), 0);  // cumulative bytes at the end of the last bin
  std::vector<std::uint64_t> now(t.links.size(), 0);
  long bin = -1;  // the bin `now` belongs to
  double end_s = 0;  // the end of the last tick seen
  // A bin's rate over the time it spans: the last bin ends with the run, often inside it.
  const auto close_bin = [&] {
    const double from = static_cast<double>(bin) * bin_seconds;
    const double to = std::min(from + bin_seconds, std::max(end_s, from + tick_s));
    t.seconds.push_back(to);
    for (std::size_t l = 0; l < now.size(); ++l) {
      t.bytes_per_s[l].push_back(static_cast<double>(now[l] - std::min(now[l], last[l])) / (to - from));
    }
    last = now;
  };
  std::uint32_t last_phase = ~0U;
  for (const record::Frame& f : frames) {
    if (f.has_phase() && !f.phase().ended() && f.phase().phase() != last_phase) {
      last_phase = f.phase().phase();
      t.phase_starts.emplace_back(f.phase().tick() * tick_s, f.phase().task());
    }
    if (!f.has_poses() || !f.poses().has_tally()) continue;
    const auto this_bin = static_cast<long>(std::floor(f.poses().tick() * tick_s / bin_seconds));
    while (bin >= 0 && this_bin > bin) {  // bins with no poses carry nothing new
      close_bin();
      ++bin;
    }
    bin = this_bin;
    end_s = (f.poses().tick() + 1) * tick_s;
    const auto& bytes = f.poses().tally().sent_bytes();
    for (std::size_t l = 0; l < now.size() && static_cast<int>(l) < bytes.size(); ++l) now[l] = bytes.Get(static_cast<int>(l));
  }
  if (bin < 0) throw std::runtime_error("the run record has no traffic tallies (written by an older swarm)");
  close_bin();
  return t;
}

void write_traffic_csv(const TrafficOverTime& t, const std::string& path) {
  std::ofstream out(path);
  out << "second";
  std::vector<std::size_t> order;  // radio links first, the on-robot link last
  for (std::size_t l = 0; l < t.links.size(); ++l) {
    if (t.links[l] != kOnRobot) order.push_back(l);
  }
  for (std::size_t l = 0; l < t.links.size(); ++l) {
    if (t.links[l] == kOnRobot) order.push_back(l);
  }
  for (const std::size_t l : order) out << "," << t.links[l] << (t.links[l] == kOnRobot ? "_on_robot" : "") << "_bytes_per_s";
  out << "\n";
  for (std::size_t b = 0; b < t.seconds.size(); ++b) {
    out << t.seconds[b];
    for (const std::size_t l : order) out << "," << t.bytes_per_s[l][b];
    out << "\n";
  }
  if (!out) throw std::runtime_error("cannot write " + path);
}

void write_traffic_png(const TrafficOverTime& t, const std::string& path) {
  static const std::vector<Colour> kColours = {{0, 114, 178}, {213, 94, 0}, {0, 158, 115}, {204, 121, 167}, {86, 180, 233}};
  CurvePanel radio{"Radio links", "kB/s", "simulated seconds", t.seconds, {}, 0, {}};
  CurvePanel robot{"Sensing on the robots (sim_robot; not radio)", "kB/s", "simulated seconds", t.seconds, {}, 0, {}};
  for (std::size_t l = 0; l < t.links.size(); ++l) {
    PlotSeries s{t.links[l], kColours[l % kColours.size()], {}, {}};
    for (const double b : t.bytes_per_s[l]) s.values.push_back(b / 1000.0);
    (t.links[l] == kOnRobot ? robot : radio).series.push_back(std::move(s));
  }
  for (const auto& [second, task] : t.phase_starts) {
    radio.marks.push_back({second, task});
    robot.marks.push_back({second, task});
  }
  Figure f{"Bytes sent per second, per link class", {radio, robot}};
  f.note = "every agent's sent bytes (the simulator's clock tallies), in bins of " +
           std::to_string(static_cast<int>(std::lround(t.bin_seconds))) + " s of simulated time";
  write_figure_png(f, path);
}

void write_traffic_files(const std::vector<record::Frame>& frames, const std::string& run_dir) {
  const TrafficOverTime t = traffic_over_time(frames);
  write_traffic_csv(t, run_dir + "/traffic.csv");
  write_traffic_png(t, run_dir + "/traffic.png");
}

}  // namespace swarm::tools
