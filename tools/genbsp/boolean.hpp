// The Boolean subcommands of genbsp: `bool` (polygons in the plane or on the
// sphere) and `csg` (closed polyhedra).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace genbsp_tool {

/// `genbsp bool A B --op … [--geometry e2|s2] [--fill-rule …] -o OUT`.
struct bool_job {
  std::string a, b, op = "union", geometry = "e2", fill_rule, output;
  bool progress = false;
  CLI::App* command = nullptr;
  void add_to(CLI::App& app);
  void run() const;
};

/// `genbsp csg A B --op … -o OUT.off|obj|stl`.
struct csg_job {
  std::string a, b, op = "union", output;
  bool progress = false;
  CLI::App* command = nullptr;
  void add_to(CLI::App& app);
  void run() const;
};

} // namespace genbsp_tool
