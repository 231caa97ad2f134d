// The teaching subcommand of genbsp: `explain`.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace genbsp_tool {

/// `genbsp explain build INPUT -o DIR`, `genbsp explain merge A B --op OP -o
/// DIR`, `genbsp explain depth-order SEGMENTS --eye X,Y -o DIR`, `genbsp
/// explain visibility2d WALLS --eye X,Y -o DIR` and `genbsp explain
/// visibility SCENE --eye X,Y,Z -o DIR`: an algorithm step by step on a small
/// input, as numbered SVG pictures, an `index.html` that steps through them
/// and a JSON trace.
struct explain_job {
  std::string input, other, op = "union", geometry, output, eye, view_dir, projection = "auto";
  CLI::App* command = nullptr;
  CLI::App* build = nullptr;
  CLI::App* merge = nullptr;
  CLI::App* depth = nullptr;
  CLI::App* seen = nullptr;
  CLI::App* space = nullptr; ///< `visibility`, in space
  void add_to(CLI::App& app);
  void run() const;
};

} // namespace genbsp_tool
