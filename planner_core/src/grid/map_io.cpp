#include "swarm/planner/grid/map_io.hpp"

#include <yaml-cpp/yaml.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <opencv2/imgcodecs.hpp>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

namespace swarm::planner {
namespace {

namespace fs = std::filesystem;

// Grids index cells with an int; keep well clear of overflow and of absurd allocations.
constexpr long long kMaxCells = 1LL << 28;

// PGM values save_map_yaml writes (map_server's map_saver conventions).
constexpr std::uint8_t kPgmFree = 254;
constexpr std::uint8_t kPgmOccupied = 0;
constexpr std::uint8_t kPgmUnknown = 205;
constexpr double kDefaultOccupiedThresh = 0.65;
constexpr double kDefaultFreeThresh = 0.196;

[[noreturn]] void fail(const std::string& file, int line, const std::string& what) {
  std::ostringstream os;
  os << file;
  if (line > 0) os << ':' << line;
  os << ": " << what;
  throw MapFileError(os.str());
}

std::string in_quotes(std::string_view s) {
  constexpr std::size_t kMax = 60;  // keep messages one readable line
  std::string out = "\"";
  for (std::size_t i = 0; i < s.size() && i < kMax; ++i) out += s[i] == '\n' ? ' ' : s[i];
  if (s.size() > kMax) out += "...";
  return out + "\"";
}

// ---------------------------------------------------------------------------------------------
// Numbers: parsed with from_chars so that what save_map_yaml writes (to_chars, shortest form)
// comes back bit-identical.

std::optional<double> parse_double(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<long long> parse_int(std::string_view s) {
  long long v = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || ptr != s.data() + s.size() || s.empty()) return std::nullopt;
  return v;
}

std::string format_double(double v) {
  char buf[64];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, ptr);
}

// ---------------------------------------------------------------------------------------------
// YAML helpers. yaml-cpp marks are 0-based; editors count from 1.

int line_of(const YAML::Node& n) {
  const YAML::Mark m = n.Mark();
  return m.is_null() ? 0 : m.line + 1;
}

std::string shown(const YAML::Node& n) {
  if (n.IsScalar()) return in_quotes(n.Scalar());
  if (n.IsNull()) return "nothing";
  YAML::Emitter e;
  e << YAML::Flow << n;
  return in_quotes(e.c_str());
}

double number_or_fail(const YAML::Node& n, const std::string& file, const std::string& what) {
  std::optional<double> v;
  if (n.IsScalar()) v = parse_double(n.Scalar());
  if (!v) fail(file, line_of(n), what + " (got " + shown(n) + ")");
  return *v;
}

// ---------------------------------------------------------------------------------------------
// PGM (netpbm "portable graymap"): magic, width, height, maxval as whitespace-separated ASCII
// fields, '#' comments allowed between them; then P5 = binary bytes, P2 = ASCII integers.

struct GreyImage {
  int width = 0;
  int height = 0;
  int maxval = 255;
  std::vector<std::uint8_t> pixels;  // row-major, first row = top
};

class PgmReader {
 public:
  PgmReader(std::string file, std::string bytes) : file_(std::move(file)), s_(std::move(bytes)) {}

