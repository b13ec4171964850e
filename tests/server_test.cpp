// The page's JSON API over HTTP, against a server on a free loopback port: answers, downloads
// equal to the CLI's files, every kind of bad request as a 4xx JSON error, concurrent requests,
// and a clean stop.
#include "server/server.h"

#include <gtest/gtest.h>
#include <httplib.h>
#include <poll.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "app/fit_run.h"
#include "app/outputs.h"
#include "app/reproduce.h"
#include "app/run.h"
#include "curdle/curdling.h"
#include "curdle/error.h"
#include "curdle/overlay.h"
#include "curdle/search.h"
#include "io/image.h"
#include "server_support.h"
#include "socket_support.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace curdle::server {
namespace {

const std::string kRecipe =
    std::string(CURDLE_SOURCE_DIR) + "/patterns/paper/fig8-segment-of-large-curd.toml";

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<uint8_t> unbase64(const std::string& text) {
  std::vector<uint8_t> out;
  uint32_t buffer = 0;
  int bits = 0;
  for (char c : text) {
    int v = c >= 'A' && c <= 'Z'   ? c - 'A'
            : c >= 'a' && c <= 'z' ? c - 'a' + 26
            : c >= '0' && c <= '9' ? c - '0' + 52
            : c == '+'             ? 62
            : c == '/'             ? 63
                                   : -1;
    if (v < 0) continue;
    buffer = buffer << 6 | static_cast<uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<uint8_t>(buffer >> bits));
    }
  }
  return out;
}

class ServerTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    ServerConfig config = test::server_config(kRecipe);
    config.api.limits.max_cells = 1 << 20;
    serving_ = new test::ServerOnLoopback(config);
    port_ = serving_->port();
  }
  static void TearDownTestSuite() { delete serving_; }

  httplib::Result get(const std::string& path) {
    httplib::Client client("127.0.0.1", port_);
    client.set_read_timeout(120, 0);
    return client.Get(path.c_str());
  }
  json get_json(const std::string& path, int status) {
    auto r = get(path);
    EXPECT_TRUE(r) << path;
    if (!r) return {};
    EXPECT_EQ(r->status, status) << path << ": " << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), kJsonType) << path;
    return json::parse(r->body);
  }
  // The CLI's file for the same recipe, seed, overrides and window.
  static app::Run open_run(const std::string& path, const std::string& seed = "",
                           const std::string& window = "",
                           const std::vector<std::string>& sets = {}) {
    app::RunRequest request;
    request.recipe_path = path;
    request.recipe_text = app::read_recipe_file(path);
    request.seed = seed;
    request.window = window;
    request.overrides = sets;
    return app::resolve_run(request);
  }
  // The file the command line writes (through a staging directory) for the same run.
  static std::string written_file(const app::Run& run, const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("curdle-server-test-" + name);
    fs::remove_all(dir);
    {
      app::StagingDirectory sink(dir);
      app::write_outputs(run, app::select_outputs(run, {name}, nullptr), sink, 0, nullptr);
      sink.commit();
    }
    std::string bytes = slurp(dir / name);
    fs::remove_all(dir);
    return bytes;
  }
  std::string cli_file(const std::string& name, const std::string& seed, const std::string& window,
                       const std::vector<std::string>& sets = {}) {
    return written_file(open_run(kRecipe, seed, window, sets), name);
  }

  // What the server answers to `request` sent as is on a socket of its own (a client library
  // would send a body first).
  std::string raw_request(const std::string& request) {
    const int fd = test::connect_loopback(port_);
    std::string answer;
    if (fd >= 0 &&
        ::send(fd, request.data(), request.size(), 0) == static_cast<ssize_t>(request.size())) {
      timeval wait{10, 0};
      ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &wait, sizeof wait);
      char buffer[4096];
      for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;)
        answer.append(buffer, static_cast<size_t>(n));
    }
    ::close(fd);
    return answer;
  }

  static test::ServerOnLoopback* serving_;
  static int port_;
};
test::ServerOnLoopback* ServerTest::serving_ = nullptr;
int ServerTest::port_ = 0;

