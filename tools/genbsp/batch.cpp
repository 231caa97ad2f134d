// `genbsp batch`: the jobs of a manifest as command lines of the other
// subcommands, run on a pool of threads that share one reading of the scene.
#include "batch.hpp"

#include "common.hpp"

#include <unistd.h>

#include <algorithm>
#include <new>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <mutex>
#include <set>
#include <sstream>
#include <system_error>
#include <thread>

namespace genbsp_tool {

using json = nlohmann::ordered_json;

namespace {

namespace fs = std::filesystem;

/// A JSON number or string as the text a command-line option takes.  A
/// number is written as the shortest decimal that reads back as the same
/// double (so 0.1 stays "0.1" and is then read exactly as one tenth); a
/// string is passed as it is ("1/3", "0.1000000000000000000001").
std::string number_text(json const& v, std::string const& where) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number()) return v.dump();
  throw usage_error(where + ": expected a number or a string, got " + v.dump());
}

/// [x, y, z] (or [x, y]) as "x,y,z".
std::string vector_text(json const& v, std::size_t n, std::string const& where) {
  if (!v.is_array() || v.size() != n)
    throw usage_error(where + ": expected an array of " + std::to_string(n) + " numbers, got " + v.dump());
  std::string t;
  for (std::size_t i = 0; i < n; ++i) t += (i ? "," : "") + number_text(v[i], where);
  return t;
}

/// The value of a render option as one or more arguments after `--NAME`.
void render_option(std::vector<std::string>& args, std::string const& key, json const& v, std::string const& where) {
  std::string name = key;
  std::replace(name.begin(), name.end(), '_', '-');
  std::string flag = "--" + name;
  if (name == "help" || name == "h" || name == "version" || name == "help-all")
    throw usage_error(where + "." + key + ": not a render option");
  if (name == "light" || name == "sun") { // repeatable points or directions
    json list = v.is_array() && !v.empty() && v[0].is_array() ? v : json::array({v});
    for (auto const& p : list) args.insert(args.end(), {flag, vector_text(p, 3, where + "." + key)});
    return;
  }
  if (v.is_boolean()) {
    if (v.get<bool>()) args.push_back(flag);
    return;
  }
  if (name == "size" && v.is_array()) {
    if (v.size() != 2 || !v[0].is_number_integer() || !v[1].is_number_integer())
      throw usage_error(where + ".size: expected [W, H] in pixels or \"WxH\"");
    args.insert(args.end(), {flag, std::to_string(v[0].get<long long>()) + "x" + std::to_string(v[1].get<long long>())});
    return;
  }
  if (v.is_array()) {
    args.insert(args.end(), {flag, vector_text(v, v.size(), where + "." + key)});
    return;
  }
  args.insert(args.end(), {flag, number_text(v, where + "." + key)});
}

/// Checks a command line without running it.
void check_command(std::vector<std::string> const& args) {
  parse_only() = true;
  try {
    run(args);
  } catch (options_checked const&) {
  } catch (...) {
    parse_only() = false;
    throw;
  }
  parse_only() = false;
}

} // namespace

std::pair<std::size_t, std::size_t> parse_shard(std::string const& text) {
  auto slash = text.find('/');
  try {
    if (slash == std::string::npos) throw std::invalid_argument("/");
    std::size_t used1 = 0, used2 = 0;
    auto i = std::stoull(text.substr(0, slash), &used1), n = std::stoull(text.substr(slash + 1), &used2);
    if (used1 != slash || used2 != text.size() - slash - 1 || text[0] == '-' || text[slash + 1] == '-') throw std::invalid_argument("i/n");
    if (n < 1 || i >= n) throw usage_error("--shard: expected 0 <= I < N in I/N, got '" + text + "'");
    return {static_cast<std::size_t>(i), static_cast<std::size_t>(n)};
  } catch (usage_error const&) {
    throw;
  } catch (std::exception const&) {
    throw usage_error("--shard: expected I/N (for example 0/4), got '" + text + "'");
  }
}