  GreyImage read() {
    const std::string magic = token();
    if (magic != "P5" && magic != "P2") {
      fail(file_, 0,
           "PGM header field 'magic number': expected P5 (binary) or P2 (ASCII) (got " +
               in_quotes(magic) + ")");
    }
    GreyImage img;
    img.width = header_int("width", 1, std::numeric_limits<int>::max(), "a positive integer");
    img.height = header_int("height", 1, std::numeric_limits<int>::max(), "a positive integer");
    if (static_cast<long long>(img.width) * img.height > kMaxCells) {
      fail(file_, 0,
           "PGM header fields 'width' x 'height': " + std::to_string(img.width) + " x " +
               std::to_string(img.height) + " is too large (at most " +
               std::to_string(kMaxCells) + " cells)");
    }
    img.maxval = header_int("maxval", 1, 255, "an integer 1..255 (16-bit PGMs are not supported)");
    const std::size_t n =
        static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height);
    img.pixels.resize(n);
    if (magic == "P5") {
      // Exactly one whitespace character separates maxval from the binary data.
      if (pos_ >= s_.size() || !is_space(s_[pos_])) {
        fail(file_, 0, "PGM header field 'maxval': expected one whitespace character after it");
      }
      ++pos_;
      if (s_.size() - pos_ < n) {
        fail(file_, 0,
             "PGM pixel data: expected " + std::to_string(n) + " bytes (" +
                 std::to_string(img.width) + " x " + std::to_string(img.height) +
                 ") after the header, found " + std::to_string(s_.size() - pos_));
      }
      if (s_.size() - pos_ > n) {
        fail(file_, 0,
             "PGM pixel data: expected " + std::to_string(n) + " bytes (" + std::to_string(img.width) + " x " +
                 std::to_string(img.height) + ") after the header, found " + std::to_string(s_.size() - pos_) +
                 " (more than one image, or a header that does not match the picture)");
      }
      for (std::size_t i = 0; i < n; ++i) {
        img.pixels[i] = static_cast<std::uint8_t>(s_[pos_ + i]);
        if (img.pixels[i] > img.maxval) bad_pixel(img, i, std::to_string(img.pixels[i]));
      }
    } else {
      for (std::size_t i = 0; i < n; ++i) {
        const std::string t = token();
        const std::optional<long long> v = parse_int(t);
        if (!v || *v < 0 || *v > img.maxval) {
          bad_pixel(img, i, t.empty() ? "end of file" : in_quotes(t));
        }
        img.pixels[i] = static_cast<std::uint8_t>(*v);
      }
      if (const std::string extra = token(); !extra.empty()) {
        fail(file_, 0,
             "PGM pixel data: expected " + std::to_string(n) + " values (" + std::to_string(img.width) + " x " +
                 std::to_string(img.height) + "), found more (" + in_quotes(extra) +
                 " after the last); the header does not match the picture");
      }
    }
    return img;
  }

 private:
  static bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
  }

  // Next whitespace-separated field, skipping '#' comments; empty at end of file.
  std::string token() {
    for (;;) {
      while (pos_ < s_.size() && is_space(s_[pos_])) ++pos_;
      if (pos_ < s_.size() && s_[pos_] == '#') {
        while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
        continue;
      }
      break;
    }
    const std::size_t begin = pos_;
    while (pos_ < s_.size() && !is_space(s_[pos_]) && s_[pos_] != '#') ++pos_;
    return s_.substr(begin, pos_ - begin);
  }

  int header_int(const char* field, long long lo, long long hi, const char* expected) {
    const std::string t = token();
    const std::optional<long long> v = parse_int(t);
    if (!v || *v < lo || *v > hi) {
      fail(file_, 0,
           std::string("PGM header field '") + field + "': expected " + expected + " (got " +
               (t.empty() ? std::string("end of file") : in_quotes(t)) + ")");
    }
    return static_cast<int>(*v);
  }

  [[noreturn]] void bad_pixel(const GreyImage& img, std::size_t i, const std::string& got) {
    fail(file_, 0,
         "PGM pixel " + std::to_string(i) + " (row " + std::to_string(i / img.width) + ", column " +
             std::to_string(i % img.width) + "): expected an integer 0.." +
             std::to_string(img.maxval) + " (got " + got + ")");
  }

  std::string file_;
  std::string s_;
  std::size_t pos_ = 0;
};

std::optional<std::string> read_file(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return std::nullopt;  // it would read as an empty file
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool has_pgm_extension(const fs::path& p) {
  std::string ext = p.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".pgm";
}

GreyImage read_image(const std::string& path) {
  if (has_pgm_extension(path)) {
    std::optional<std::string> bytes = read_file(path);
    if (!bytes) fail(path, 0, "cannot open the image file");
    return PgmReader(path, std::move(*bytes)).read();
  }
  const cv::Mat m = cv::imread(path, cv::IMREAD_GRAYSCALE);
  if (m.empty() || m.type() != CV_8UC1) {
    fail(path, 0, "cannot read the image (expected a PGM, or an 8-bit image OpenCV can decode)");
  }
  GreyImage img;
  img.width = m.cols;
  img.height = m.rows;
  img.pixels.resize(static_cast<std::size_t>(m.cols) * static_cast<std::size_t>(m.rows));
  for (int r = 0; r < m.rows; ++r) {
    const std::uint8_t* row = m.ptr<std::uint8_t>(r);
    std::copy(row, row + m.cols, img.pixels.begin() + static_cast<std::ptrdiff_t>(r) * m.cols);
  }
  return img;
}

}  // namespace