TEST_F(ServerTest, RecipeDescribesTheDesignAndTheFloor) {
  const json j = get_json("/api/recipe", 200);
  EXPECT_EQ(j["name"], "fig8-segment-of-large-curd");
  EXPECT_EQ(j["field"], json({256, 256}));
  EXPECT_EQ(j["layout"]["segment_cells"], json({67, 67}));
  EXPECT_EQ(j["default_window"], json({0, 0, 67, 67}));
  EXPECT_EQ(j["curds"][0]["probabilities"], json({"2/3", "1/2", "1/3"}));
  EXPECT_EQ(j["legend"].size(), 2u);
  // The downloads come from the registry of outputs: every single file, and the recipe.
  EXPECT_EQ(j["downloads"],
            json({"report.json", "cells.csv", "preview.png", "layout.svg", "layout.png",
                  "layout.pdf", "layout.glb", "layout.ifc", "schedule.csv", "layout.dxf",
                  "layout.gpkg", "quantities.csv", "lots.csv", "install.svg", "recipe.toml"}));
  // Each with what it is for, as the links say on hover.
  EXPECT_NE(j["download_descriptions"]["layout.gpkg"].get<std::string>().find("QGIS"),
            std::string::npos);
  EXPECT_EQ(j["seed"], "8");  // the recipe's, as a string
}

// New values take the library's blend, which truncates: (255 + 0) / 2 = 127, not 128.
TEST_F(ServerTest, ColoursAreTheLibrarysBlends) {
  const json j = get_json("/api/colours?colour=%23ff0000&colour=%230000ff", 200);
  EXPECT_EQ(j["values"], json({"#ece8de", "#ff0000", "#0000ff", "#7f007f"}));
}

TEST_F(ServerTest, GenerateGivesTheEnginesCellsAndReport) {
  const json j = get_json(
      "/api/generate?seed=42&curds.0.probabilities=%5B%223%2F4%22,%221%2F2%22,%221%2F3%22%5D", 200);
  EXPECT_EQ(j["seed"], "42");  // a string: JavaScript numbers lose seeds above 2^53
  EXPECT_EQ(j["report"]["cells"], 65536);
  const auto bytes = unbase64(j["values"]);
  ASSERT_EQ(bytes.size(), 65536u);
  const app::Run s =
      open_run(kRecipe, "42", "", {"curds.0.probabilities=[\"3/4\",\"1/2\",\"1/3\"]"});
  const auto& d = s.recipe.design;
  const auto values = values_in(curdle::curdle(d, 42, d.field), d.field);
  EXPECT_TRUE(std::equal(values.begin(), values.end(), bytes.begin()));
  EXPECT_EQ(j["command"], "curdle generate " + kRecipe +
                              " --set 'curds.0.probabilities=[\"3/4\",\"1/2\",\"1/3\"]' --seed 42");
  // A window: that segment's report, no cells when cells=0.
  const json w = get_json("/api/generate?seed=42&window=10,20,67,67&cells=0", 200);
  EXPECT_EQ(w["report"]["cells"], 4489);
  EXPECT_FALSE(w.contains("values"));
  EXPECT_EQ(w["command"], "curdle generate " + kRecipe + " --seed 42 --window 10,20,67,67");
}

// Resident memory of this process (the server runs in it), kB.
long resident_kb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

// Heavy requests give their memory back: three exports of a 600 x 600-cell layout.png kept
// about 500 MB resident for good before the server trimmed its heap after each.
TEST_F(ServerTest, HeavyRequestsGiveTheirMemoryBack) {
  const long before = resident_kb();
  for (int i = 0; i < 3; ++i) {
    auto r = get("/api/export?seed=" + std::to_string(i + 1) +
                 "&layout.floor=%5B180000,180000%5D&field.cells=%5B600,600%5D&file=layout.png");
    ASSERT_TRUE(r) << httplib::to_string(r.error());
    ASSERT_EQ(r->status, 200) << r->body;
  }
  const long after = resident_kb();
  ASSERT_GT(before, 0);
  EXPECT_LT(after - before, 150 * 1024) << before << " kB before, " << after << " kB after";
}

