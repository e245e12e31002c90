#include "text_table.hpp"

#include <algorithm>
#include <cassert>
#include <utility>

namespace swarm::tools {

std::size_t display_width(const std::string& text) {
  std::size_t n = 0;
  for (unsigned char c : text) {
    if ((c & 0xC0) != 0x80) ++n;  // not a continuation byte
  }
  return n;
}

TextTable::TextTable(std::vector<std::string> header) : header_(std::move(header)) {}

void TextTable::add_section(std::string title) { lines_.push_back({true, {std::move(title)}}); }

void TextTable::add_row(std::vector<std::string> cells) {
  assert(cells.size() <= header_.size());
  cells.resize(header_.size());
  lines_.push_back({false, std::move(cells)});
}

std::string TextTable::render() const {
  std::vector<std::size_t> width(header_.size(), 0);
  auto measure = [&](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) {
      width[i] = std::max(width[i], display_width(cells[i]));
    }
  };
  measure(header_);
  for (const Line& l : lines_) {
    if (!l.section) measure(l.cells);
  }
  auto pad = [](const std::string& s, std::size_t w, bool left) {
    const std::string fill(w > display_width(s) ? w - display_width(s) : 0, ' ');
    return left ? s + fill : fill + s;
  };
  auto row = [&](const std::vector<std::string>& cells) {
    std::string out;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (i > 0) out += "  ";
      out += pad(cells[i], width[i], i == 0);
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out + "\n";
  };
  std::string out = row(header_);
  for (const Line& l : lines_) out += l.section ? l.cells.front() + "\n" : row(l.cells);
  return out;
}

}  // namespace swarm::tools
