// `swarm view`'s server: HTTP on one address and port, serving the viewer's page and the data it
// asks for, until SIGINT or SIGTERM. websocketpp over standalone asio (Debian's
// libwebsocketpp-dev and libasio-dev, header-only): one small library that serves both the HTTP the
// page needs and the WebSocket a live view speaks, on one port, without Boost.
//
//   ViewServer::Options o;             // 127.0.0.1:8765
//   ViewServer::Routes routes = {{"/", {"text/html", page}}, {"/run.json", {"application/json", json}}};
//   return serve(o, routes, std::cout, std::cerr);   // 0 after a signal; 2: cannot listen
#pragma once

#include <map>
#include <ostream>
#include <string>
#include <utility>

namespace swarm::tools {

struct ViewServerOptions {
  std::string bind = "127.0.0.1";  // loopback only unless told otherwise
  int port = 8765;
};

// path -> (content type, body). "/" is also served for "/index.html"; a query string is ignored.
using ViewRoutes = std::map<std::string, std::pair<std::string, std::string>>;

// Serves `routes` until SIGINT or SIGTERM: 0 then. 2 when the address is not an IP address or the
// port cannot be listened on (in use), with a message on `err` naming it.
int serve(const ViewServerOptions& options, const ViewRoutes& routes, std::ostream& out, std::ostream& err);

// The viewer's page (tools/view/page/index.html, built in).
const std::string& view_page();

}  // namespace swarm::tools