// Forty clients that send their headers a byte at a time held all 32 threads of the server
// that was: the page got no answer. Now they hold a connection each and the page is served.
TEST_F(ServerTest, FortySlowClientsDoNotHoldUpThePage) {
  std::vector<int> slow;
  const std::string start =
      "GET /api/recipe HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port_) + "\r\nX-Pad: ";
  for (int i = 0; i < 40; ++i) {
    slow.push_back(test::connect_loopback(port_));
    ASSERT_GE(slow.back(), 0);
    ::send(slow.back(), start.data(), start.size(), MSG_NOSIGNAL);
  }
  for (int round = 0; round < 3; ++round) {
    for (int fd : slow) ::send(fd, "a", 1, MSG_NOSIGNAL);
    httplib::Client client("127.0.0.1", port_);
    client.set_read_timeout(5, 0);
    auto r = client.Get("/api/recipe");
    ASSERT_TRUE(r) << "no answer within 5 s in round " << round;
    EXPECT_EQ(r->status, 200);
  }
  for (int fd : slow) ::close(fd);
}

TEST_F(ServerTest, DownloadsAreTheFilesTheCommandLineWrites) {
  for (const std::string name : {"layout.svg", "layout.glb", "schedule.csv", "quantities.csv",
                                 "report.json", "install.svg", "layout.png", "cells.csv"}) {
    auto r = get("/api/export?seed=5&window=100,30,67,67&lattice.mode=quota&file=" + name);
    ASSERT_TRUE(r) << httplib::to_string(r.error());
    ASSERT_EQ(r->status, 200) << name << ": " << r->body;
    EXPECT_EQ(r->get_header_value("Content-Disposition"), "attachment; filename=\"" + name + "\"");
    EXPECT_EQ(r->body, cli_file(name, "5", "100,30,67,67", {"lattice.mode=quota"})) << name;
  }
  // recipe.toml carries every change, the seed and the window: it needs no options.
  auto r = get("/api/export?seed=5&window=100,30,67,67&lattice.mode=quota&file=recipe.toml");
  ASSERT_TRUE(r) << httplib::to_string(r.error());
  const fs::path saved = fs::temp_directory_path() / "curdle-server-test-recipe.toml";
  std::ofstream(saved, std::ios::binary) << r->body;
  const app::Run s = open_run(saved.string());
  EXPECT_EQ(s.seed, 5u);
  EXPECT_EQ(s.view.origin[0], 100);
  EXPECT_EQ(s.recipe.design.lattice.mode, Mode::quota);
  EXPECT_EQ(written_file(s, "schedule.csv"),
            cli_file("schedule.csv", "5", "100,30,67,67", {"lattice.mode=quota"}));
  fs::remove(saved);
}

