#pragma once
/// \file
/// `dyop view SCENE [--runner A --runner B] [--steps N] [--seed S] [--skip all|none|LIST]...
/// [--internal-edges on|off]... [--recycle D]... [--out FILE] [--json FILE|-]`: records a scene
/// under two runners
/// (by default Box2D's own contact and the plug-in's `dyop`; `experiments/lockstep_recording.hpp`)
/// and writes one self-contained HTML page that plays them back side by side
/// (`report/viewer_page.hpp`). SCENE may also be a level of the grounds comparison,
/// `grounds-flat`, `grounds-tile-grid` or `grounds-outline` (`experiments::record_ground`): A's
/// world the level as Box2D's chains, B's through the plug-in's builders, the same bodies on both;
/// or `terrain-craters` (`experiments::record_terrain_craters`: craters dug under a crowd on a
/// chunked terrain, 600 steps by default).
/// The command line (CLI11, `add_view_command`) validates names; this checks them again, checks
/// files and runs.

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace dyop::cli {

struct ViewCommand {
  /// A name of `scenes::scene_catalog()`, `experiments::ground_recording_name` of a level, or
  /// `experiments::terrain_recording_name`.
  std::string scene;
  /// Two runners (`scenes::parse_runner`): A (blue on the page), then B (orange).
  std::vector<std::string> runners = {"box2d-own", "dyop"};
  std::optional<int> steps;  ///< none: the scene's default (a level's: 240)
  std::uint64_t seed = 0;
  /// `parse_skips` arguments: one for both runners, or A's then B's.
  std::vector<std::string> skips = {"all"};
  /// `box2d::Config::internal_edges`, "on" or "off": one for both runners, or A's then B's.
  std::vector<std::string> internal_edges = {"on"};
  /// `box2d::Config::recycle_distance` (metres, ≥ 0; 0: off): one for both runners, or A's then
  /// B's; empty: the default config's.
  std::vector<float> recycle;
  std::string out;   ///< the page; empty: `reports/view/SCENE.html` (directories made as needed)
  std::string json;  ///< the per-step counts (`report::viewer_summary`); empty: none; "-": `out`
};

/// Runs the command: the page is written, then one line per runner and the page's path and size
/// on `out` (on `err` when the JSON goes to `out`). Returns `exit_success`, `exit_usage_error`
/// (unknown name or skip, not two runners, more than two settings) or `exit_io_error` (a file
/// cannot be written, or the scene could not run), with the reason on `err`.
int run_view_command(const ViewCommand& command, std::ostream& out, std::ostream& err);

}  // namespace dyop::cli
