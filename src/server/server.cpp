#include "server/server.h"

#include <httplib.h>
#include <malloc.h>
#include <netinet/in.h>
#include <netinet/tcp.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <list>
#include <memory>
#include <mutex>
#include <optional>
#include <semaphore>
#include <thread>

#include "app/stopping.h"
#include "curdle/error.h"
#include "curdle/text.h"
#include "server/field_socket.h"
#include "server/http_connection.h"
#include "server/websocket.h"

namespace curdle::server {

Params query_params(const std::string& target) {
  Params params;
  const size_t q = target.find('?');
  if (q == std::string::npos) return params;
  const std::string query = target.substr(q + 1);
  for (size_t start = 0; start <= query.size();) {
    size_t end = query.find('&', start);
    if (end == std::string::npos) end = query.size();
    const std::string pair = query.substr(start, end - start);
    if (!pair.empty()) {
      const size_t eq = pair.find('=');
      const std::string key = pair.substr(0, eq);
      const std::string value = eq == std::string::npos ? "" : pair.substr(eq + 1);
      params.emplace(httplib::detail::decode_url(key, true),
                     httplib::detail::decode_url(value, true));
    }
    start = end + 1;
  }
  return params;
}

Params request_params(const std::string& target, const std::string& method,
                      const std::string& body) {
  Params params = query_params(target);
  if (method == "POST" && !body.empty()) {
    Params form = query_params("?" + body);
    params.insert(form.begin(), form.end());
  }
  return params;
}

namespace {
Params params_of(const httplib::Request& req) {
  return request_params(req.target, req.method, req.body);
}
}  // namespace

namespace {

// The paths that take a body: a picture to measure, a site drawing.
constexpr const char* kUpload = "/api/measure";
constexpr const char* kSiteUpload = "/api/site";
// The paths whose query may come by POST as the body, where the address would be too long.
bool takes_query_by_post(const std::string& path) {
  return path == "/api/generate" || path == "/api/field" || path == "/api/export" ||
         path == "/api/search" || path == "/api/colours";
}
// The query as the body's text: httplib reads a form-encoded body itself, and refuses one over
// 8 KiB before the handler sees it.
constexpr const char* kFormType = "text/plain";

// What a request must say in its Host header (and an API request in its Origin): the address
// the server is bound to, so that a page elsewhere cannot reach it through a DNS name that
// resolves here (DNS rebinding).
std::string port_suffix(int port) {
  std::string p = ":";  // appended: GCC 12 warns falsely (-Wrestrict) on ":" + ...
  p += std::to_string(port);
  return p;
}

std::vector<std::string> hosts_for(const std::string& host, int port) {
  const std::string p = port_suffix(port);
  if (host == "127.0.0.1" || host == "localhost" || host == "::1")
    return {"127.0.0.1" + p, "localhost" + p, "[::1]" + p};
  if (host.find(':') != std::string::npos) return {"[" + host + "]" + p};
  return {host + p};
}

// Bound to every address, the server is reached by this machine's addresses: IP literals.
bool is_ip_literal_with_port(const std::string& value, int port) {
  const std::string p = port_suffix(port);
  if (value.size() <= p.size() || value.compare(value.size() - p.size(), p.size(), p) != 0)
    return false;
  const std::string name = value.substr(0, value.size() - p.size());
  if (name == "localhost") return true;
  if (name.size() > 2 && name.front() == '[' && name.back() == ']')
    return name.find_first_not_of("0123456789abcdefABCDEF:.", 1) == name.size() - 1;
  return !name.empty() && name.find_first_not_of("0123456789.") == std::string::npos;
}

// Whether a query's keys and values are all text: UTF-8 with no control characters.
bool query_is_text(const Params& params) {
  for (const auto& [key, value] : params)
    if (!valid_utf8(key) || !valid_utf8(value) || has_control_characters(key) ||
        has_control_characters(value))
      return false;
  return true;
}

// Whether a header's comma-separated list holds `token`, in any case ("keep-alive, Upgrade").
bool header_has_token(const std::string& value, const std::string& token) {
  size_t start = 0;
  while (start <= value.size()) {
    size_t end = value.find(',', start);
    if (end == std::string::npos) end = value.size();
    std::string item = value.substr(start, end - start);
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if (item.size() == token.size() &&
        std::equal(item.begin(), item.end(), token.begin(), [](unsigned char a, unsigned char b) {
          return std::tolower(a) == std::tolower(b);
        }))
      return true;
    start = end + 1;
  }
  return false;
}

ConnectionLimits connection_limits(const ServerConfig& c) {
  ConnectionLimits limits;
  limits.arrival = std::chrono::milliseconds(static_cast<int64_t>(c.arrival_seconds * 1000));
  limits.max_connections = c.max_connections;
  return limits;
}

// A heavy request stops when it runs past its budget, when its client has gone (nobody would
// read the answer) or when the server stops.
class RequestStop : public app::StopRule {
 public:
  RequestStop(double seconds, const std::atomic<bool>& stopping)
      : seconds_(seconds),
        end_(std::chrono::steady_clock::now() +
             std::chrono::milliseconds(static_cast<int64_t>(seconds * 1000))),
        stopping_(stopping),
        socket_(HttpServer::current_socket()) {}