TEST_F(ServerTest, BadRequestsAreJsonErrorsThatSayWhatIsAllowed) {
  struct Case {
    std::string path;
    int status;
    std::string says;
  };
  const std::vector<Case> cases = {
      {"/api/generate?seed=abc", 400, "is not a seed"},
      {"/api/generate?seed=-1", 400, "is not a seed"},
      {"/api/generate?colour=red", 400, "unknown parameter"},
      {"/api/generate?lattice.base=1", 400, "from 2 to 64"},
      {"/api/generate?curds.0.probabilities=%5B%221.5%22,%221%22,%221%22%5D", 400,
       "curds.0.probabilities"},
      {"/api/generate?window=250,250,67,67", 400, "inside the field"},
      // The API names a parameter by its key, never by a command-line option.
      {"/api/generate?window=1,2,3", 400, "window=: a 2-D lattice takes a window X,Y,W,H"},
      {"/api/colours?colour=red", 400, "is not a colour written #rrggbb"},
      {"/api/colours?shade=%23ffffff", 400, "unknown parameter"},
      {"/api/generate?cells=2", 400, "must be 0 or 1"},
      {"/api/generate?set=lattice.base", 400, "KEY=VALUE"},
      {"/api/generate?field.cells=%5B2048,2048%5D", 413, "the server allows 1048576"},
      {"/api/export?file=secrets.txt", 400, "is not a download; allowed: report.json, cells.csv"},
      {"/api/export?file=layout.svg&window=1,1,20,20", 400, "takes exactly 67 x 67 cells"},
      {"/api/search?seeds=5..1", 400, "not a range of seeds"},
      {"/api/search?seeds=1..100000000", 413, "above the budget of 1073741824"},
      {"/api/search?seeds=0..18446744073709551615", 413, "at most 2^40 seeds"},
      {"/api/search?target=size:dark=3", 400, "unknown measure"},
      {"/api/search?seeds=1..3&target=ratio:dark=2", 400, "a ratio is from 0 to 1"},
      {"/api/search?segment=300,300", 400, "must fit in the view"},
      {"/api/search?window=1,1,67,67", 400, "segment=W,H"},
      {"/api/nothing", 404, "no such endpoint"},
  };
  for (const Case& c : cases) {
    const json j = get_json(c.path, c.status);
    ASSERT_TRUE(j.contains("error")) << c.path;
    EXPECT_NE(j["error"].get<std::string>().find(c.says), std::string::npos)
        << c.path << ": " << j["error"];
  }
  httplib::Client client("127.0.0.1", port_);
  // A query too long for an address comes by POST as the body's text; nothing else is posted.
  auto post = client.Post("/api/generate", "{}", "application/json");
  ASSERT_TRUE(post);
  EXPECT_EQ(post->status, 415);
  EXPECT_NE(post->body.find("its text as the body (Content-Type text/plain)"), std::string::npos);
  auto by_post = client.Post("/api/generate", "seed=3&cells=0", "text/plain;charset=UTF-8");
  ASSERT_TRUE(by_post);
  EXPECT_EQ(by_post->status, 200) << by_post->body;
  json posted = json::parse(by_post->body),
       got = json::parse(get("/api/generate?seed=3&cells=0")->body);
  posted.erase("server_ms"), got.erase("server_ms");
  EXPECT_EQ(posted, got);
  auto recipe_post = client.Post("/api/recipe", "seed=3", "text/plain");
  ASSERT_TRUE(recipe_post);
  EXPECT_EQ(recipe_post->status, 405);
  // An address longer than the server reads.
  auto longer = get("/api/generate?seed=1&lattice.description=" + std::string(9000, 'a'));
  ASSERT_TRUE(longer);
  EXPECT_EQ(longer->status, 414);
  // A large body is refused with its method, before anything reads it.
  const std::string big = raw_request(
      "POST /api/generate HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port_) +
      "\r\nContent-Type: text/plain\r\nContent-Length: 4194305\r\nConnection: close\r\n\r\n");
  EXPECT_NE(big.find("413"), std::string::npos) << big;
  EXPECT_NE(big.find("the query is larger than 4096 KiB"), std::string::npos) << big;
  // Every method but GET and HEAD is refused, on the API and on the page's files alike.
  for (const char* method : {"PATCH", "OPTIONS", "PUT", "DELETE"}) {
    httplib::Request r;
    r.method = method;
    r.path = "/index.html";
    auto answer = client.send(r);
    ASSERT_TRUE(answer) << method;
    EXPECT_EQ(answer->status, 405) << method;
    EXPECT_EQ(answer->get_header_value("Allow"), "GET, HEAD") << method;
  }
}

// DNS rebinding and cross-site requests: a page elsewhere may make the browser send requests
// here (an <img>, a fetch), but with its own Host or Origin.
TEST_F(ServerTest, RequestsFromOtherSitesAndNamesAreRefused) {
  httplib::Client client("127.0.0.1", port_);
  auto with = [&](const httplib::Headers& headers, const std::string& path = "/api/recipe") {
    auto r = client.Get(path, headers);
    return r ? r->status : -1;
  };
  EXPECT_EQ(with({}), 200);
  EXPECT_EQ(with({{"Host", "localhost:" + std::to_string(port_)}}), 200);
  EXPECT_EQ(with({{"Host", "evil.example:" + std::to_string(port_)}}), 403);
  EXPECT_EQ(with({{"Host", "evil.example:" + std::to_string(port_)}}, "/index.html"), 403);
  EXPECT_EQ(with({{"Host", "127.0.0.1:1"}}), 403);
  // Two Host headers, the first this server's: refused, not judged by the first.
  const std::string two =
      raw_request("GET /api/recipe HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port_) +
                  "\r\nHost: evil.example\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(two.rfind("HTTP/1.1 400", 0), 0u) << two;
  EXPECT_NE(two.find("2 Host headers"), std::string::npos) << two;
  EXPECT_EQ(with({{"Origin", "http://evil.example"}}), 403);
  EXPECT_EQ(with({{"Origin", "http://127.0.0.1:" + std::to_string(port_)}}), 200);
  EXPECT_EQ(with({{"Sec-Fetch-Site", "cross-site"}}), 403);
  EXPECT_EQ(with({{"Sec-Fetch-Site", "same-origin"}}), 200);
  // A query that is not UTF-8 text is a 400, not a 500.
  auto bad = client.Get("/api/generate?name=%FF%FE");
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->status, 400);
  EXPECT_NE(bad->body.find("not UTF-8"), std::string::npos);
  // And the server still answers.
  EXPECT_EQ(with({}), 200);
}

