#include "studio/server.hpp"

#include <httplib.h>

#include <atomic>
#include <cctype>
#include <chrono>
#include <ctime>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include <fmt/format.h>

#include "io/html_page.hpp"
#include "io/interrupt.hpp"
#include "renders/figure.hpp"
#include "sizing/sizing.hpp"
#include "studio/answer.hpp"
#include "studio/mesh_upload.hpp"
#include "studio/studio_assets.hpp"
#include "twin/load_builder.hpp"

namespace sreh::studio {
namespace {

constexpr const char* kJsonType = "application/json";

// Every response goes out as it is, never compressed: cpp-httplib compresses
// a JSON or text/ body when the client accepts it, and Chromium accepts
// brotli, which the library runs at quality 11: 60-130 ms for a single
// move's ~85 kB answer (more than the answer itself often takes), 0.5 s for
// a report, to save nothing over the loopback (issue 37,
// docs/performance-sizing.md). A body of known length from a content
// provider is written as it is.
void reply(httplib::Response& res, std::string body, const std::string& type) {
  if (body.empty()) {
    res.set_content(body, type);
    return;
  }
  auto kept = std::make_shared<const std::string>(std::move(body));
  res.set_content_provider(kept->size(), type, [kept](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
    return sink.write(kept->data() + offset, length);
  });
}

// What the page needs to know besides the state: the shapes and the limits
// (read from the sizing, never retyped in the script).
Json meta() {
  Json shapes = Json::array();
  for (const ShapeKeys& s : part_shapes()) shapes.push_back({{"shape", s.shape}, {"keys", s.keys}});
  return {{"shapes", shapes},
          {"max_load_gcm2", max_load_gcm2()},
          {"min_voltage_V", sizing::min_voltage_V()},
          {"max_voltage_V", sizing::max_voltage_V()},
          {"max_mesh_upload_bytes", kMaxMeshUploadBytes}};
}

std::string page(const Json& initial) {
  // </ inside a script would end it: the JSON's slashes escaped.
  std::string data = Json{{"meta", meta()}, {"project", initial}}.dump();
  for (std::size_t at = data.find("</"); at != std::string::npos; at = data.find("</", at)) data.replace(at, 2, "<\\/");
  return io::html_page("sreh-twin studio: sizing in the browser",
                       fmt::format("<style>{}</style>\n<link rel=\"stylesheet\" href=\"/assets/studio.css\">\n"
                                   "<link rel=\"icon\" href=\"data:,\">\n",
                                   io::kPageCss),
                       std::string(find_studio_asset("studio_body.html")) + "<script>window.STUDIO = " + data +
                           ";</script>\n<script src=\"/assets/studio.js\"></script>\n");
}

std::string content_type_for(const std::string& name) {
  if (name.ends_with(".js")) return "text/javascript; charset=utf-8";
  if (name.ends_with(".css")) return "text/css; charset=utf-8";
  return "text/html; charset=utf-8";
}

// The state of a request: the JSON body (POST) or ?s=JSON (GET links, the
// exports the page offers as downloads).
Json state_of(const httplib::Request& req) {
  const std::string text = req.method == "POST" ? req.body : req.get_param_value("s");
  Json j = Json::parse(text, nullptr, false);
  if (j.is_discarded()) throw ProjectError("the state is not valid JSON");
  return j;
}

double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

std::string file_stem(const Json& state) {
  std::string out;
  for (char c : state.value("name", std::string("project"))) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return out.empty() ? "project" : out;
}

} // namespace

void run_studio(const StudioOptions& o, const std::function<void(const std::string& url)>& ready) {
  const Json initial = o.project.empty() ? normalised_state(Json{{"parts", Json::array()}}) : state_from_project_file(o.project);
  const std::string html = page(initial);
  std::mutex sizing_mutex; // one sizing at a time: the page debounces, a second tab waits
  std::atomic<int> simulations{0}; // of the answer being computed: the page's progress bar
  httplib::Server server;
  server.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
    std::string what = "internal error";
    try {
      if (ep) std::rethrow_exception(ep);
    } catch (const std::exception& e) {
      what = e.what();
    }
    res.status = 400;
    reply(res, Json{{"error", what}}.dump(), kJsonType);
  });
  server.Get("/", [&](const httplib::Request&, httplib::Response& res) { reply(res, html, "text/html; charset=utf-8"); });
  server.Get(R"(/assets/([A-Za-z0-9._-]+))", [](const httplib::Request& req, httplib::Response& res) {
    const std::string name = req.matches[1];
    const std::string_view body = find_studio_asset(name);
    if (body.empty()) {
      res.status = 404;
      return;
    }
    reply(res, std::string(body), content_type_for(name));
  });
  server.Post("/api/answer", [&](const httplib::Request& req, httplib::Response& res) {
    const Json state = state_of(req);
    const auto t0 = std::chrono::steady_clock::now();
    Json a;
    double cpu_ms = 0;
    {
      std::lock_guard<std::mutex> lock(sizing_mutex);
      const double c0 = thread_cpu_ms();
      simulations = 0;
      a = answer(state, [&simulations] { ++simulations; });
      cpu_ms = thread_cpu_ms() - c0;
    }
    // Wall time (includes waiting for another tab's sizing) and this thread's CPU time (docs/performance-sizing.md).
    a["elapsed_ms"] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    a["cpu_ms"] = cpu_ms;
    reply(res, a.dump(), kJsonType);
  });
  // The progress of the answer being computed (a cycle takes seconds): its simulations so far.
  server.Get("/api/progress", [&](const httplib::Request&, httplib::Response& res) {
    reply(res, Json{{"simulations", simulations.load()}}.dump(), kJsonType);
  });
  auto download = [&](const char* path, const char* ext, const char* type, auto make) {
    server.Get(path, [&, ext, type, make](const httplib::Request& req, httplib::Response& res) {
      const Json state = state_of(req);
      std::string body;
      {
        std::lock_guard<std::mutex> lock(sizing_mutex);
        body = make(state);
      }
      res.set_header("Content-Disposition", fmt::format("attachment; filename=\"{}{}\"", file_stem(state), ext));
      reply(res, body, type);
    });
  };
  download("/api/export/project", ".yaml", "application/yaml", [](const Json& s) { return project_yaml(s); });
  download("/api/export/csv", ".csv", "text/csv", [](const Json& s) { return answer_csv(s); });
  download("/api/export/scenario", "_scenario.yaml", "application/yaml", [](const Json& s) { return answer_scenario(s); });
  // An STL for a mesh part: the body is the file, ?name= the name the user picked.
  const std::string meshes = mesh_folder(o.project);
  // A larger body is refused (413) before it is read; the page checks the size first and names the file and limit.
  server.set_payload_max_length(kMaxMeshUploadBytes);
  server.Post("/api/mesh", [&](const httplib::Request& req, httplib::Response& res) {
    const StoredMesh m = store_mesh(req.get_param_value("name"), req.body, meshes);
    reply(res, Json{{"file", m.path}, {"triangles", m.triangles}, {"volume", m.volume}}.dump(), kJsonType);
  });
  server.Get("/api/picture", [&](const httplib::Request& req, httplib::Response& res) {
    const Json state = state_of(req);
    std::lock_guard<std::mutex> lock(sizing_mutex);
    reply(res, load_picture_png(state), "image/png");
  });
  server.Get("/report", [&](const httplib::Request& req, httplib::Response& res) {
    const Json state = state_of(req);
    std::lock_guard<std::mutex> lock(sizing_mutex);
    reply(res, answer_report(state, o.version), "text/html; charset=utf-8");
  });
  const int port = o.port == 0 ? server.bind_to_any_port(o.host) : (server.bind_to_port(o.host, o.port) ? o.port : -1);
  if (port < 0) throw std::runtime_error(fmt::format("--http {}:{}: cannot listen there", o.host, o.port));
  std::thread listener([&] { server.listen_after_bind(); });
  ready(fmt::format("http://{}:{}/", o.host.find(':') != std::string::npos ? "[" + o.host + "]" : o.host, port));
  while (io::interrupt_signal() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  server.stop();
  listener.join();
}

} // namespace sreh::studio
