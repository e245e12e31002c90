#include "swarm/planner/mapf/graph_file.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <fstream>
#include <unordered_map>

#include "file_fields.hpp"

namespace swarm::planner::mapf {
namespace {

using detail::fail;

// The words of a line, without its comment ('#' to the end).
std::vector<std::string> words_of(std::string line) {
  if (const std::size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
  std::vector<std::string> out;
  std::size_t i = 0;
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
  while (i < line.size()) {
    while (i < line.size() && space(line[i])) ++i;
    const std::size_t begin = i;
    while (i < line.size() && !space(line[i])) ++i;
    if (i > begin) out.push_back(line.substr(begin, i - begin));
  }
  return out;
}

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

// Reads one file; each method handles one statement of the current line.
class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}

  Instance read() {
    std::ifstream file(path_);
    if (!file) fail(path_, 0, "cannot open the graph file (check the path)");
    std::string text;
    while (std::getline(file, text)) {
      ++line_;
      const std::vector<std::string> w = words_of(text);
      if (w.empty()) continue;
      if (vertices_ < 0 && w[0] != "vertices") {
        fail(path_, line_, "expected \"vertices N\" first (got " + quoted(w[0]) + ")");
      }
      if (w[0] == "vertices") {
        vertices(w);
      } else if (w[0] == "edge") {
        edge(w);
      } else if (w[0] == "position") {
        position(w);
      } else if (w[0] == "agent") {
        agent(w);
      } else {
        fail(path_, line_, "unknown statement " + quoted(w[0]) + " (expected vertices, position, edge or agent)");
      }
    }
    if (vertices_ < 0) fail(path_, 0, "empty file: expected \"vertices N\", then edge and agent lines");
    if (in_.starts.empty()) fail(path_, 0, "no agents: expected at least one \"agent START GOAL\" line");
    const auto given = std::count_if(position_line_.begin(), position_line_.end(), [](int l) { return l > 0; });
    if (given > 0 && given < vertices_) {
      const auto missing = std::find(position_line_.begin(), position_line_.end(), 0) - position_line_.begin();
      fail(path_, 0, "positions are given for " + std::to_string(given) + " of " + std::to_string(vertices_) +
                         " vertices (vertex " + std::to_string(missing) + " has none): give one per vertex, or none");
    }
    in_.graph = Graph(vertices_, std::move(edges_), std::move(positions_));
    return std::move(in_);
  }

 private:
  void expect_words(const std::vector<std::string>& w, std::size_t n, const char* form) {
    if (w.size() != n) {
      fail(path_, line_, std::string("expected ") + form + " (" + std::to_string(n) + " words), got " +
                             std::to_string(w.size()) + (w.size() == 1 ? " word" : " words"));
    }
  }

  // A vertex id of the statement `what` ("edge 2 9", ...).
  int vertex(const std::string& word, const std::string& what) const {
    int v = 0;
    if (!detail::parse_int(word, v)) fail(path_, line_, what + ": vertex ids are integers (got " + quoted(word) + ")");
    if (v < 0 || v >= vertices_) {
      fail(path_, line_, what + ": vertex " + word + " is not in the graph (vertices 0.." + std::to_string(vertices_ - 1) + ")");
    }
    return v;
  }

  void vertices(const std::vector<std::string>& w) {
    if (vertices_ >= 0) fail(path_, line_, "\"vertices\" is given again (first on line " + std::to_string(vertices_line_) + ")");
    expect_words(w, 2, "\"vertices N\"");
    if (!detail::parse_int(w[1], vertices_) || vertices_ < 1 || vertices_ > kMaxGraphFileVertices) {
      fail(path_, line_, "the number of vertices must be an integer from 1 to " + std::to_string(kMaxGraphFileVertices) +
                             " (got " + quoted(w[1]) + ")");
    }
    vertices_line_ = line_;
  }

