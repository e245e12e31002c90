// What a live view sends over the viewer's WebSocket (view_server.hpp): fixed channels in
// Foxglove's schemas, and the messages newer than what a connection has had.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace swarm::tools {

struct LiveChannel {
  std::uint32_t id = 0;
  std::string topic, schema_name, schema;  // schema: a JSON Schema (encoding jsonschema)
};

struct LiveMessage {
  std::uint32_t channel = 0;
  std::uint64_t ns = 0;  // log time
  std::string json;
};

class LiveFeed {
 public:
  virtual ~LiveFeed() = default;
  [[nodiscard]] virtual std::vector<LiveChannel> channels() const = 0;
  // The messages newer than `cursor` (a connection's, empty at first), which it advances: the
  // newest state of each channel, and every log line not yet sent. Thread-safe.
  [[nodiscard]] virtual std::vector<LiveMessage> since(std::vector<std::uint64_t>& cursor) const = 0;
  // The page's setup (/live.json): map size and frame, robot names, groups.
  [[nodiscard]] virtual std::string setup_json() const = 0;
};

}  // namespace swarm::tools