  std::optional<std::string> stop_reason() override {
    if (stopping_) return "the server is stopping";
    if (std::chrono::steady_clock::now() > end_) {
      char budget[32];
      std::snprintf(budget, sizeof budget, "%g", seconds_);
      return std::string("this request ran past its budget of ") + budget +
             " s and was stopped; ask for a smaller field, layout or range of seeds, or start "
             "the server with a larger --request-seconds";
    }
    if (client_gone(socket_)) return "the client went away";
    return std::nullopt;
  }

 private:
  double seconds_;
  std::chrono::steady_clock::time_point end_;
  const std::atomic<bool>& stopping_;
  int socket_;
};

}  // namespace

struct Server::Impl {
  ServerConfig config;
  HttpServer http;
  std::atomic<bool> stopping{false};
  std::string bound_host;
  int bound_port = 0;
  std::counting_semaphore<64> slots;
  std::counting_semaphore<64> light_slot{1};  // a generate as small as the page's
  std::counting_semaphore<64> field_slot{1};  // the page's canvas (/api/field)
  // Open field sockets, each holding a connection's thread; past them the page fetches.
  std::counting_semaphore<64> field_sockets{8};

  explicit Impl(ServerConfig c)
      : config(std::move(c)),
        http(connection_limits(config)),
        slots(std::clamp(config.workers, 1, 64)) {
    config.api.stopping = &stopping;
  }

  void reply(httplib::Response& res, const ApiResponse& r) {
    res.status = r.status;
    res.set_header("Cache-Control", "no-store");
    if (!r.filename.empty())
      res.set_header("Content-Disposition", "attachment; filename=\"" + r.filename + "\"");
    res.set_content(r.body, r.content_type.c_str());
  }

  // Runs a heavy endpoint when one of `pool`'s slots is free (503 when none frees up within a
  // minute), and stops it at its budget or when its client goes.
  template <class F>
  void heavy(httplib::Response& res, F&& endpoint) {
    run_in(slots, res, std::forward<F>(endpoint));
  }
  // How a request's memory is handled: a deep or large one runs on a thread of its own, whose
  // stack (deep in a drawing) is given back when it ends, and gives its pages back after it; a
  // pool thread that ran it would keep those pages for good, a hundred threads over (380 MB
  // after three exports). The page's field is shallow and at most max_cells (a few MB): both
  // cost it more than they save (over loopback, 3.6 -> 2.0 ms a 1024 x 1024 field and 11.0 ->
  // 6.8 ms at 2048 x 2048 without them: its next allocations faulted the given pages back in).
  enum class Footprint { large, small };
  // A slot of a pool, acquired: released when it goes, and with `trim` the heap's free pages
  // given back after it.
  struct SlotHeld {
    std::counting_semaphore<64>& pool;
    bool trim;
    ~SlotHeld() {
      pool.release();
      if (trim) ::malloc_trim(0);
    }
  };
  template <class F>
  void run_in(std::counting_semaphore<64>& pool, httplib::Response& res, F&& endpoint,
              Footprint footprint = Footprint::large) {
    reply(res, answer_in(pool, std::forward<F>(endpoint), footprint));
  }
  // The answer of `endpoint` run as run_in runs it; what it throws is thrown on.
  template <class F>
  ApiResponse answer_in(std::counting_semaphore<64>& pool, F&& endpoint, Footprint footprint) {
    if (!pool.try_acquire_for(std::chrono::seconds(60)))
      return api_error(503, "the server is busy; try again");
    const SlotHeld held{pool, footprint == Footprint::large};
    RequestStop rule(config.request_seconds, stopping);
    ApiResponse answer;
    std::exception_ptr failure;
    auto run = [&] {
      app::StopScope scope(rule);
      try {
        answer = endpoint();
      } catch (...) {
        failure = std::current_exception();
      }
    };
    if (footprint == Footprint::large)
      std::thread(run).join();
    else
      run();
    if (failure) std::rethrow_exception(failure);
    return answer;
  }

