// `genbsp batch`: one scene, many viewpoints, on every core.  A manifest
// names the scene and the jobs; each job runs the subcommands it asks for
// (stats, map, render) with the scene read once, and reports one JSON line.
#pragma once

#include "commands.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace genbsp_tool {

/// One job of a manifest, as command lines of genbsp's subcommands.
struct planned_job {
  std::size_t index = 0;                       ///< its position in the manifest (0-based)
  nlohmann::ordered_json id;                   ///< the manifest's "id", or null
  std::vector<std::vector<std::string>> commands; ///< argument vectors, each starting "genbsp"
  std::vector<std::string> kinds;              ///< per command: "stats", "map" or "render"
  std::vector<std::string> outputs;            ///< the files the job writes (resolved)
  std::vector<std::string> possible;           ///< the files it writes if there is something to draw (split layers)
};

/// A manifest read and checked: the scene and the jobs.
struct batch_plan {
  std::string scene;              ///< the scene's path (resolved)
  std::vector<planned_job> jobs;  ///< every job of the manifest, in order
};

/// Reads the jobs of a manifest (`{"scene": PATH, "jobs": [...]}`; the
/// scene may be omitted when `scene_override` is given).  Relative paths are
/// taken from `base`.  Every job's command lines are checked before any
/// runs; bad input is a `usage_error` naming `name` and the job.
batch_plan plan_batch(nlohmann::ordered_json const& manifest, std::filesystem::path const& base, std::string const& name,
                      std::string const& scene_override = {});

/// How to run a plan.
struct batch_settings {
  unsigned workers = 0;      ///< threads; 0: one per core (never more than jobs)
  std::size_t shard = 0;     ///< run the jobs whose index is `shard` modulo `shards`
  std::size_t shards = 1;
  /// A progress line on standard error: always, never, or (unset) on a terminal only.
  std::optional<bool> progress;
};

/// Runs the plan's jobs of the shard on `scene` (read once by the caller),
/// calling `report` with each job's result as it ends (one call at a time),
/// and returns the summary.  A failed job removes the files it wrote and
/// does not stop the others.
nlohmann::ordered_json run_batch(batch_plan const& plan, std::shared_ptr<scene_data const> const& scene, batch_settings const& settings,
                                 std::function<void(nlohmann::ordered_json const&)> const& report);

/// "I/N" as a shard (0 <= I < N).
std::pair<std::size_t, std::size_t> parse_shard(std::string const& text);

/// `genbsp batch MANIFEST.json [--jobs N] [--shard I/N] [--progress]`.
struct batch_job {
  std::string manifest, shard;
  unsigned workers = 0;
  bool progress = false;
  CLI::App* command = nullptr;
  void add_to(CLI::App& app);
  int run() const;
};

} // namespace genbsp_tool