batch_plan plan_batch(json const& manifest, fs::path const& base, std::string const& name, std::string const& scene_override) {
  auto resolve = [&](std::string const& p) {
    fs::path q(p);
    return (q.is_absolute() ? q : base / q).lexically_normal().string();
  };
  if (!manifest.is_object()) throw usage_error(name + ": the manifest is a JSON object {\"scene\": …, \"jobs\": […]}");
  for (auto const& [key, value] : manifest.items())
    if (key != "scene" && key != "jobs") throw usage_error(name + ": unknown key \"" + key + "\" (expected scene and jobs)");
  batch_plan plan;
  if (!scene_override.empty()) {
    plan.scene = scene_override;
  } else {
    if (!manifest.contains("scene") || !manifest["scene"].is_string()) throw usage_error(name + ": \"scene\": expected the scene file's path");
    plan.scene = resolve(manifest["scene"].get<std::string>());
  }
  if (!manifest.contains("jobs") || !manifest["jobs"].is_array()) throw usage_error(name + ": \"jobs\": expected an array of jobs");
  std::map<std::string, std::size_t> written; // output → job
  auto const& jobs = manifest["jobs"];
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    std::string where = name + ": job " + std::to_string(k);
    json const& j = jobs[k];
    if (!j.is_object()) throw usage_error(where + ": expected an object");
    static std::set<std::string> const known{"id", "eye", "view_dir", "up", "number", "cull_backfaces", "simplify", "stats", "map", "render"};
    for (auto const& [key, value] : j.items())
      if (!known.contains(key))
        throw usage_error(where + ": unknown key \"" + key + "\" (expected id, eye, view_dir, up, number, cull_backfaces, simplify, stats, map, render)");
    planned_job p;
    p.index = k;
    if (j.contains("id")) p.id = j["id"];
    // What every command of the job shares: the viewpoint and the build options.
    std::vector<std::string> common{plan.scene};
    std::string eye;
    if (j.contains("eye")) eye = vector_text(j["eye"], 3, where + ".eye");
    auto flag = [&](char const* key) {
      if (!j.contains(key)) return std::optional<bool>();
      if (!j[key].is_boolean()) throw usage_error(where + "." + key + ": expected true or false");
      return std::optional<bool>(j[key].get<bool>());
    };
    if (j.contains("number")) {
      if (!j["number"].is_string()) throw usage_error(where + ".number: expected \"exact\" or \"double\"");
      common.insert(common.end(), {"--number", j["number"].get<std::string>()});
    }
    if (flag("cull_backfaces").value_or(false)) common.push_back("--cull-backfaces");
    if (!flag("simplify").value_or(true)) common.push_back("--no-simplify");
    std::vector<std::string> viewpoint;
    if (!eye.empty()) viewpoint = {"--eye", eye};
    if (j.contains("view_dir")) viewpoint.insert(viewpoint.end(), {"--view-dir", vector_text(j["view_dir"], 3, where + ".view_dir")});
    std::vector<std::string> places; // per command: where in the manifest it comes from
    auto add = [&](std::string const& kind, std::vector<std::string> args, std::string const& place) {
      args.insert(args.begin(), "genbsp");
      p.commands.push_back(std::move(args));
      p.kinds.push_back(kind);
      places.push_back(place);
    };
    auto claim = [&](std::string const& file, std::string const& what, bool surely = true) {
      if (auto [at, fresh] = written.emplace(file, k); !fresh)
        throw usage_error(where + ": " + what + " " + file + " is written by job " + std::to_string(at->second) + " too");
      (surely ? p.outputs : p.possible).push_back(file);
    };
    auto output = [&](std::string const& path, std::string const& what) {
      auto r = resolve(path);
      claim(r, what);
      return r;
    };
    bool stats = flag("stats").value_or(false);
    std::vector<std::string> map_args = {"map"};
    map_args.insert(map_args.end(), common.begin(), common.end());
    map_args.insert(map_args.end(), viewpoint.begin(), viewpoint.end());
    if (j.contains("up")) map_args.insert(map_args.end(), {"--up", vector_text(j["up"], 3, where + ".up")});
    if (j.contains("map")) {
      if (!j["map"].is_string()) throw usage_error(where + ".map: expected the output MAP.json's path");
      map_args.insert(map_args.end(), {"-o", output(j["map"].get<std::string>(), "map")});
      if (stats) map_args.push_back("--stats");
      add("map", map_args, where);
    } else if (stats) {
      map_args[0] = "stats";
      if (j.contains("up")) throw usage_error(where + ".up: for a map (with view_dir)");
      add("stats", map_args, where);
    }
    if (j.contains("render")) {
      json renders = j["render"].is_array() ? j["render"] : json::array({j["render"]});
      for (std::size_t r = 0; r < renders.size(); ++r) {
        std::string rw = where + ".render" + (j["render"].is_array() ? "[" + std::to_string(r) + "]" : "");
        json const& spec = renders[r];
        if (!spec.is_object()) throw usage_error(rw + ": expected an object of render options");
        if (!spec.contains("output") || !spec["output"].is_string()) throw usage_error(rw + ".output: expected the image's path");
        std::vector<std::string> args = {"render"};
        args.insert(args.end(), common.begin(), common.end());
        if (!eye.empty()) args.insert(args.end(), {"--eye", eye});
        for (auto const& [key, value] : spec.items()) {
          if (key == "output") continue;
          if (key == "eye" || key == "number" || key == "cull_backfaces" || key == "no_simplify" || key == "progress")
            throw usage_error(rw + "." + key + ": set it on the job, not on its render");
          render_option(args, key, value, rw);
        }
        // Every file the render may write (a cube map's faces, split layers)
        // is the job's: no other job may write it, and a failure removes it.
        auto is = [&](char const* key, json const& value) {
          std::string dashed = key;
          std::replace(dashed.begin(), dashed.end(), '_', '-');
          return (spec.contains(key) && spec[key] == value) || (spec.contains(dashed) && spec[dashed] == value);
        };
        bool cube = is("projection", "cube"), layers = is("split_layers", true);
        auto image = resolve(spec["output"].get<std::string>());
        auto files = render_files(image, cube, layers);
        std::size_t views = cube ? cube_faces.size() : 1;
        for (std::size_t f = 0; f < files.size(); ++f) claim(files[f], "image", f < views);
        args.insert(args.end(), {"-o", image});
        add("render", std::move(args), rw);
      }
    }
    if (p.commands.empty()) throw usage_error(where + ": asks for nothing (give stats, map or render)");
    for (std::size_t c = 0; c < p.commands.size(); ++c) try {
        check_command(p.commands[c]);
      } catch (usage_error const& e) {
        throw usage_error(places[c] + ": " + e.what());
      }
    plan.jobs.push_back(std::move(p));
  }
  return plan;
}

