#include "live_view.hpp"

#include <nlohmann/json.hpp>

#include "swarm/app/convert.hpp"
#include "swarm/comm/endpoint.hpp"
#include "swarm/comm/topology.hpp"
#include "swarm/record/record.hpp"

namespace swarm::tools {

namespace {
enum Channel : std::uint32_t { kTf = 1, kRobots = 2, kMap = 3, kTruth = 4, kLog = 5 };
// The cursor's slots: what a connection has had of each channel.
enum Slot : std::size_t { kCellsSeen, kRobotsSeen, kMapSeen, kTruthSeen, kLogSeen, kSlots };
}  // namespace

struct LiveView::Readers {
  std::unique_ptr<comm::Reader<msgs::Clock>> clock;
  std::unique_ptr<comm::Reader<msgs::RoundStart>> round;
  std::unique_ptr<comm::Reader<msgs::PhaseStart>> phase;
};

LiveView::Setup LiveView::setup_for(const config::World& world, comm::DdsOptions dds) {
  const auto& s = world.scenario;
  Setup setup;
  setup.dds = std::move(dds);
  record::Header team;
  team.set_groups(s.groups());
  team.set_robots_per_group(s.robots_per_group());
  setup.names = record::robot_names(team);
  setup.robots_per_group = static_cast<int>(s.robots_per_group());
  setup.frame = planner::OccupancyGrid(world.truth.width(), world.truth.height(), world.truth.resolution(),
                                       world.truth.origin_x(), world.truth.origin_y());
  setup.truth = &world.truth;
  setup.tick_ns = std::uint64_t{s.tick_ms()} * 1'000'000U;
  setup.title = s.map() + ", seed " + std::to_string(s.seed());
  return setup;
}

LiveView::LiveView(Setup setup)
    : setup_(std::move(setup)),
      frame_{setup_.frame.resolution(), setup_.frame.origin_x(), setup_.frame.origin_y()},
      map_(setup_.frame) {
  participant_ = std::make_unique<comm::Participant>(setup_.dds);
  readers_ = std::make_unique<Readers>();
  readers_->clock = std::make_unique<comm::Reader<msgs::Clock>>(*participant_, comm::topic::kClock, [this](msgs::Clock&& c) {
    std::vector<planner::Cell> cells;
    for (const auto& r : c.robots()) cells.push_back({r.x(), r.y()});
    const std::lock_guard<std::mutex> lock(mutex_);
    if (c.tick() < tick_ && cells_version_ > 0) return;  // an old clock repeated
    tick_ = c.tick();
    cells_ = std::move(cells);
    ++cells_version_;
    lost_.resize(c.robots().size(), false);
    for (std::size_t r = 0; r < c.robots().size(); ++r) {
      if (c.robots()[r].alive() || lost_[r]) continue;
      lost_[r] = true;
      ++lost_version_;
      const std::string name = r < setup_.names.size() ? setup_.names[r] : "robot " + std::to_string(r);
      log_.emplace_back(std::uint64_t{tick_} * setup_.tick_ns, name + " lost at tick " + std::to_string(tick_));
    }
  });
  readers_->round = std::make_unique<comm::Reader<msgs::RoundStart>>(*participant_, comm::topic::kRound, [this](msgs::RoundStart&& r) {
    planner::OccupancyGrid g = setup_.frame;
    try {
      app::decode_map(r.map_rle(), static_cast<planner::PatchEncoding>(r.encoding()), g);
    } catch (const std::exception&) {
      return;  // a map of another size: not this run's
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    if (r.fused_tick() < map_tick_) return;
    map_ = std::move(g);
    map_tick_ = r.fused_tick();
    ++map_version_;
  });
  readers_->phase = std::make_unique<comm::Reader<msgs::PhaseStart>>(*participant_, comm::topic::kPhase, [this](msgs::PhaseStart&& p) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const std::string text = "phase " + std::to_string(p.phase() + 1) + " (" + p.task() + ") " + (p.settle() ? "settling" : "started");
    if (log_.empty() || log_.back().second != text) log_.emplace_back(std::uint64_t{tick_} * setup_.tick_ns, text);
  });
}

LiveView::~LiveView() {
  readers_.reset();
  participant_.reset();
}

std::vector<LiveChannel> LiveView::channels() const {
  std::vector<LiveChannel> out = {{kTf, "/tf", "foxglove.FrameTransforms", ""},
                                  {kRobots, "/robots", "foxglove.SceneUpdate", ""},
                                  {kMap, "/map", "foxglove.Grid", ""},
                                  {kLog, "/log", "foxglove.Log", ""}};
  if (setup_.truth != nullptr) out.push_back({kTruth, "/map/truth", "foxglove.Grid", ""});
  for (LiveChannel& c : out) c.schema = foxglove_schema(c.schema_name).dump();
  return out;
}

std::vector<LiveMessage> LiveView::since(std::vector<std::uint64_t>& cursor) const {
  cursor.resize(kSlots, 0);
  std::vector<LiveMessage> out;
  if (setup_.truth != nullptr && cursor[kTruthSeen] == 0) {
    out.push_back({kTruth, 0, foxglove_grid(*setup_.truth, 0).dump()});
    cursor[kTruthSeen] = 1;
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  if (lost_version_ > cursor[kRobotsSeen]) {
    const std::uint64_t ns = std::uint64_t{tick_} * setup_.tick_ns;
    out.push_back({kRobots, ns, foxglove_robots(setup_.names, setup_.robots_per_group, frame_.resolution, lost_).dump()});
    cursor[kRobotsSeen] = lost_version_;
  }
  if (map_version_ > cursor[kMapSeen]) {
    const std::uint64_t ns = map_tick_ * setup_.tick_ns;
    out.push_back({kMap, ns, foxglove_grid(map_, ns).dump()});
    cursor[kMapSeen] = map_version_;
  }
  if (cells_version_ > cursor[kCellsSeen]) {
    const std::uint64_t ns = std::uint64_t{tick_} * setup_.tick_ns;
    out.push_back({kTf, ns, foxglove_transforms(setup_.names, cells_, frame_, ns).dump()});
    cursor[kCellsSeen] = cells_version_;
  }
  for (std::size_t k = cursor[kLogSeen]; k < log_.size(); ++k) {
    out.push_back({kLog, log_[k].first, foxglove_log(log_[k].second, log_[k].first).dump()});
  }
  cursor[kLogSeen] = log_.size();
  return out;
}

std::string LiveView::setup_json() const {
  const nlohmann::json j = {{"live", true},
                            {"width", setup_.frame.width()},
                            {"height", setup_.frame.height()},
                            {"resolution", frame_.resolution},
                            {"origin", {frame_.origin_x, frame_.origin_y}},
                            {"names", setup_.names},
                            {"robots_per_group", setup_.robots_per_group},
                            {"groups", setup_.names.size() / static_cast<std::size_t>(std::max(1, setup_.robots_per_group))},
                            {"tick_ns", setup_.tick_ns},
                            {"title", setup_.title}};
  return j.dump();
}

}  // namespace swarm::tools
