#include "view_server.hpp"

#include <chrono>
#include <csignal>
#include <optional>
#include <nlohmann/json.hpp>
#include <websocketpp/config/asio_no_tls.hpp>
#include <websocketpp/server.hpp>

namespace swarm::tools {

namespace {
using Server = websocketpp::server<websocketpp::config::asio>;
constexpr const char* kProtocol = "foxglove.websocket.v1";
constexpr auto kSendEvery = std::chrono::milliseconds(50);
constexpr std::size_t kMostBuffered = 8u << 20;  // bytes queued for a client before it is skipped

struct Client {
  std::map<std::uint32_t, std::uint32_t> subscription_of;  // channel -> subscription id
  std::vector<std::uint64_t> cursor;                        // LiveFeed::since's
};

void put_le(std::string& s, std::uint64_t v, int bytes) {
  for (int b = 0; b < bytes; ++b) s.push_back(static_cast<char>((v >> (8 * b)) & 0xFF));
}
}  // namespace

int serve(const ViewServerOptions& options, const ViewRoutes& routes, std::ostream& out, std::ostream& err,
          const LiveFeed* live, const std::atomic<bool>* stop, std::atomic<bool>* listening) {
  const std::string where = options.bind + ":" + std::to_string(options.port);
  std::error_code ec;
  const asio::ip::address address = asio::ip::make_address(options.bind, ec);
  if (ec) {
    err << "swarm view: --view-bind " << options.bind << " is not an IP address\n";
    return 2;
  }
  Server server;
  server.clear_access_channels(websocketpp::log::alevel::all);
  server.clear_error_channels(websocketpp::log::elevel::all);
  server.init_asio();
  server.set_reuse_addr(true);  // a port left in TIME_WAIT by the last run; one listened on still refuses
  server.set_http_handler([&](websocketpp::connection_hdl h) {
    const Server::connection_ptr con = server.get_con_from_hdl(h);
    std::string path = con->get_resource();
    path = path.substr(0, path.find('?'));
    if (path == "/index.html") path = "/";
    const auto it = routes.find(path);
    if (it == routes.end()) {
      con->set_status(websocketpp::http::status_code::not_found);
      con->set_body("not found: " + path + "\n");
      return;
    }
    con->set_status(websocketpp::http::status_code::ok);
    con->append_header("Content-Type", it->second.first);
    con->append_header("Cache-Control", "no-store");
    con->set_body(it->second.second);
  });

  // The live WebSocket: every handler and the timer run on the one asio thread.
  std::map<websocketpp::connection_hdl, Client, std::owner_less<websocketpp::connection_hdl>> clients;
  std::vector<LiveChannel> channels;
  if (live != nullptr) channels = live->channels();
  server.set_validate_handler([&](websocketpp::connection_hdl h) {
    if (live == nullptr) return false;  // a replay has no WebSocket
    const Server::connection_ptr con = server.get_con_from_hdl(h);
    for (const std::string& p : con->get_requested_subprotocols()) {
      if (p == kProtocol) {
        con->select_subprotocol(kProtocol);
        return true;
      }
    }
    return false;
  });
  server.set_open_handler([&](websocketpp::connection_hdl h) {
    clients[h] = Client{};
    nlohmann::json advertise = {{"op", "advertise"}, {"channels", nlohmann::json::array()}};
    for (const LiveChannel& c : channels) {
      advertise["channels"].push_back({{"id", c.id},
                                       {"topic", c.topic},
                                       {"encoding", "json"},
                                       {"schemaName", c.schema_name},
                                       {"schema", c.schema},
                                       {"schemaEncoding", "jsonschema"}});
    }
    const nlohmann::json info = {{"op", "serverInfo"},
                                 {"name", "swarm"},
                                 {"capabilities", nlohmann::json::array()},
                                 {"supportedEncodings", {"json"}},
                                 {"metadata", nlohmann::json::object()}};
    std::error_code ignored;
    server.send(h, info.dump(), websocketpp::frame::opcode::text, ignored);
    server.send(h, advertise.dump(), websocketpp::frame::opcode::text, ignored);
  });
  server.set_close_handler([&](websocketpp::connection_hdl h) { clients.erase(h); });
  server.set_fail_handler([&](websocketpp::connection_hdl h) { clients.erase(h); });
  server.set_message_handler([&](websocketpp::connection_hdl h, Server::message_ptr m) {
    const auto it = clients.find(h);
    if (it == clients.end() || m->get_opcode() != websocketpp::frame::opcode::text) return;
    const nlohmann::json j = nlohmann::json::parse(m->get_payload(), nullptr, false);
    if (!j.is_object() || !j.contains("op") || !j["op"].is_string()) return;  // not the protocol: ignored
    Client& c = it->second;
    if (j["op"] == "subscribe" && j.contains("subscriptions") && j["subscriptions"].is_array()) {
      for (const auto& s : j["subscriptions"]) {
        if (!s.is_object() || !s.contains("id") || !s.contains("channelId") || !s["id"].is_number_unsigned() ||
            !s["channelId"].is_number_unsigned()) {
          continue;
        }
        c.subscription_of[s["channelId"].get<std::uint32_t>()] = s["id"].get<std::uint32_t>();
      }
      c.cursor.clear();  // the newest of every channel again, for the new subscription
    } else if (j["op"] == "unsubscribe" && j.contains("subscriptionIds") && j["subscriptionIds"].is_array()) {
      for (const auto& id : j["subscriptionIds"]) {
        for (auto s = c.subscription_of.begin(); s != c.subscription_of.end();) {
          s = id.is_number_unsigned() && s->second == id.get<std::uint32_t>() ? c.subscription_of.erase(s) : std::next(s);
        }
      }
    }
  });

  server.listen(asio::ip::tcp::endpoint(address, static_cast<unsigned short>(options.port)), ec);
  if (ec) {
    err << "swarm view: cannot listen on " << where << ": " << ec.message()
        << (ec == std::errc::address_in_use ? " (another program has it; choose one with --view-port)" : "") << "\n";
    return 2;
  }
  server.start_accept(ec);
  if (ec) {
    err << "swarm view: cannot accept on " << where << ": " << ec.message() << "\n";
    return 2;
  }
  const auto finish = [&] {
    std::error_code ignored;
    server.stop_listening(ignored);
    for (const auto& [h, c] : clients) server.close(h, websocketpp::close::status::going_away, "the view stops", ignored);
    server.stop();
  };
  // Alone, the server stops on a signal; beside a run (`stop` given), the run's supervisor owns the
  // signals and says when to stop.
  std::optional<asio::signal_set> signals;
  if (stop == nullptr) {
    signals.emplace(server.get_io_service(), SIGINT, SIGTERM);
    signals->async_wait([&](const std::error_code&, int) { finish(); });
  }
  asio::steady_timer timer(server.get_io_service());
  std::function<void(const std::error_code&)> tick = [&](const std::error_code& e) {
    if (e) return;
    if (stop != nullptr && stop->load()) {
      finish();
      return;
    }
    for (auto& [h, c] : clients) {
      if (c.subscription_of.empty()) continue;
      std::error_code send_error;
      const Server::connection_ptr con = server.get_con_from_hdl(h, send_error);
      if (send_error || con->get_buffered_amount() > kMostBuffered) continue;
      for (const LiveMessage& m : live->since(c.cursor)) {
        const auto s = c.subscription_of.find(m.channel);
        if (s == c.subscription_of.end()) continue;
        std::string frame;
        frame.reserve(13 + m.json.size());
        frame.push_back('\x01');
        put_le(frame, s->second, 4);
        put_le(frame, m.ns, 8);
        frame += m.json;
        server.send(h, frame, websocketpp::frame::opcode::binary, send_error);
      }
    }
    timer.expires_after(kSendEvery);
    timer.async_wait(tick);
  };
  timer.expires_after(kSendEvery);
  timer.async_wait(tick);
  out << "swarm view: http://" << where << "/ (Ctrl-C to stop)" << std::endl;
  if (listening != nullptr) listening->store(true);
  server.run();
  return 0;
}

}  // namespace swarm::tools