  void edge(const std::vector<std::string>& w) {
    expect_words(w, 3, "\"edge U V\"");
    const std::string what = "edge " + w[1] + " " + w[2];
    const int u = vertex(w[1], what), v = vertex(w[2], what);
    if (u == v) fail(path_, line_, what + " is a self loop");
    const std::uint64_t key = (static_cast<std::uint64_t>(std::min(u, v)) << 32) | static_cast<std::uint32_t>(std::max(u, v));
    if (const auto [it, fresh] = edge_line_.emplace(key, line_); !fresh) {
      fail(path_, line_, what + " repeats line " + std::to_string(it->second));
    }
    edges_.push_back({u, v});
  }

  void position(const std::vector<std::string>& w) {
    expect_words(w, 4, "\"position V X Y\"");
    const std::string what = "position of vertex " + w[1];
    const int v = vertex(w[1], what);
    Position p;
    if (!detail::parse_double(w[2], p.x)) fail(path_, line_, what + ": x must be a number (got " + quoted(w[2]) + ")");
    if (!detail::parse_double(w[3], p.y)) fail(path_, line_, what + ": y must be a number (got " + quoted(w[3]) + ")");
    if (positions_.empty()) {  // the first position: every vertex needs one now
      positions_.assign(static_cast<std::size_t>(vertices_), {});
      position_line_.assign(static_cast<std::size_t>(vertices_), 0);
    }
    int& first = position_line_[static_cast<std::size_t>(v)];
    if (first > 0) fail(path_, line_, what + " is already given on line " + std::to_string(first));
    first = line_;
    positions_[static_cast<std::size_t>(v)] = p;
  }

  void agent(const std::vector<std::string>& w) {
    expect_words(w, 3, "\"agent START GOAL\"");
    const std::string what = "agent " + w[1] + " " + w[2];
    const int s = vertex(w[1], what), g = vertex(w[2], what);
    if (const auto [it, fresh] = start_line_.emplace(s, line_); !fresh) {
      fail(path_, line_, "start " + w[1] + " is also the start of line " + std::to_string(it->second));
    }
    if (const auto [it, fresh] = goal_line_.emplace(g, line_); !fresh) {
      fail(path_, line_, "goal " + w[2] + " is also the goal of line " + std::to_string(it->second));
    }
    in_.starts.push_back(vertex_cell(s));
    in_.goals.push_back(vertex_cell(g));
  }

  std::string path_;
  int line_ = 0;
  int vertices_ = -1;
  int vertices_line_ = 0;
  std::vector<Edge> edges_;
  std::unordered_map<std::uint64_t, int> edge_line_;  // {min, max} -> its line
  std::vector<Position> positions_;  // empty until a position is given, then one per vertex
  std::vector<int> position_line_;   // per vertex, 0 = not given
  std::unordered_map<int, int> start_line_, goal_line_;
  Instance in_;
};

// Shortest round-trip form of a number.
std::string number(double v) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : std::to_string(v);
}

}  // namespace

Instance load_graph_instance(const std::string& path) { return Reader(path).read(); }

void save_graph_instance(const std::string& path, const Instance& in) {
  const Instance g = graph_instance(in);
  const Graph& graph = *g.graph;
  std::ofstream out(path);
  if (!out) fail(path, 0, "cannot write the graph file (check the folder)");
  out << "# MAPF graph instance (swarm planner/mapf/graph_file.hpp): " << graph.vertices() << " vertices, "
      << graph.edges().size() << " edges, " << g.agents() << " agents\n";
  out << "vertices " << graph.vertices() << "\n";
  for (std::size_t v = 0; v < graph.positions().size(); ++v) {
    out << "position " << v << " " << number(graph.positions()[v].x) << " " << number(graph.positions()[v].y) << "\n";
  }
  for (const Edge& e : graph.edges()) out << "edge " << e.u << " " << e.v << "\n";
  for (int a = 0; a < g.agents(); ++a) {
    out << "agent " << g.starts[static_cast<std::size_t>(a)].x << " " << g.goals[static_cast<std::size_t>(a)].x << "\n";
  }
  out.close();
  if (!out) fail(path, 0, "cannot write the graph file (disk full?)");
}

}  // namespace swarm::planner::mapf