TEST_F(ServerTest, ConcurrentRequestsGiveEachTheirOwnAnswer) {
  std::vector<std::thread> clients;
  std::vector<std::string> reports(12);
  for (int i = 0; i < 12; ++i)
    clients.emplace_back([&, i] {
      httplib::Client client("127.0.0.1", port_);
      client.set_read_timeout(120, 0);
      auto r = client.Get(("/api/generate?seed=" + std::to_string(100 + i % 3)).c_str());
      if (r && r->status == 200) {
        json j = json::parse(r->body);
        reports[i] = j["report"].dump() + j["values"].get<std::string>();
      }
    });
  for (auto& t : clients) t.join();
  for (int i = 0; i < 12; ++i) {
    ASSERT_FALSE(reports[i].empty()) << i;
    EXPECT_EQ(reports[i], reports[i % 3]) << i;
  }
  EXPECT_NE(reports[0], reports[1]);
}

TEST_F(ServerTest, SearchRanksAsTheLibraryDoes) {
  const json j = get_json(
      "/api/"
      "search?seeds=1..40&segment=67,67&stride=16&top=4&target=ratio:dark%3D0.111&target=cluster:"
      "dark%3C%3D8",
      200);
  ASSERT_EQ(j["hits"].size(), 4u);
  const app::Run s = open_run(kRecipe);
  const Design& d = s.recipe.design;
  SearchSpec spec;
  spec.targets = {parse_target("ratio:dark=0.111", d), parse_target("cluster:dark<=8", d)};
  spec.window = std::array<int64_t, 2>{67, 67};
  spec.stride = 16;
  spec.top = 4;
  const auto hits = search_seeds(d, d.field, spec, 1, 40);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(j["hits"][i]["seed"], std::to_string(hits[i].seed));
    EXPECT_EQ(j["hits"][i]["window"], app::window_text(hits[i].segment, 2));
    EXPECT_DOUBLE_EQ(j["hits"][i]["score"].get<double>(), hits[i].score);
  }
}

