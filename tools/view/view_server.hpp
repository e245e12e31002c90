// `swarm view`'s server: HTTP on one address and port, serving the viewer's page and the data it
// asks for, and, for a live view, a WebSocket that speaks Foxglove's protocol
// (foxglove.websocket.v1), so that Foxglove and Lichtblick can connect as well as our page.
// websocketpp over standalone asio (Debian's libwebsocketpp-dev and libasio-dev, header-only): one
// small library for both the HTTP and the WebSocket on one port, without Boost.
//
// The WebSocket (live only), as the protocol says: on connecting, the client gets serverInfo and
// an advertise of every channel (JSON encoding, a JSON Schema each); it subscribes with
// {"op":"subscribe","subscriptions":[{"id":S,"channelId":C}]} (and unsubscribes with
// {"op":"unsubscribe","subscriptionIds":[S]}); then, 20 times a second, every channel it is
// subscribed to that has something newer comes as a binary frame: 0x01, uint32 S, uint64 log time
// (ns), the message's JSON. A client that reads too slowly is skipped until it catches up; one that
// goes away changes nothing for the others or for the run.
//
//   ViewRoutes routes = {{"/", {"text/html", page}}, {"/run.json", {"application/json", json}}};
//   return serve(options, routes, std::cout, std::cerr);                 // replay: until a signal
//   serve(options, routes, out, err, &live_view, &stop);                 // live: until `stop` too
#pragma once

#include <atomic>
#include <map>
#include <ostream>
#include <string>
#include <utility>

#include "live_feed.hpp"

namespace swarm::tools {

struct ViewServerOptions {
  std::string bind = "127.0.0.1";  // loopback only unless told otherwise
  int port = 8765;
};

// path -> (content type, body). "/" is also served for "/index.html"; a query string is ignored.
using ViewRoutes = std::map<std::string, std::pair<std::string, std::string>>;

// Serves `routes` (and `live`'s WebSocket) until SIGINT or SIGTERM (without `stop`), or until
// `stop` turns true: 0 then. 2 when the address is not an IP address or the port cannot be listened on (in use), with
// a message on `err` naming it. `listening`, when given, turns true once connections are taken.
int serve(const ViewServerOptions& options, const ViewRoutes& routes, std::ostream& out, std::ostream& err,
          const LiveFeed* live = nullptr, const std::atomic<bool>* stop = nullptr, std::atomic<bool>* listening = nullptr);

// The viewer's page (tools/view/page/index.html, built in).
const std::string& view_page();

}  // namespace swarm::tools