  // GET /api/field-socket: the handshake checked, the connection becomes the page's field
  // channel (field_socket.h) for as long as the page keeps it.
  void field_socket(const httplib::Request& req, httplib::Response& res) {
    const auto accept = websocket_accept(req.get_header_value("Sec-WebSocket-Key"));
    if (req.method != "GET" || !header_has_token(req.get_header_value("Upgrade"), "websocket") ||
        !header_has_token(req.get_header_value("Connection"), "upgrade") ||
        req.get_header_value("Sec-WebSocket-Version") != "13" || !accept) {
      res.set_header("Sec-WebSocket-Version", "13");
      reply(res, api_error(426,
                           "/api/field-socket is a WebSocket (version 13, with a 16-byte "
                           "Sec-WebSocket-Key); fetch /api/field for one field"));
      return;
    }
    // All held: the socket idle longest, if idle long enough, gives its place up.
    if (!field_sockets.try_acquire() &&
        !(ask_idle_socket_to_yield() && field_sockets.try_acquire_for(std::chrono::seconds(2)))) {
      reply(res, api_error(503,
                           "the server has as many field sockets open as it keeps; fetch "
                           "/api/field instead"));
      return;
    }
    const SlotHeld held{field_sockets, false};
    const auto me = std::make_shared<OpenSocket>();
    {
      const std::lock_guard lock(open_sockets_mutex);
      open_sockets.push_back(me);
    }
    const struct Forget {
      Impl& impl;
      std::shared_ptr<OpenSocket> me;
      ~Forget() {
        const std::lock_guard lock(impl.open_sockets_mutex);
        impl.open_sockets.remove(me);
      }
    } forget{*this, me};
    const HttpServer::TakenConnection taken = HttpServer::take_connection();
    serve_field_socket(
        taken.socket, taken.early_bytes, *accept, config.field_socket,
        [this, me](const std::string& query) {
          me->last_message = std::chrono::steady_clock::now();
          return field_over_socket(query);
        },
        [this] { return stopping.load(); }, [me] { return me->yield.load(); });
  }

  // An open field socket: when it was last asked something, and whether it must give way.
  struct OpenSocket {
    std::atomic<std::chrono::steady_clock::time_point> last_message{
        std::chrono::steady_clock::now()};
    std::atomic<bool> yield{false};
  };
  std::mutex open_sockets_mutex;
  std::list<std::shared_ptr<OpenSocket>> open_sockets;

  // Asks the socket idle longest, if idle for yield_after, to close; false when none is.
  bool ask_idle_socket_to_yield() {
    const std::lock_guard lock(open_sockets_mutex);
    std::shared_ptr<OpenSocket> idlest;
    for (const auto& s : open_sockets)
      if (!s->yield && (!idlest || s->last_message.load() < idlest->last_message.load()))
        idlest = s;
    if (!idlest || std::chrono::steady_clock::now() - idlest->last_message.load() <
                       config.field_socket.yield_after)
      return false;
    idlest->yield = true;
    return true;
  }

  // A POST's body is read after the screen, which checked the address's query: its text
  // is checked here. False: answered 400.
  bool query_text(const httplib::Request& req, httplib::Response& res) {
    if (req.method != "POST" || query_is_text(params_of(req))) return true;
    reply(res, api_error(400, "the query holds bytes that are not UTF-8 text"));
    return false;
  }

