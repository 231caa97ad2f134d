// The 2D visibility subcommand of genbsp: `visibility2d`.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace genbsp_tool {

/// `genbsp visibility2d SCENE --eye X,Y | --eyes FILE [--box X0,Y0,X1,Y1] -o OUT.wkt|geojson|svg`.
struct visibility2d_job {
  std::string scene, eye, eyes, box, output;
  std::uint64_t seed = 1;
  CLI::App* command = nullptr;
  void add_to(CLI::App& app);
  void run() const;
};

} // namespace genbsp_tool
