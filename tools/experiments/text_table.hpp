// Plain-text tables for the terminal: a header row, section lines and rows of cells; the first
// column is left-aligned, the others right-aligned, columns two spaces apart. Widths count UTF-8
// characters (so "±" is one column).
//
//   TextTable t({"", "open", "maze1"});
//   t.add_section("steps");
//   t.add_row({"  group-frontier", "180.2 ± 10.3", "390.0 ± 30.1"});
//   std::cout << t.render();
#pragma once

#include <string>
#include <vector>

namespace swarm::tools {

class TextTable {
 public:
  explicit TextTable(std::vector<std::string> header);
  // A line of its own (e.g. the metric the next rows show).
  void add_section(std::string title);
  // Missing cells are blank; extra cells are an error of the caller (asserted).
  void add_row(std::vector<std::string> cells);
  [[nodiscard]] std::string render() const;

 private:
  struct Line {
    bool section = false;
    std::vector<std::string> cells;
  };
  std::vector<std::string> header_;
  std::vector<Line> lines_;
};

// The number of UTF-8 characters in `text`.
[[nodiscard]] std::size_t display_width(const std::string& text);

}  // namespace swarm::tools