// A picture sent by the page: measured with the lattice asked for, and fitted to the recipe
// `curdle fit` writes for the same file; every bad picture or option is a 4xx that says why.
TEST_F(ServerTest, MeasureTakesAPictureAndFitsTheRecipeTheCommandLineFits) {
  const fs::path mask = fs::path(CURDLE_SOURCE_DIR) / "patterns/gallery-facade-mask.png";
  const std::string bytes = slurp(mask);
  httplib::Client client("127.0.0.1", port_);
  client.set_read_timeout(120, 0);
  auto r =
      client.Post("/api/measure?name=gallery-facade-mask.png&base=2&stages=5", bytes, "image/png");
  ASSERT_TRUE(r) << httplib::to_string(r.error());
  ASSERT_EQ(r->status, 200) << r->body;
  const json j = json::parse(r->body);
  EXPECT_EQ(j["measure"]["size"], json::array({240, 120}));
  EXPECT_EQ(j["measure"]["base"], 2);
  EXPECT_EQ(j["measure"]["values"].size(), 2u);
  app::FitRequest fit;
  fit.source = mask.string();
  fit.base = 2;
  fit.stages = 5;
  EXPECT_EQ(j["fit"]["recipe_toml"], app::run_fit(fit).toml);
  ASSERT_EQ(j["fit"]["curds"].size(), 1u);
  EXPECT_EQ(j["fit"]["curds"][0]["probabilities"].size(), 5u);
  // The mask is drawn in cells of 2 x 2 pixels: fitted in cells, as `curdle fit` fits it.
  EXPECT_EQ(j["fit"]["field"], json::array({120, 60}));

  // Without options, the served recipe's base and stages (fig. 8: base 4, 3 stages).
  auto plain = client.Post("/api/measure", bytes, "image/png");
  ASSERT_TRUE(plain);
  ASSERT_EQ(plain->status, 200) << plain->body;
  EXPECT_EQ(json::parse(plain->body)["fit"]["lattice"]["base"], 4);

  // A picture with more pixels than the server generates cells (2^20 here).
  PreviewImage wide;
  wide.width = 1100;
  wide.height = 1000;
  wide.rgb.assign(size_t{3} * 1100 * 1000, 255);
  const std::string wide_png = encode_png(wide);
  struct Case {
    std::string path, body;
    int status;
    std::string says;
  };
  const std::vector<Case> cases = {
      {"/api/measure?name=notes.png", "plain text", 400, "cannot read the picture notes.png"},
      {"/api/measure?name=..%2F..%2Fetc%2Fpasswd", "plain text", 400,
       "cannot read the picture passwd"},
      {"/api/measure", "", 400, "is empty"},
      {"/api/measure?name=wide.png", wide_png, 413, "at most 1048576 pixels"},
      {"/api/measure?stages=0", bytes, 400, "stages=: must be from 1 to 30"},
      {"/api/measure?curds=9", bytes, 400, "curds=: must be from 1 to 4"},
      {"/api/measure?base=x", bytes, 400, "base=: 'x' is not a whole number"},
      {"/api/measure?seed=3", bytes, 400, "takes name, base, stages and curds only"},
      {"/api/measure?colour=red", bytes, 400, "unknown parameter"},
  };
  for (const Case& c : cases) {
    auto answer = client.Post(c.path, c.body, "image/png");
    ASSERT_TRUE(answer) << c.path;
    EXPECT_EQ(answer->status, c.status) << c.path << ": " << answer->body;
    EXPECT_NE(answer->body.find(c.says), std::string::npos) << c.path << ": " << answer->body;
  }
  // Larger than the server takes: refused from its Content-Length, before a byte of the body
  // is sent.
  const std::string huge =
      raw_request("POST /api/measure HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port_) +
                  "\r\nContent-Length: 16777217\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(huge.rfind("HTTP/1.1 413", 0), 0u) << huge;
  EXPECT_NE(huge.find("the picture is larger than 16384 KiB"), std::string::npos) << huge;
  // A body without a length (chunked) is refused: its size could not be checked first.
  const std::string chunked =
      raw_request("POST /api/measure HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port_) +
                  "\r\nTransfer-Encoding: chunked\r\nConnection: "
                  "close\r\n\r\n");
  EXPECT_EQ(chunked.rfind("HTTP/1.1 411", 0), 0u) << chunked;
  // Only POST, and only from this server's own page.
  auto got = get("/api/measure");
  ASSERT_TRUE(got);
  EXPECT_EQ(got->status, 405);
  EXPECT_EQ(got->get_header_value("Allow"), "POST");
  // A small body: refused before it is read, a large one could meet a closed socket.
  auto cross = client.Post("/api/measure", {{"Origin", "http://evil.example"}}, "x", "image/png");
  ASSERT_TRUE(cross);
  EXPECT_EQ(cross->status, 403);
  // No temporary picture is left behind (in this test's own TMPDIR: other tests upload too).
  const char* was = std::getenv("TMPDIR");
  const std::string saved = was ? was : "";
  const fs::path own = fs::temp_directory_path() / "curdle-server-test-uploads";
  fs::create_directories(own);
  ::setenv("TMPDIR", own.c_str(), 1);
  for (const Case& c : cases) (void)client.Post(c.path, c.body, "image/png");
  (void)client.Post("/api/measure", bytes, "image/png");
  was ? ::setenv("TMPDIR", saved.c_str(), 1) : ::unsetenv("TMPDIR");
  EXPECT_TRUE(fs::is_empty(own));
  fs::remove_all(own);
}

// A client that connects and is slow to send (a busy machine) is answered: a new connection
// waits for its first request as long as a request may take to arrive, not the 2 s keep-alive
// (the cause of ServerTest.MeasureTakesAPicture... failing with an empty reason under load).
TEST_F(ServerTest, AClientSlowToSendItsFirstRequestIsAnswered) {
  const int fd = test::connect_loopback(port_);
  ASSERT_GE(fd, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(2500));
  const std::string request =
      "GET /api/recipe HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port_) + "\r\n\r\n";
  ASSERT_EQ(::send(fd, request.data(), request.size(), MSG_NOSIGNAL),
            static_cast<ssize_t>(request.size()));
  char answer[64] = {};
  pollfd p{fd, POLLIN, 0};
  ASSERT_EQ(::poll(&p, 1, 30000), 1);
  const ssize_t n = ::recv(fd, answer, sizeof answer - 1, 0);
  ::close(fd);
  EXPECT_EQ(std::string(answer, n > 0 ? static_cast<size_t>(n) : 0).substr(0, 12), "HTTP/1.1 200");
}

// The page's generate is never brotli- or gzip-compressed, whatever the browser accepts: over
// loopback compression was nearly all of its time.
TEST_F(ServerTest, TheApisJsonIsNotCompressed) {
  httplib::Client client("127.0.0.1", port_);
  client.set_read_timeout(120, 0);
  auto r = client.Get("/api/generate?seed=3", {{"Accept-Encoding", "gzip, deflate, br"}});
  ASSERT_TRUE(r) << httplib::to_string(r.error());
  EXPECT_EQ(r->status, 200);
  EXPECT_FALSE(r->has_header("Content-Encoding")) << r->get_header_value("Content-Encoding");
  EXPECT_EQ(r->body.front(), '{');
  // Nor is the canvas's binary field.
  auto field = client.Get("/api/field?seed=3", {{"Accept-Encoding", "gzip, deflate, br"}});
  ASSERT_TRUE(field) << httplib::to_string(field.error());
  EXPECT_EQ(field->status, 200);
  EXPECT_FALSE(field->has_header("Content-Encoding"))
      << field->get_header_value("Content-Encoding");
  EXPECT_EQ(field->get_header_value("Content-Type"), "application/octet-stream");
  EXPECT_EQ(field->body.substr(0, 4), "CRD1");
}

// Nor is anything else: the page's scripts (three.js took 2 s to brotli-compress on every load),
// a download (1.8 s for a schedule.csv), an error, or the answer to a HEAD.
TEST_F(ServerTest, NoAnswerIsCompressed) {
  httplib::Client client("127.0.0.1", port_);
  client.set_read_timeout(120, 0);
  client.set_decompress(false);
  const httplib::Headers accept{{"Accept-Encoding", "gzip, deflate, br, zstd"}};
  for (const char* target : {"/app.js", "/style.css", "/", "/api/export?seed=3&file=schedule.csv",
                             "/no-such-file", "/api/generate?seed=x"}) {
    auto r = client.Get(target, accept);
    ASSERT_TRUE(r) << target << ": " << httplib::to_string(r.error());
    EXPECT_FALSE(r->has_header("Content-Encoding"))
        << target << ": " << r->get_header_value("Content-Encoding");
    EXPECT_EQ(r->get_header_value("Content-Length"), std::to_string(r->body.size())) << target;
  }
  auto head = client.Head("/app.js", accept);
  ASSERT_TRUE(head) << httplib::to_string(head.error());
  EXPECT_FALSE(head->has_header("Content-Encoding")) << head->get_header_value("Content-Encoding");
  EXPECT_EQ(head->get_header_value("Content-Length"),
            std::to_string(fs::file_size(fs::path(CURDLE_SOURCE_DIR) / "web" / "app.js")));
}

TEST_F(ServerTest, ThePageIsServedFromItsFiles) {
  auto r = get("/");
  ASSERT_TRUE(r) << httplib::to_string(r.error());
  EXPECT_EQ(r->status, 200);
  EXPECT_NE(r->body.find("<script type=\"module\" src=\"app.js\">"), std::string::npos);
  auto js = get("/app.js");
  ASSERT_TRUE(js);
  EXPECT_EQ(js->status, 200);
  auto missing = get("/no-such-file.js");
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->status, 404);
  // No other site may frame the page or run scripts in it; the API's answers say so too.
  for (const auto* answer : {&r, &js, &missing}) {
    EXPECT_EQ((*answer)->get_header_value("X-Frame-Options"), "DENY");
    EXPECT_NE((*answer)->get_header_value("Content-Security-Policy").find("frame-ancestors 'none'"),
              std::string::npos);
  }
  auto api = get("/api/recipe");
  ASSERT_TRUE(api);
  EXPECT_EQ(api->get_header_value("Content-Security-Policy"), kContentSecurityPolicy);
}

