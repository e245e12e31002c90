#include "view_server.hpp"

#include <csignal>
#include <websocketpp/config/asio_no_tls.hpp>
#include <websocketpp/server.hpp>

namespace swarm::tools {

namespace {
using Server = websocketpp::server<websocketpp::config::asio>;
}  // namespace

int serve(const ViewServerOptions& options, const ViewRoutes& routes, std::ostream& out, std::ostream& err) {
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
  server.listen(asio::ip::tcp::endpoint(address, static_cast<unsigned short>(options.port)), ec);
  if (ec) {
    err << "swarm view: cannot listen on " << where << ": " << ec.message()
        << (ec == std::errc::address_in_use ? " (another program has it; choose one with --port)" : "") << "\n";
    return 2;
  }
  server.start_accept(ec);
  if (ec) {
    err << "swarm view: cannot accept on " << where << ": " << ec.message() << "\n";
    return 2;
  }
  asio::signal_set signals(server.get_io_service(), SIGINT, SIGTERM);
  signals.async_wait([&](const std::error_code&, int) {
    std::error_code ignored;
    server.stop_listening(ignored);
    server.stop();
  });
  out << "swarm view: http://" << where << "/ (Ctrl-C to stop)" << std::endl;
  server.run();
  return 0;
}

}  // namespace swarm::tools
