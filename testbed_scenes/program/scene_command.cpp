#include "scenes/scene_command.hpp"

#include <fstream>
#include <iomanip>
#include <ostream>

#include "scenes/metrics_io.hpp"
#include "scenes/scene.hpp"

namespace dyop::scenes {

void write_summary(const SceneMetrics& m, std::ostream& out) {
  const auto flags = out.flags();
  const auto precision = out.precision(4);
  out << "scene " << m.scene << " / " << m.backend << ", seed " << m.seed << ": " << m.steps
      << " steps, " << m.bodies << " bodies, " << m.triangles << " triangles\n"
      << "  narrow phase: " << m.triangle_pairs << " triangle pairs, " << m.narrowphase_ns_per_pair
      << " ns per pair (" << m.narrowphase_ms_total << " ms); step median " << m.step_ms_median
      << " ms\n"
      << "  penetration (exact): max " << m.max_penetration << " m, mean " << m.mean_penetration
      << " m; depth error vs exact: max " << m.pd_error_max << " m, mean " << m.pd_error_mean
      << " m, misclassified " << m.misclassified << ", invalid " << m.invalid << '\n'
      << "  kinetic energy " << m.kinetic_energy_final << " J";
  if (m.top_displacement) out << ", top displacement " << *m.top_displacement << " m";
  if (m.fallbacks) out << ", fallbacks to Box2D " << *m.fallbacks;
  out << (m.nan_detected ? ", NaN DETECTED" : ", no NaN") << ", hash " << hash_hex(m.hash) << '\n';
  if (m.skip_config && m.skips) {
    out << "  skips " << skip_argument(*m.skip_config) << ": of "
        << m.plugin_evaluations.value_or(0) << " evaluations, skipped";
    for (int s = 0; s < box2d::skip_count; ++s) {
      out << (s ? ", " : " ") << box2d::name(static_cast<box2d::Skip>(s)) << ' ' << (*m.skips)[s];
    }
    out << '\n';
  } else {
    out << (m.backend == box2d_own ? "  skips: none apply (the plug-in is not installed)\n"
                                   : "  skips: none apply (no Box2D world)\n");
  }
  out.precision(precision);
  out.flags(flags);
}

int run_scene_command(const SceneCommand& c, std::ostream& out, std::ostream& err) {
  const SceneInfo* info = find_scene(c.scene);
  const std::optional<box2d::Backend> backend = parse_backend(c.backend);
  const bool own = c.backend == box2d_own;
  if (info == nullptr || !(backend || own)) {
    err << "dyop scene: unknown "
        << (info == nullptr ? "scene '" + c.scene + "'" : "backend '" + c.backend + "'") << '\n';
    return 1;
  }
  if (own && std::string(info->name) == "paper") {
    err << "dyop scene: paper has no Box2D world: " << box2d_own << " runs only Box2D scenes\n";
    return 1;
  }
  const ParsedSkips skips = parse_skips(c.skip);
  if (!skips.ok()) {
    err << "dyop scene: --skip: " << skips.error << '\n';
    return 1;
  }
  if (c.json == "-" && c.svg == "-") {
    err << "dyop scene: --json and --svg cannot both go to standard output\n";
    return 1;
  }
  if (c.steps && *c.steps < 1) {
    err << "dyop scene: --steps must be at least 1\n";
    return 1;
  }
  std::ofstream json_file, svg_file;
  for (auto [path, file] : {std::pair{&c.json, &json_file}, std::pair{&c.svg, &svg_file}}) {
    if (path->empty() || *path == "-") continue;
    file->open(*path);
    if (!*file) {
      err << "dyop scene: cannot write '" << *path << "'\n";
      return 2;
    }
  }
  std::ostream& summary = c.json == "-" || c.svg == "-" ? err : out;

  SceneMetrics m;
  Drawing final_state;
  try {
    m = run_scene(c.scene, own ? Runner() : Runner(backend), c.steps.value_or(info->default_steps),
                  c.seed, skips.config,
                  c.svg.empty() ? nullptr : &final_state);
  } catch (const std::exception& e) {
    err << "dyop scene: " << c.scene << " / " << c.backend << " could not run: " << e.what()
        << '\n';
    return 2;
  }
  write_summary(m, summary);
  if (!c.json.empty()) write_json(m, c.json == "-" ? out : json_file);
  if (!c.svg.empty()) write_svg(final_state, c.svg == "-" ? out : svg_file);
  bool written = static_cast<bool>(out);
  for (std::ofstream* f : {&json_file, &svg_file}) {
    if (!f->is_open()) continue;
    f->close();
    written = written && !f->fail();
  }
  if (!written) {
    err << "dyop scene: output error\n";
    return 2;
  }
  return 0;
}

}  // namespace dyop::scenes
