#include "tour_command.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "offline_common.hpp"
#include "tour_file.hpp"
#include "tour_report.hpp"

namespace swarm::tools {
namespace {

namespace fs = std::filesystem;
using planner::TourVariant;

std::vector<TourVariant> parse_variants(const std::vector<std::string>& names) {
  if (names.empty()) return {TourVariant::kNna, TourVariant::kDistance, TourVariant::kDistanceAngle};
  std::vector<TourVariant> out;
  for (const std::string& n : names) {
    const auto v = planner::parse_variant(n);
    if (!v) throw OfflineBadInput("unknown variant '" + n + "'; accepted: nna, distance, distance-angle");
    out.push_back(*v);
  }
  return out;
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f << text;
  if (!f) throw OfflineBadInput("cannot write " + path + "; choose a writable --out DIR");
}

}  // namespace

int tour_command(const TourCommandOptions& o, std::ostream& out, std::ostream& err) {
  try {
    const std::vector<TourVariant> variants = parse_variants(o.variants);
    const auto search = planner::parse_search(o.search);
    if (!search) throw OfflineBadInput("unknown --search '" + o.search + "'; accepted: ga, ga-polished, exact");
    if (o.generations < 1) throw OfflineBadInput("--generations must be at least 1 (the paper: 1000)");
    TourFile file;
    try {
      file = load_tour_file(o.file);
    } catch (const TourFileError& e) {
      throw OfflineBadInput(e.what());
    }
    if (!file.unreachable.empty()) {
      for (const std::string& u : file.unreachable) (o.skip_unreachable ? out : err) << (o.skip_unreachable ? "skipped: " : "") << u << "\n";
      if (!o.skip_unreachable) {
        throw OfflineBadInput(std::to_string(file.unreachable.size()) +
                              " object(s) cannot be reached; move them, or pass --skip-unreachable to plan without them");
      }
    }
    const std::string dir = make_out_dir(o.out_dir, "tour-" + fs::path(o.file).stem().string());

    planner::TourOptions options;
    options.seed = o.seed;
    options.search = *search;
    options.ga.generations = o.generations;
    options.compute_reference = true;
    out << "tour of " << o.file << " (" << file.map_text << "; " << file.problem.objects.size() << " objects of "
        << file.type_names.size() << " types), search " << o.search << ", seed " << o.seed << "\n";
    std::vector<VariantPlan> plans;
    nlohmann::json json{{"file", o.file}, {"search", o.search}, {"seed", o.seed}, {"variants", nlohmann::json::array()}};
    for (TourVariant v : variants) {
      options.variant = v;
      const auto t0 = std::chrono::steady_clock::now();
      VariantPlan vp{v, planner::plan_tour(file.map, file.problem, options)};
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      out << "  " << planner::variant_name(v) << ": length " << fixed(vp.plan.length_cells(), 2) << " cells, rotation "
          << fixed(vp.plan.rotation_rad(), 2) << " rad (" << fixed(s, 2) << " s)\n";
      const std::string png = (fs::path(dir) / ("tour-" + std::string(planner::variant_name(v)) + ".png")).string();
      draw_tour_png(file, vp, png);
      json["variants"].push_back(tour_json(file, vp));
      plans.push_back(std::move(vp));
    }
    const std::string table = leg_table(file, plans);
    out << "\n" << table << "\nlengths in cells (straight 1, diagonal sqrt 2); written to " << dir << "\n";
    write_text((fs::path(dir) / "table.txt").string(), table);
    write_text((fs::path(dir) / "tour.json").string(), json.dump(2) + "\n");
  } catch (const OfflineBadInput& e) {
    err << "swarm tour: " << e.what() << "\n";
    return 2;
  } catch (const std::runtime_error& e) {  // a picture that cannot be written
    err << "swarm tour: " << e.what() << "\n";
    return 2;
  }
  return 0;
}

}  // namespace swarm::tools