  ApiResponse field_over_socket(const std::string& query) {
    const Params params = query_params("?" + query);
    if (!query_is_text(params))
      return api_error(400, "the query holds bytes that are not UTF-8 text");
    try {
      return answer_in(
          field_slot, [&] { return api_field(config.api, params); }, Footprint::small);
    } catch (...) {
      return api_error(500, "internal error");
    }
  }

  bool host_allowed(const std::string& value) const {
    if (bound_host == "0.0.0.0" || bound_host == "::")
      return is_ip_literal_with_port(value, bound_port);
    const auto hosts = hosts_for(bound_host, bound_port);
    return std::find(hosts.begin(), hosts.end(), value) != hosts.end();
  }

  // Every request is checked before it is routed: its method, its Host, and for the API its
  // origin and the text of its query.
  httplib::Server::HandlerResponse screen(const httplib::Request& req, httplib::Response& res) {
    // Nothing is compressed, whatever the browser accepts: httplib brotli-compresses any text
    // at its highest quality (2 s for three.js's 1.5 MB, 1.8 s for a 740 KB schedule.csv, even
    // to answer a HEAD), and the page and its server share one machine. The request is httplib's
    // own, made mutable and handed to its handlers as const.
    const_cast<httplib::Request&>(req).headers.erase("Accept-Encoding");
    const bool api = req.path.rfind("/api/", 0) == 0;
    auto refuse = [&](int status, const std::string& message) {
      HttpServer::close_after_this_request();  // its body, if any, is never read
      if (status == 405)
        res.set_header("Allow", req.path == kUpload || req.path == kSiteUpload ? "POST"
                                : takes_query_by_post(req.path)                ? "GET, HEAD, POST"
                                                                               : "GET, HEAD");
      if (api)
        reply(res, api_error(status, message));
      else {
        res.status = status;
        res.set_content(message + "\n", "text/plain");
      }
      return httplib::Server::HandlerResponse::Handled;
    };
    const bool upload = req.path == kUpload || req.path == kSiteUpload;
    const bool form = !upload && req.method == "POST" && takes_query_by_post(req.path);
    if (form && req.get_header_value("Content-Type").rfind(kFormType, 0) != 0)
      return refuse(415, "a query sent by POST is its text as the body (Content-Type " +
                             std::string(kFormType) + "), not '" +
                             req.get_header_value("Content-Type").substr(0, 100) + "'");
    if (upload ? req.method != "POST" : req.method != "GET" && req.method != "HEAD" && !form)
      return refuse(
          405, upload ? "a picture to measure or a site drawing is sent by POST, not " + req.method
                      : "the server takes GET requests (their query also by POST as the "
                        "body), and POST to " +
                            std::string(kUpload) + " and " + kSiteUpload + "; not " + req.method);
    // A body is read only after this: its length is checked first, from the header.
    const bool chunked = req.has_header("Transfer-Encoding");
    const uint64_t limit = upload ? config.api.limits.max_upload_bytes
                           : form ? config.max_query_bytes
                                  : config.max_body_bytes;
    if (chunked) return refuse(411, "send the body with a Content-Length, not in chunks");
    const std::string length = req.get_header_value("Content-Length");
    uint64_t bytes = 0;
    if (!length.empty()) {
      auto [end, ec] = std::from_chars(length.data(), length.data() + length.size(), bytes);
      if (ec != std::errc() || end != length.data() + length.size())
        return refuse(400, "Content-Length '" + length + "' is not a whole number");
    }
    // httplib reads no body for a GET: left in the connection, it would be read as a request.
    if (!upload && !form && bytes > 0)
      return refuse(400,
                    "a " + req.method + " request carries no body (Content-Length " + length + ")");
    if (bytes > limit)
      return refuse(413,
                    std::string(upload ? (req.path == kSiteUpload ? "the drawing" : "the picture")
                                : form ? "the query"
                                       : "the request's body") +
                        " is larger than " + std::to_string(limit >> 10) + " KiB");
    // Two Host headers: which one the request is for is not said, whatever the first says.
    if (req.get_header_value_count("Host") > 1)
      return refuse(400, "the request has " + std::to_string(req.get_header_value_count("Host")) +
                             " Host headers; a request names one host");
    if (!host_allowed(req.get_header_value("Host")))
      return refuse(403, "this server answers requests addressed to " +
                             hosts_for(bound_host, bound_port).front() + " only");
    if (api) {
      const std::string origin = req.get_header_value("Origin");
      if (!origin.empty() && !(origin.rfind("http://", 0) == 0 && host_allowed(origin.substr(7))))
        return refuse(403, "requests from other sites are refused (Origin " + origin + ")");
      const std::string site = req.get_header_value("Sec-Fetch-Site");
      if (!site.empty() && site != "same-origin" && site != "none")
        return refuse(403, "requests from other sites are refused (Sec-Fetch-Site " + site + ")");
      if (!query_is_text(query_params(req.target)))
        return refuse(400, "the query holds bytes that are not UTF-8 text");
    }
    return httplib::Server::HandlerResponse::Unhandled;
  }

