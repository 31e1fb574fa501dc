// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// ssmd_viewer: drag a mesh in the browser. A small HTTP + WebSocket server
// (Boost.Beast, synchronous, one thread per connection) that serves the
// page and runs one deformation session per WebSocket connection. See
// doc/viewer.md.

#include "Viewer_session.h"

#include <CLI/CLI.hpp>

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/version.hpp>
#include <boost/beast/websocket.hpp>

#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <thread>

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace net = boost::asio;
using tcp = net::ip::tcp;

namespace {

struct Server_options
{
  std::string mesh_file;
  std::string host = "127.0.0.1";
  unsigned short port = 8080;
  std::string web_dir = SSMD_VIEWER_WEB_DIR;
  std::string three_dir = SSMD_VIEWER_THREE_DIR;
  unsigned int subdivide = 0;
  std::size_t max_message_bytes = 16u << 20;
  ssmd_viewer::Session_options session;
};

struct Static_file
{
  std::string path;
  const char* content_type;
};

// The only files the server ever reads after start-up: URL paths map to
// fixed files, nothing of the request reaches the file system.
std::map<std::string, Static_file> static_files(const Server_options& options)
{
  std::map<std::string, Static_file> files;
  files["/"] = {options.web_dir + "/index.html", "text/html; charset=utf-8"};
  files["/index.html"] = files["/"];
  files["/main.js"] = {options.web_dir + "/main.js", "text/javascript; charset=utf-8"};
  for(const char* name : {"three.module.js", "three.core.js"})
    files[std::string("/three/") + name] = {options.three_dir + "/build/" + name, "text/javascript; charset=utf-8"};
  for(const char* name : {"OrbitControls.js", "TransformControls.js"})
    files[std::string("/three/addons/controls/") + name] = {options.three_dir + "/examples/jsm/controls/" + name,
                                                            "text/javascript; charset=utf-8"};
  return files;
}

// Host of a "host:port" or "[v6]:port" header value, lower case.
std::string host_name(std::string value)
{
  for(char& c : value)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if(!value.empty() && value[0] == '[')
    return value.substr(0, value.find(']') + 1);
  return value.substr(0, value.find(':'));
}

// A page of another site may open a WebSocket to localhost, and a DNS name
// rebound to 127.0.0.1 may reach the HTTP server: requests must name the
// server by a loopback address or the address it was started with (any
// name when it listens on all addresses), and a WebSocket must come from a
// page of the same host.
bool trusted_request(const http::request<http::string_body>& request, const Server_options& options)
{
  const std::string host = host_name(std::string(request[http::field::host]));
  const bool any_address = options.host == "0.0.0.0" || options.host == "::";
  if(!any_address && host != "localhost" && host != "127.0.0.1" && host != "[::1]" &&
     host != host_name(options.host))
    return false;
  const auto origin = request.find(http::field::origin);
  if(origin == request.end())
    return true;
  std::string value(origin->value());
  const std::size_t scheme = value.find("://");
  return scheme != std::string::npos && host_name(value.substr(scheme + 3)) == host;
}

http::response<http::string_body> respond(const http::request<http::string_body>& request, http::status status,
                                          const std::string& content_type, std::string body)
{
  http::response<http::string_body> response{status, request.version()};
  response.set(http::field::server, "ssmd_viewer");
  response.set(http::field::content_type, content_type);
  response.set(http::field::cache_control, "no-store");
  response.set("X-Content-Type-Options", "nosniff");
  response.keep_alive(request.keep_alive());
  response.body() = std::move(body);
  response.prepare_payload();
  return response;
}

http::response<http::string_body> serve_file(const http::request<http::string_body>& request,
                                             const Server_options& options)
{
  if(request.method() != http::verb::get && request.method() != http::verb::head)
    return respond(request, http::status::method_not_allowed, "text/plain", "only GET\n");
  std::string target(request.target());
  target = target.substr(0, target.find('?'));
  const std::map<std::string, Static_file> files = static_files(options);
  const auto it = files.find(target);
  if(it == files.end())
    return respond(request, http::status::not_found, "text/plain", "not found\n");
  std::ifstream in(it->second.path, std::ios::binary);
  if(!in)
    return respond(request, http::status::internal_server_error, "text/plain",
                   "missing " + it->second.path + " (run scripts/viewer.sh, which installs three.js)\n");
  std::string body((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  http::response<http::string_body> response = respond(request, http::status::ok, it->second.content_type, body);
  if(request.method() == http::verb::head)
    response.body().clear();
  return response;
}

void run_websocket(tcp::socket socket, const http::request<http::string_body>& request,
                   const std::shared_ptr<const ssmd_viewer::Loaded_mesh>& mesh, const Server_options& options)
{
  websocket::stream<tcp::socket> ws(std::move(socket));
  // The size cap is applied below while reading, so that a message over it
  // is answered with an error instead of closing the connection.
  ws.read_message_max(0);
  ws.accept(request);
  ssmd_viewer::Session session(mesh, options.session, [&ws](const ssmd_viewer::Outgoing& message) {
    ws.binary(message.binary);
    ws.write(net::buffer(message.payload));
  });
  session.start();
  for(;;)
  {
    beast::flat_buffer buffer;
    std::size_t bytes = 0;
    bool oversized = false;
    do
    {
      bytes += ws.read_some(buffer, 1 << 16);
      if(bytes > options.max_message_bytes)
      {
        oversized = true;
        buffer.consume(buffer.size());
      }
    } while(!ws.is_message_done());
    if(oversized)
      session.on_oversized(bytes, options.max_message_bytes);
    else if(ws.got_binary())
      session.on_binary(bytes);
    else
      session.on_text(beast::buffers_to_string(buffer.data()));
  }
}

void serve_connection(tcp::socket socket, std::shared_ptr<const ssmd_viewer::Loaded_mesh> mesh,
                      const Server_options& options)
{
  try
  {
    beast::flat_buffer buffer;
    for(;;)
    {
      http::request_parser<http::string_body> parser;
      parser.body_limit(1 << 16);
      http::read(socket, buffer, parser);
      http::request<http::string_body> request = parser.release();
      if(!trusted_request(request, options))
      {
        http::write(socket, respond(request, http::status::forbidden, "text/plain", "forbidden host or origin\n"));
        return;
      }
      if(websocket::is_upgrade(request))
      {
        if(request.target() != "/ws")
        {
          http::write(socket, respond(request, http::status::not_found, "text/plain", "not found\n"));
          return;
        }
        run_websocket(std::move(socket), request, mesh, options);
        return;
      }
      http::response<http::string_body> response = serve_file(request, options);
      http::write(socket, response);
      if(!response.keep_alive())
        return;
    }
  }
  catch(const beast::system_error& e)
  {
    // The page went away: the connection and its session end.
    if(e.code() != http::error::end_of_stream && e.code() != websocket::error::closed &&
       e.code() != net::error::connection_reset && e.code() != net::error::eof)
      std::cerr << "ssmd_viewer: connection ended: " << e.code().message() << "\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "ssmd_viewer: connection ended: " << e.what() << "\n";
  }
}

} // namespace

int main(int argc, char** argv)
{
  Server_options options;
  CLI::App app{"Serves a page in which the mesh is deformed by dragging a handle (see doc/viewer.md)."};
  app.add_option("mesh", options.mesh_file, "the mesh (any format CGAL reads: OFF, OBJ, PLY, STL, ...)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--host", options.host, "address to listen on (default 127.0.0.1: this machine only)");
  app.add_option("--port", options.port, "port to listen on (0: any free port)")->capture_default_str();
  app.add_option("--subdivide", options.subdivide, "rounds of Loop subdivision applied to the mesh")
      ->capture_default_str();
  app.add_option("--frequencies", options.session.frequencies, "number of frequencies m of the basis")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  app.add_option("--iterations", options.session.iterations_per_drag,
                 "solves per drag (each drag continues the iteration of the previous one)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  app.add_option("--rotation-patches", options.session.rotation_patches,
                 "rotations of the iteration fitted per patch of about 1/K of the region (0: per dual vertex)")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t(0), std::size_t(100000000)));
  app.add_option("--refine-iterations", options.session.refine_iterations,
                 "as-rigid-as-possible iterations per update of the Refine button")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_option("--refine-max-iterations", options.session.refine_max_iterations,
                 "as-rigid-as-possible iterations of Refine at most, since the last drag")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  app.add_option("--refine-tolerance", options.session.refine_tolerance,
                 "Refine stops when an iteration lowers the energy by less than this fraction of it")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--max-message", options.max_message_bytes, "largest command accepted, in bytes")
      ->capture_default_str();
  app.add_option("--web-dir", options.web_dir, "folder of index.html and main.js")->capture_default_str();
  app.add_option("--three-dir", options.three_dir, "the npm package three (its folder)")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  try
  {
    std::cerr << "ssmd_viewer: reading " << options.mesh_file << "\n";
    std::shared_ptr<const ssmd_viewer::Loaded_mesh> mesh =
        ssmd_viewer::load_mesh(options.mesh_file, options.subdivide);
    net::io_context context;
    tcp::acceptor acceptor(context, tcp::endpoint(net::ip::make_address(options.host), options.port));
    const unsigned short port = acceptor.local_endpoint().port();
    const std::string host = options.host.find(':') != std::string::npos ? "[" + options.host + "]" : options.host;
    std::cout << "ssmd_viewer: " << ssmd_viewer::number_of_vertices(*mesh) << " vertices, "
              << ssmd_viewer::number_of_faces(*mesh) << " faces; open http://" << host << ":" << port << "/"
              << std::endl;
    for(;;)
    {
      tcp::socket socket(context);
      acceptor.accept(socket);
      // A reply is a JSON header then its binary positions: with Nagle's
      // algorithm the second write waits for the acknowledgement of the
      // first, which the browser delays (tens of milliseconds per drag).
      socket.set_option(tcp::no_delay(true));
      std::thread(serve_connection, std::move(socket), mesh, std::cref(options)).detach();
    }
  }
  catch(const ssmd_viewer::Mesh_error& e)
  {
    std::cerr << "ssmd_viewer: error: " << e.what() << "\n";
    return 1;
  }
  catch(const std::exception& e)
  {
    std::cerr << "ssmd_viewer: error: " << e.what() << "\n";
    return 1;
  }
}
