#include "swarm/record/path_player.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace swarm::record {

std::string base64(const std::string& bytes) {
  static const char* const kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned b0 = static_cast<unsigned char>(bytes[i]);
    const unsigned b1 = i + 1 < bytes.size() ? static_cast<unsigned char>(bytes[i + 1]) : 0;
    const unsigned b2 = i + 2 < bytes.size() ? static_cast<unsigned char>(bytes[i + 2]) : 0;
    const unsigned v = (b0 << 16) | (b1 << 8) | b2;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[v & 63] : '=';
  }
  return out;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void write_path_player(const std::string& path, const std::string& title, const PathPlayer& p) {
  std::string escaped;  // the title as HTML text
  for (const char c : title) escaped += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  nlohmann::json data;
  data["image"] = "data:image/png;base64," + base64(p.background_png);
  data["scale"] = p.scale;
  data["band"] = p.band;
  data["height"] = p.height;
  data["vanish"] = p.vanish;
  nlohmann::json colours = nlohmann::json::array(), paths = nlohmann::json::array();
  for (const Rgb& c : p.colours) colours.push_back({c.r, c.g, c.b});
  for (const auto& cells : p.paths) {
    nlohmann::json one = nlohmann::json::array();
    for (const planner::Cell c : cells) one.push_back({c.x, c.y});
    paths.push_back(one);
  }
  data["colours"] = colours;
  data["paths"] = paths;
  std::ofstream html(path);
  html << R"(<!doctype html>
<html><head><meta charset="utf-8"><title>)" << escaped << R"(</title>
<style>body{font-family:sans-serif;margin:12px}canvas{image-rendering:pixelated;border:1px solid #ccc;max-width:100%}
#bar{margin:6px 0}</style></head><body>
<div id="bar"><button id="play">Play</button> <button id="prev">&lt;</button> <button id="next">&gt;</button>
<input type="range" id="slider" min="0" value="0" step="1" style="width:420px">
<span id="label"></span> &nbsp; steps/s <select id="speed"><option>1</option><option>2</option><option selected>4</option>
<option>8</option><option>16</option></select></div>
<canvas id="view"></canvas>
<script>
const D = )" << data.dump() << R"(;
const img = new Image();
const view = document.getElementById('view'), ctx = view.getContext('2d');
const slider = document.getElementById('slider'), label = document.getElementById('label');
const horizon = Math.max(1, ...D.paths.map(p => p.length)) - 1;
slider.max = horizon;
let t = 0, playing = false, last = null;
function at(p, k) { return p[Math.min(k, p.length - 1)]; }
function draw() {
  ctx.drawImage(img, 0, 0);
  const k = Math.floor(t), f = t - k, r = Math.max(1.5, D.scale * 0.4);
  D.paths.forEach((p, a) => {
    if (p.length === 0 || (D.vanish && k > p.length - 1)) return;  // arrived and left
    const u = at(p, k), v = at(p, k + 1);
    const x = (u[0] + (v[0] - u[0]) * f + 0.5) * D.scale;
    const y = D.band + (D.height - 1 - (u[1] + (v[1] - u[1]) * f) + 0.5) * D.scale;
    ctx.beginPath(); ctx.arc(x, y, r, 0, 2 * Math.PI);
    ctx.fillStyle = 'rgb(' + D.colours[a].join(',') + ')'; ctx.fill();
    ctx.lineWidth = 1; ctx.strokeStyle = '#222'; ctx.stroke();
  });
  slider.value = k;
  label.textContent = 't = ' + k + ' / ' + horizon;
}
function tick(now) {
  if (!playing) return;
  if (last !== null) t = Math.min(horizon, t + (now - last) / 1000 * Number(document.getElementById('speed').value));
  last = now;
  draw();
  if (t >= horizon) { playing = false; document.getElementById('play').textContent = 'Play'; return; }
  requestAnimationFrame(tick);
}
document.getElementById('play').onclick = () => {
  playing = !playing; last = null;
  if (playing && t >= horizon) t = 0;
  document.getElementById('play').textContent = playing ? 'Pause' : 'Play';
  if (playing) requestAnimationFrame(tick);
};
document.getElementById('prev').onclick = () => { playing = false; t = Math.max(0, Math.ceil(t) - 1); draw(); };
document.getElementById('next').onclick = () => { playing = false; t = Math.min(horizon, Math.floor(t) + 1); draw(); };
slider.oninput = () => { playing = false; t = Number(slider.value); draw(); };
img.onload = () => { view.width = img.width; view.height = img.height; draw(); };
img.src = D.image;
</script></body></html>
)";
  if (!html) throw std::runtime_error("cannot write " + path);
}

}  // namespace swarm::record