OccupancyGrid load_map_yaml(const std::string& yaml_path) {
  std::optional<std::string> text = read_file(yaml_path);
  if (!text) fail(yaml_path, 0, "cannot open the map file (check the path)");
  YAML::Node root;
  try {
    root = YAML::Load(*text);
  } catch (const YAML::ParserException& e) {
    fail(yaml_path, e.mark.is_null() ? 0 : e.mark.line + 1, "invalid YAML: " + e.msg);
  }
  if (!root.IsMap()) {
    fail(yaml_path, line_of(root) > 0 ? line_of(root) : 1,
         "expected a YAML mapping with keys image, resolution and origin (map_server format)");
  }
  const auto require = [&](const char* key, const char* expected) {
    YAML::Node n = root[key];
    if (!n) {
      fail(yaml_path, line_of(root),
           std::string("missing key '") + key + "' (expected " + expected + ")");
    }
    return n;
  };

  // mode first: a scale/raw map must not be silently read as trinary.
  if (YAML::Node mode = root["mode"]) {
    if (!mode.IsScalar() || mode.Scalar() != "trinary") {
      fail(yaml_path, line_of(mode),
           "mode " + shown(mode) +
               " is not supported (expected trinary, the default; re-save scale/raw maps as "
               "trinary)");
    }
  }

  const YAML::Node image = require("image", "the image file name, relative to this file");
  if (!image.IsScalar() || image.Scalar().empty()) {
    fail(yaml_path, line_of(image), "image must be a file name (got " + shown(image) + ")");
  }

  const YAML::Node res_node = require("resolution", "a positive number, metres per cell");
  const double resolution =
      number_or_fail(res_node, yaml_path, "resolution must be a positive number");
  if (!(resolution >= kMinResolutionM && resolution <= kMaxResolutionM)) {
    fail(yaml_path, line_of(res_node),
         "resolution must be a number of metres per cell in [" + format_double(kMinResolutionM) + ", " +
             format_double(kMaxResolutionM) + "] (got " + shown(res_node) + ")");
  }

  const YAML::Node origin = require("origin", "a list [x, y, yaw] in metres and radians");
  if (!origin.IsSequence() || origin.size() != 3) {
    fail(yaml_path, line_of(origin),
         "origin must be a list of three numbers [x, y, yaw] (got " + shown(origin) + ")");
  }
  const char* const origin_names[3] = {"x", "y", "yaw"};
  double origin_v[3];
  for (std::size_t i = 0; i < 3; ++i) {
    origin_v[i] = number_or_fail(origin[i], yaml_path,
                                 std::string("origin ") + origin_names[i] + " must be a number");
    if (std::abs(origin_v[i]) > kMaxOriginM) {
      fail(yaml_path, line_of(origin), std::string("origin ") + origin_names[i] + " must be within +-" +
                                           format_double(kMaxOriginM) + " (got " + shown(origin[i]) + ")");
    }
  }

  bool negate = false;
  if (YAML::Node n = root["negate"]) {
    const std::string s = n.IsScalar() ? n.Scalar() : std::string();
    if (s == "1" || s == "true") {
      negate = true;
    } else if (s != "0" && s != "false") {
      fail(yaml_path, line_of(n), "negate must be 0 or 1 (got " + shown(n) + ")");
    }
  }

  const auto threshold = [&](const char* key, double fallback) {
    YAML::Node n = root[key];
    if (!n) return fallback;
    const std::string what = std::string(key) + " must be a number between 0 and 1";
    const double v = number_or_fail(n, yaml_path, what);
    if (v < 0.0 || v > 1.0) fail(yaml_path, line_of(n), what + " (got " + shown(n) + ")");
    return v;
  };
  const double occupied_thresh = threshold("occupied_thresh", kDefaultOccupiedThresh);
  const double free_thresh = threshold("free_thresh", kDefaultFreeThresh);
  if (free_thresh > occupied_thresh) {
    const YAML::Node n = root["free_thresh"] ? root["free_thresh"] : root["occupied_thresh"];
    fail(yaml_path, line_of(n),
         "free_thresh (" + format_double(free_thresh) + ") must not exceed occupied_thresh (" +
             format_double(occupied_thresh) + ")");
  }

  fs::path image_path(image.Scalar());
  if (image_path.is_relative()) image_path = fs::path(yaml_path).parent_path() / image_path;
  std::error_code ec;
  if (!fs::is_regular_file(image_path, ec)) {
    fail(yaml_path, line_of(image),
         "image " + in_quotes(image.Scalar()) + " not found (looked for " + image_path.string() +
             "; relative image paths are resolved from the YAML file's folder)");
  }

  const GreyImage img = read_image(image_path.string());
  OccupancyGrid grid(img.width, img.height, resolution, origin_v[0], origin_v[1]);
  const double m = img.maxval;
  for (int r = 0; r < img.height; ++r) {
    const int y = img.height - 1 - r;  // first image row is the top of the map
    for (int x = 0; x < img.width; ++x) {
      const double v = img.pixels[static_cast<std::size_t>(r) * img.width + x];
      const double p = negate ? v / m : (m - v) / m;
      CellState s = CellState::Unknown;
      if (p > occupied_thresh) {
        s = CellState::Occupied;
      } else if (p < free_thresh) {
        s = CellState::Free;
      }
      grid.set(Cell{x, y}, s);
    }
  }
  return grid;
}