  void routes() {
    // The page runs its own scripts only (the import map's by its hash: tests/js/page.mjs fails
    // on any report of the policy), and no other site may frame it.
    http.set_default_headers({{"Content-Security-Policy", kContentSecurityPolicy},
                              {"X-Frame-Options", "DENY"},
                              {"X-Content-Type-Options", "nosniff"},
                              {"Referrer-Policy", "no-referrer"}});
    http.set_payload_max_length(
        std::max(config.max_body_bytes, config.api.limits.max_upload_bytes));
    // Slow clients are dealt with by the connections (http_connection.h); the pool has a thread
    // for every connection allowed and a few over, to turn the next ones away.
    const size_t threads = static_cast<size_t>(config.max_connections) + 8;
    http.new_task_queue = [threads] { return new httplib::ThreadPool(threads); };
    http.set_pre_routing_handler(
        [this](const httplib::Request& req, httplib::Response& res) { return screen(req, res); });
    // SO_REUSEADDR only: httplib's default SO_REUSEPORT would let a second server take the
    // same port silently, each answering half the requests.
    // TCP_NODELAY (inherited by each connection): httplib sends the headers and the body
    // apart, and with Nagle's algorithm the body waited for the browser's delayed ACK, 40 ms
    // on every answer.
    http.set_socket_options([](socket_t sock) {
      int yes = 1;
      setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
      setsockopt(sock, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
    });
    http.set_tcp_nodelay(true);
    // The recipe reads its pictures and drawings: in the light slot, so that a hundred page
    // loads decode them one at a time, never all at once.
    http.Get("/api/recipe", [this](const httplib::Request&, httplib::Response& res) {
      run_in(light_slot, res, [&] { return api_recipe(config.api); });
    });
    // Each takes its query from the address, or by POST as the body (request_params).
    const auto colours = [this](const httplib::Request& req, httplib::Response& res) {
      if (!query_text(req, res)) return;
      reply(res, api_colours(params_of(req)));
    };
    const auto generate = [this](const httplib::Request& req, httplib::Response& res) {
      if (!query_text(req, res)) return;
      const Params params = params_of(req);
      run_in(api_generate_is_light(config.api, params) ? light_slot : slots, res,
             [&] { return api_generate(config.api, params); });
    };
    // The page's canvas has a slot of its own, so that a download or the 3-D view's model
    // being made never holds up a redraw (a field is at most max_cells: tens of ms).
    const auto field = [this](const httplib::Request& req, httplib::Response& res) {
      if (!query_text(req, res)) return;
      run_in(
          field_slot, res, [&] { return api_field(config.api, params_of(req)); }, Footprint::small);
    };
    const auto export_file = [this](const httplib::Request& req, httplib::Response& res) {
      if (!query_text(req, res)) return;
      heavy(res, [&] { return api_export(config.api, params_of(req)); });
    };
    const auto search = [this](const httplib::Request& req, httplib::Response& res) {
      if (!query_text(req, res)) return;
      heavy(res, [&] { return api_search(config.api, params_of(req)); });
    };
    for (const auto& [path, handler] :
         std::initializer_list<std::pair<const char*, httplib::Server::Handler>>{
             {"/api/colours", colours},
             {"/api/generate", generate},
             {"/api/field", field},
             {"/api/export", export_file},
             {"/api/search", search}}) {
      http.Get(path, handler);
      http.Post(path, handler);
    }
    // The same fields over one open socket, without a fetch's cost on each change.
    http.Get("/api/field-socket", [this](const httplib::Request& req, httplib::Response& res) {
      field_socket(req, res);
    });
    http.Post(kUpload, [this](const httplib::Request& req, httplib::Response& res) {
      heavy(res, [&] { return api_measure(config.api, query_params(req.target), req.body); });
    });
    http.Post(kSiteUpload, [this](const httplib::Request& req, httplib::Response& res) {
      heavy(res, [&] { return api_site(config.api, query_params(req.target), req.body); });
    });
    // Anything else under /api/ is a JSON 404 (or 405 for another method), never a page.
    auto not_found = [this](const httplib::Request& req, httplib::Response& res) {
      const bool get = req.method == "GET";
      reply(
          res,
          api_error(get ? 404 : 405,
                    get ? "no such endpoint " + req.path +
                              "; the API has /api/recipe, /api/colours, /api/generate, /api/field, "
                              "/api/export, "
                              "/api/search, /api/measure and /api/site"
                        : "the API takes GET requests (their query also by POST as the body), and "
                          "POST to " +
                              std::string(kUpload) + " and " + kSiteUpload));
    };
    http.Get(R"(/api/.*)", not_found);
    http.set_mount_point("/", config.web_root.string());
    http.set_exception_handler(
        [this](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
          reply(res, api_error(500, "internal error"));
        });
    http.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
      // Errors httplib raises itself (413 too large, 414 URI too long, 404 file): JSON for the
      // API, plain text for files.
      if (!res.body.empty()) return;
      // httplib could not frame the request: what follows on the connection is not a request.
      if (res.status == 400 || res.status == 413 || res.status == 414 || res.status == 431)
        HttpServer::close_after_this_request();
      const std::string message = res.status == 413   ? "the request is too large"
                                  : res.status == 400 ? "the request is malformed"
                                  : res.status == 414 ? "the request's address is too long"
                                  : res.status == 404 ? "not found: " + req.path
                                                      : "request failed";
      if (req.path.rfind("/api/", 0) == 0)
        res.set_content(api_error(res.status, message).body, kJsonType);
      else
        res.set_content(message + "\n", "text/plain");
    });
  }
};