// A server of its own on the rhythm façade, whose layout.pdf 3 km tall takes about 40 s.
class RhythmServer {
 public:
  explicit RhythmServer(double request_seconds)
      : serving(config(request_seconds)), port(serving.port()) {}

  // Sends a GET on a socket of its own and returns the socket, unread.
  int send_get(const std::string& path) const {
    const int fd = test::connect_loopback(port);
    EXPECT_GE(fd, 0);
    const std::string request =
        "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n\r\n";
    EXPECT_EQ(::send(fd, request.data(), request.size(), 0), static_cast<ssize_t>(request.size()));
    return fd;
  }
  httplib::Result get(const std::string& path) const {
    httplib::Client client("127.0.0.1", port);
    client.set_read_timeout(120, 0);
    return client.Get(path.c_str());
  }

  static ServerConfig config(double request_seconds) {
    ServerConfig c =
        test::server_config(std::string(CURDLE_SOURCE_DIR) + "/patterns/fins-facade-rhythm.toml");
    c.workers = 1;
    c.request_seconds = request_seconds;
    return c;
  }

  test::ServerOnLoopback serving;
  int port;
};

constexpr const char* kTallPdf = "/api/export?layout.height=3000000&file=layout.pdf";

TEST(ServerWork, AHeavyRequestStopsAtItsBudgetWith503) {
  RhythmServer rhythm(0.5);
  auto r = rhythm.get(kTallPdf);
  ASSERT_TRUE(r) << httplib::to_string(r.error());
  EXPECT_EQ(r->status, 503) << r->body.substr(0, 200);
  EXPECT_NE(r->body.find("budget of 0.5 s"), std::string::npos) << r->body.substr(0, 200);
  // The worker is free again: the next request is answered.
  auto next = rhythm.get("/api/export?file=report.json");
  ASSERT_TRUE(next);
  EXPECT_EQ(next->status, 200);
}