void save_map_yaml(const std::string& yaml_path, const OccupancyGrid& map) {
  fs::path pgm_path(yaml_path);
  pgm_path.replace_extension(".pgm");

  std::string pgm = "P5\n# swarm occupancy grid: free 254, occupied 0, unknown 205\n" +
                    std::to_string(map.width()) + " " + std::to_string(map.height()) + "\n255\n";
  const std::size_t header = pgm.size();
  pgm.resize(header + map.size());
  for (int r = 0; r < map.height(); ++r) {
    const int y = map.height() - 1 - r;
    for (int x = 0; x < map.width(); ++x) {
      std::uint8_t v = kPgmUnknown;
      switch (map.at(Cell{x, y})) {
        case CellState::Free: v = kPgmFree; break;
        case CellState::Occupied: v = kPgmOccupied; break;
        case CellState::Unknown: v = kPgmUnknown; break;
      }
      pgm[header + static_cast<std::size_t>(r) * map.width() + x] = static_cast<char>(v);
    }
  }
  {
    std::ofstream out(pgm_path, std::ios::binary | std::ios::trunc);
    if (!out || !out.write(pgm.data(), static_cast<std::streamsize>(pgm.size()))) {
      fail(pgm_path.string(), 0, "cannot write the image file (does the folder exist?)");
    }
  }

  std::ostringstream yaml;
  yaml << "image: " << pgm_path.filename().string() << "\n"
       << "mode: trinary\n"
       << "resolution: " << format_double(map.resolution()) << "\n"
       << "origin: [" << format_double(map.origin_x()) << ", " << format_double(map.origin_y())
       << ", 0]\n"
       << "negate: 0\n"
       << "occupied_thresh: " << format_double(kDefaultOccupiedThresh) << "\n"
       << "free_thresh: " << format_double(kDefaultFreeThresh) << "\n";
  std::ofstream out(yaml_path, std::ios::trunc);
  const std::string s = yaml.str();
  if (!out || !out.write(s.data(), static_cast<std::streamsize>(s.size()))) {
    fail(yaml_path, 0, "cannot write the map file (does the folder exist?)");
  }
}