json run_batch(batch_plan const& plan, std::shared_ptr<scene_data const> const& scene, batch_settings const& settings,
               std::function<void(json const&)> const& report) {
  auto start = std::chrono::steady_clock::now();
  std::vector<planned_job const*> todo;
  for (auto const& j : plan.jobs)
    if (j.index % settings.shards == settings.shard) todo.push_back(&j);
  unsigned workers = settings.workers ? settings.workers : std::max(1u, std::thread::hardware_concurrency());
  workers = static_cast<unsigned>(std::min<std::size_t>(workers, std::max<std::size_t>(todo.size(), 1)));
  std::atomic<std::size_t> next{0};
  std::mutex lock; // guards the counters, `report` and the progress line
  std::size_t done = 0, failed = 0, bad_input = 0;
  bool tty = ::isatty(2) != 0;
  bool report_progress = settings.progress.value_or(tty);
  int last_decile = -1;
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  auto show_progress = [&] {
    if (!report_progress) return;
    double t = elapsed();
    if (tty) {
      double left = done ? t / static_cast<double>(done) * static_cast<double>(todo.size() - done) : 0;
      std::fprintf(stderr, "\rgenbsp: batch %zu/%zu jobs, %zu failed (%.0f s, about %.0f s left)%s", done, todo.size(), failed, t, left,
                   done == todo.size() ? "\n" : "");
    } else if (int decile = static_cast<int>(10 * done / std::max<std::size_t>(todo.size(), 1)); decile != last_decile) {
      last_decile = decile;
      std::fprintf(stderr, "genbsp: batch %zu/%zu jobs, %zu failed (%.1f s)\n", done, todo.size(), failed, t);
    }
    std::fflush(stderr);
  };
  auto work = [&] {
    // The calling thread works too; it gets its flag back afterwards.
    struct worker_flag {
      bool previous = batch_worker();
      worker_flag() { batch_worker() = true; }
      ~worker_flag() { batch_worker() = previous; }
    } flag;
    scene_scope scope(scene);
    for (std::size_t i; (i = next.fetch_add(1)) < todo.size();) {
      auto const& job = *todo[i];
      auto t0 = std::chrono::steady_clock::now();
      json result{{"job", job.index}};
      if (!job.id.is_null()) result["id"] = job.id;
      std::ostringstream captured;
      std::ostream* previous = output_stream();
      output_stream() = &captured;
      std::size_t finished = 0; // commands that ran to the end (their files written)
      int status = 0;
      std::string error;
      json renders = json::array();
      try {
        for (; finished < job.commands.size(); ++finished) {
          captured.str({});
          run(job.commands[finished]);
          auto const& kind = job.kinds[finished];
          std::string text = captured.str();
          if (kind == "stats" || (kind == "map" && !text.empty())) result["stats"] = json::parse(text);
          if (kind == "render" && !text.empty()) renders.push_back(json::parse(text));
        }
      } catch (usage_error const& e) {
        status = 2, error = e.what();
      } catch (geometry::io::read_error const& e) {
        status = 2, error = e.what();
      } catch (std::bad_alloc const&) {
        status = 2, error = out_of_memory_text();
      } catch (std::exception const& e) {
        status = 1, error = std::string("internal error: ") + e.what();
      }
      output_stream() = previous;
      if (status) {
        // Whole or not at all: the files of the commands that had finished go too.
        std::error_code ec;
        for (auto const& f : job.outputs) fs::remove(f, ec);
        for (auto const& f : job.possible) fs::remove(f, ec);
        result["ok"] = false;
        result["error"] = error;
        result["status"] = status;
      } else {
        result["ok"] = true;
        auto written = job.outputs;
        std::error_code ec;
        for (auto const& f : job.possible)
          if (fs::exists(f, ec)) written.push_back(f);
        result["outputs"] = written;
        if (!renders.empty()) result["render"] = std::move(renders);
      }
      result["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::lock_guard<std::mutex> g(lock);
      ++done;
      if (status) ++failed, bad_input += status == 2;
      report(result);
      show_progress();
    }
  };
  {
    std::vector<std::jthread> pool;
    for (unsigned w = 1; w < workers; ++w) {
      try {
        pool.emplace_back(work);
      } catch (std::system_error const&) {
        break; // no room for another thread (a memory limit, say): the ones started do the work
      }
    }
    workers = static_cast<unsigned>(pool.size()) + 1;
    work();
  }
  json shard = settings.shards > 1 ? json(std::to_string(settings.shard) + "/" + std::to_string(settings.shards)) : json(nullptr);
  return {{"genbsp", version()},   {"scene", plan.scene},  {"jobs", todo.size()}, {"ok", todo.size() - failed},
          {"failed", failed},      {"bad_input", bad_input}, {"workers", workers},  {"shard", shard},
          {"seconds", elapsed()}};
}

void batch_job::add_to(CLI::App& app) {
  command = app.add_subcommand("batch",
                               "run many jobs on one scene on every core: a JSON manifest {\"scene\": PATH, \"jobs\": [{\"eye\": [X,Y,Z], "
                               "\"stats\": true, \"map\": PATH, \"render\": {…}}, …]} (docs/batch.md); prints a JSON line per job and a summary");
  command->add_option("MANIFEST", manifest, "the manifest, JSON (- for standard input); relative paths in it are from its folder")->required();
  command->add_option("-j,--jobs", workers, "threads (default: one per core)")->check(CLI::Range(1u, 1024u));
  command->add_option("--shard", shard, "run only the jobs whose index is I modulo N, as I/N (0 <= I < N): one part of a job array");
  command->add_flag("--progress", progress, "report the jobs done on standard error (always on a terminal)");
}

int batch_job::run() const {
  std::string text, name = manifest == "-" ? "<stdin>" : manifest;
  if (manifest == "-") {
    text.assign(std::istreambuf_iterator<char>(std::cin), {});
  } else {
    std::ifstream in(manifest, std::ios::binary);
    if (!in) {
      int code = errno;
      throw file_error(manifest + ": cannot open", code);
    }
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  json m;
  try {
    m = json::parse(text);
  } catch (json::parse_error const& e) {
    // The line of the byte the parser stopped at.
    std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(std::min(e.byte, text.size())), '\n'));
    std::string what = e.what();
    auto colon = what.find(": ", what.find("parse error"));
    throw usage_error(name + ":" + std::to_string(line) + ": not JSON (" + (colon == std::string::npos ? what : what.substr(colon + 2)) + ")");
  }
  fs::path base = manifest == "-" ? fs::current_path() : fs::absolute(manifest).parent_path();
  batch_settings s;
  s.workers = workers;
  if (progress) s.progress = true;
  if (!shard.empty()) std::tie(s.shard, s.shards) = parse_shard(shard);
  auto plan = plan_batch(m, base, name);
  auto scene = read_scene_data(plan.scene);
  std::ostream* o = &out();
  auto summary = run_batch(plan, scene, s, [o](json const& line) { *o << line.dump() << "\n" << std::flush; });
  out() << json{{"summary", summary}}.dump() << "\n";
  auto failed = summary["failed"].get<std::size_t>(), bad = summary["bad_input"].get<std::size_t>();
  return failed == 0 ? 0 : failed == bad ? 2 : 1;
}

} // namespace genbsp_tool