Server::Server(ServerConfig config) : impl_(std::make_unique<Impl>(std::move(config))) {
  // A hundred connection threads would each get a heap arena of their own (up to 16 on two
  // cores), whose freed pages malloc_trim cannot all give back: under 16 clients for 15 s the
  // heap stayed at 98 MB after the load, against 8 MB with two arenas.
  ::mallopt(M_ARENA_MAX, 2);
  // Blocks up to 64 MB come from the heap and stay there until a heavy request's malloc_trim,
  // instead of each being mapped afresh and faulted in page by page: the page's 2048 x 2048
  // field over loopback 9.0 -> 4.1 ms. Resident memory after 15 s of 16 clients' exports is
  // the same (54 MB; tests/benchmarks/server_load.py).
  ::mallopt(M_MMAP_THRESHOLD, 64 << 20);
  ::mallopt(M_TRIM_THRESHOLD, 128 << 20);
  if (!std::filesystem::is_regular_file(impl_->config.web_root / "index.html"))
    throw InputError("the page's files are not in " + impl_->config.web_root.string() +
                     " (index.html missing); give --web-root");
  impl_->routes();
}

Server::~Server() { stop(); }

int Server::bind(const std::string& host, int port) {
  const int bound = port == 0 ? impl_->http.bind_to_any_port(host)
                              : (impl_->http.bind_to_port(host, port) ? port : -1);
  if (bound <= 0)
    throw InputError(parameter("port"),
                     "cannot listen on " + host + ":" + std::to_string(port) +
                         " (in use, or not an address of this machine); choose another port, "
                         "or 0 for any free port");
  impl_->bound_host = host;
  impl_->bound_port = bound;
  return bound;
}

bool Server::listen() { return impl_->http.listen_after_bind(); }

void Server::stop() {
  impl_->stopping = true;
  impl_->http.stop();
}

std::filesystem::path find_web_root(const std::filesystem::path& executable) {
  const auto dir = executable.parent_path();
  for (const auto& candidate : {dir / "share/curdle/web", dir / "../share/curdle/web"})
    if (std::filesystem::is_regular_file(candidate / "index.html"))
      return std::filesystem::weakly_canonical(candidate);
  return dir / "share/curdle/web";
}

}  // namespace curdle::server