TEST(ServerWork, WorkStopsWhenItsClientGoesAndThePagesGeneratePassesIt) {
  RhythmServer rhythm(600);
  const int abandoned = rhythm.send_get(kTallPdf);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  // The only worker is busy; a generate as small as the page's has its own slot.
  auto small = rhythm.get("/api/generate");
  ASSERT_TRUE(small);
  EXPECT_EQ(small->status, 200);
  pollfd p{abandoned, POLLIN, 0};
  EXPECT_EQ(::poll(&p, 1, 0), 0) << "the tall drawing was already done; it proves nothing";
  // Its client goes: the drawing stops and the worker takes the next export at once, not
  // after the half minute the drawing would take.
  ::close(abandoned);
  const auto start = std::chrono::steady_clock::now();
  auto next = rhythm.get("/api/export?file=report.json");
  const double waited =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(next);
  EXPECT_EQ(next->status, 200);
  EXPECT_LT(waited, 15.0);
}

TEST(ServerSetup, RefusesAMissingPageOrABusyPort) {
  ServerConfig config;
  config.api.recipe_path = kRecipe;
  config.api.recipe_text = slurp(kRecipe);
  config.web_root = "/nonexistent";
  EXPECT_THROW(Server{config}, InputError);
  config.web_root = fs::path(CURDLE_SOURCE_DIR) / "web";
  Server first(config), second(config);
  const int port = first.bind("127.0.0.1", 0);
  EXPECT_THROW(second.bind("127.0.0.1", port), InputError);
  EXPECT_THROW(second.bind("203.0.113.9", 8080), InputError);  // not this machine's address
}

}  // namespace
}  // namespace curdle::server