OccupancyGrid load_movingai_map(const std::string& path, double resolution_m) {
  std::error_code ec;
  std::ifstream in(path);
  if (!in || fs::is_directory(path, ec)) fail(path, 0, "cannot open the MovingAI map file (check the path)");
  int line_no = 0;
  std::string line;
  const auto next_line = [&]() -> bool {
    if (!std::getline(in, line)) return false;
    ++line_no;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) {
      line.pop_back();
    }
    return true;
  };
  const auto header_value = [&](const char* key, const char* expected) -> std::string {
    if (!next_line()) {
      fail(path, line_no + 1, std::string("expected \"") + expected + "\", found end of file");
    }
    std::istringstream ls(line);
    std::string k, v, extra;
    ls >> k >> v;
    if (k != key || v.empty() || (ls >> extra)) {
      fail(path, line_no,
           std::string("expected \"") + expected + "\" (got " + in_quotes(line) + ")");
    }
    return v;
  };
  const auto dimension = [&](const char* key, const char* expected) {
    const std::string v = header_value(key, expected);
    const std::optional<long long> n = parse_int(v);
    if (!n || *n < 1 || *n > (1 << 20)) {
      fail(path, line_no,
           std::string(key) + " must be a positive integer (got " + in_quotes(v) + ")");
    }
    return static_cast<int>(*n);
  };

  header_value("type", "type octile");
  const int height = dimension("height", "height <rows>");
  const int width = dimension("width", "width <columns>");
  if (static_cast<long long>(width) * height > kMaxCells) {
    fail(path, line_no,
         "map of " + std::to_string(width) + " x " + std::to_string(height) + " is too large");
  }
  if (!next_line() || line != "map") {
    fail(path, line_no, "expected \"map\" before the rows (got " + in_quotes(line) + ")");
  }

  if (!(resolution_m >= kMinResolutionM && resolution_m <= kMaxResolutionM)) {
    fail(path, 0, "resolution must be a number of metres per cell in [" + format_double(kMinResolutionM) + ", " +
                      format_double(kMaxResolutionM) + "] (got " + format_double(resolution_m) + ")");
  }
  OccupancyGrid grid(width, height, resolution_m);
  for (int r = 0; r < height; ++r) {
    if (!next_line()) {
      fail(path, line_no + 1,
           "expected " + std::to_string(height) + " map rows (height), found " + std::to_string(r));
    }
    if (static_cast<int>(line.size()) != width) {
      fail(path, line_no,
           "map row " + std::to_string(r) + " has " + std::to_string(line.size()) +
               " characters, expected " + std::to_string(width) + " (width)");
    }
    const int y = height - 1 - r;  // first row is the top
    for (int x = 0; x < width; ++x) {
      const char c = line[static_cast<std::size_t>(x)];
      const bool passable = c == '.' || c == 'G' || c == 'S';
      grid.set(Cell{x, y}, passable ? CellState::Free : CellState::Occupied);
    }
  }
  while (next_line()) {
    if (!line.empty()) {
      fail(path, line_no,
           "a map row past the " + std::to_string(height) + " rows the header gives (height " + std::to_string(height) +
               "): fix height, or remove the extra rows (got " + in_quotes(line.substr(0, 40)) + ")");
    }
  }
  return grid;
}

void save_movingai_map(const std::string& path, const OccupancyGrid& map) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) fail(path, 0, "cannot write the MovingAI map file (check the folder exists and is writable)");
  out << "type octile\nheight " << map.height() << "\nwidth " << map.width() << "\nmap\n";
  for (int y = map.height() - 1; y >= 0; --y) {  // the first row is the top
    std::string row(static_cast<std::size_t>(map.width()), '@');
    for (int x = 0; x < map.width(); ++x) {
      const CellState s = map.at(Cell{x, y});
      row[static_cast<std::size_t>(x)] = s == CellState::Free ? '.' : s == CellState::Unknown ? 'T' : '@';
    }
    out << row << '\n';
  }
  if (!out.flush()) fail(path, 0, "cannot write the MovingAI map file");
}

}  // namespace swarm::planner
