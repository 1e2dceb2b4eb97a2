// `dyop compare`'s terrain section: a chunked terrain (`OutlineTerrain`) played as a game plays it
// (`experiments/terrain_runs.hpp`): craters dug under and beside a crowd on the 300 m level with
// caves (each edit's cost, the step after it, what the bodies feel), bodies sliding a kilometre
// across a level streamed around them (their glide across the seams, what stays loaded, memory
// beside Box2D's chain and `add_outline`), and a viewer page of the craters
// (`view_terrain-craters.html`).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "experiments/progress.hpp"
#include "experiments/terrain_runs.hpp"
#include "report/compare_section.hpp"
#include "report/compare_summary.hpp"
#include "report/format.hpp"
#include "report/records.hpp"
#include "report/viewer_page.hpp"
#include "scenes/metrics.hpp"

namespace dyop::report {
namespace {

using experiments::TerrainCraters;
using experiments::TerrainEdit;
using experiments::TerrainStream;

double largest(const std::vector<double>& v) {
  return v.empty() ? 0 : *std::max_element(v.begin(), v.end());
}

// Each edit's figure `of`.
std::vector<double> of_edits(const TerrainCraters& c, double TerrainEdit::*of) {
  std::vector<double> v;
  for (const TerrainEdit& e : c.edits) v.push_back(e.*of);
  return v;
}

class TerrainSection : public CompareSection {
 public:
  const char* section_name() const override { return "terrain"; }

  void run(const SectionContext& c) override {
    using experiments::detail::fixed;
    out_dir_ = c.options.out_dir;
    if (!experiments::terrain_available()) {
      skipped_ = true;
      return;
    }
    timing_ = experiments::terrain_timing(c.options.quick, c.options.steps);
    double start = c.elapsed();
    craters_ = experiments::run_terrain_craters(timing_, c.options.skips, c.options.seed);
    c.progress << "[terrain] craters under a crowd of " << craters_.bodies << ", "
               << craters_.edits.size() << " craters over " << timing_.crater_steps << " steps × "
               << timing_.crater_runs << ": " << fixed(c.elapsed() - start, 2) << " s (total "
               << fixed(c.elapsed(), 1) << " s)\n"
               << std::flush;
    start = c.elapsed();
    stream_ = experiments::run_terrain_stream(timing_, c.options.skips);
    c.progress << "[terrain] " << fixed(stream_.distance, 0)
               << " m across two streamed levels, 4 bodies each, " << stream_.steps
               << " steps: " << fixed(c.elapsed() - start, 2) << " s (total "
               << fixed(c.elapsed(), 1) << " s)\n"
               << std::flush;
    start = c.elapsed();
    std::ostringstream page;
    write_viewer_page(experiments::record_terrain_craters(
                          {std::nullopt, box2d::Backend::Dyop}, timing_.crater_steps,
                          {c.options.skips, c.options.skips}, c.options.seed),
                      page);
    page_ = page.str();
    c.progress << "[terrain] viewer page, " << timing_.crater_steps
               << " steps: " << fixed(c.elapsed() - start, 2) << " s (total "
               << fixed(c.elapsed(), 1) << " s)\n"
               << std::flush;
    measured_ = true;
  }

  bool measured() const override { return measured_ || skipped_; }

  void write_tables(std::ostream& out) const override {
    if (!measured_) {
      out << "\nTerrain section not run: no dyop::box2d_outlines (GEOS) in this build.\n";
      return;
    }
    out << "\nA chunked terrain (OutlineTerrain) under a crowd, craters dug over "
        << fmt("%.0f", timing_.crater_steps / 60.0) << " s (plug-in installed):\n\n";
    timing_records().write_table(out);
    out << step_ratios() << '\n';
    check_records().write_table(out);
    out << "\nBodies sliding " << fmt("%.0f", stream_.distance)
        << " m across levels streamed around them:\n\n";
    glide_records().write_table(out);
    out << '\n';
    streaming_records().write_table(out);
    out << '\n';
    memory_records().write_table(out);
    out << "\nViewer page (the craters appearing under the crowd, Box2D's own contact A, the "
           "plug-in B; open in a browser):\n  "
        << out_dir_ << '/' << page_file() << "  (" << fmt("%.1f", double(page_.size()) / 1e6)
        << " MB)\n";
  }

  void write_files(ReportDirectory& dir, Charts&) const override {
    if (!measured_) return;
    dir.write(page_file(), [&](std::ostream& o) { o << page_; });
    dir.write("terrain_edits.csv", [&](std::ostream& o) { edit_records().write_csv(o); });
    dir.write("terrain_timing.csv", [&](std::ostream& o) { timing_records().write_csv(o); });
    dir.write("terrain_checks.csv", [&](std::ostream& o) { check_records().write_csv(o); });
    dir.write("terrain_glides.csv", [&](std::ostream& o) { glide_records().write_csv(o); });
    dir.write("terrain_streaming.csv", [&](std::ostream& o) { streaming_records().write_csv(o); });
    dir.write("terrain_memory.csv", [&](std::ostream& o) { memory_records().write_csv(o); });
  }

  void write_markdown(std::ostream& o, const Charts&) const override {
    o << "## A terrain edited and streamed while it is played\n\n";
    if (!measured_) {
      o << "*Not run: this build has no `dyop::box2d_outlines` (GEOS not found).*\n\n";
      return;
    }
    o << "`dyop::box2d::OutlineTerrain` holds a level's outline in 16 m chunks of triangles (2 m "
         "cells), with the plug-in installed (`dyop`), sleeping off as in every world of this "
         "report.\n\n"
      << "**Craters under a crowd.** The 300 m level with caves, " << craters_.triangles
      << " triangles in " << craters_.chunks << " chunks (friction 0.6); " << craters_.bodies
      << " everyday bodies (boxes of two triangles, `SetAsBox` boxes, "
         "hexagons, balls; friction 0.6) resting along its top 1.5 m apart (balls only where the "
         "top is within 3° of level), "
      << craters_.pushed
      << " of them pushed along it at 2 m/s (they meet only the ground); after 1 s to settle, "
      << timing_.craters() << " craters of radius 1, 1.5 and 2 m in turn over "
      << fmt("%.0f", timing_.crater_steps / 60.0)
      << " s, one every 0.25 s: under a resting body, beside one (the rim 0.5 m from its side), "
         "or 3 m ahead of a pushed one; "
      << craters_.runs << (craters_.runs == 1 ? " scene" : " scenes, timings pooled")
      << ". Times: the `remove` call and each `Step`, wall clock and this "
         "thread's CPU time (a call preempted on a shared machine shows a long wall time and a "
         "short CPU time). Checks after every step: a body's centre inside the ground "
         "(`OutlineTerrain::solid`), the deepest overlap of a body's skin with the ground (Box2D "
         "keeps about 5 mm, `b2_linearSlop`), and, for every body resting when an edit is made "
         "(speed ≤ "
      << fmt("%g", experiments::resting_speed) << " m/s for the last " << experiments::resting_steps
      << " steps), its largest vertical speed until the next edit, unless another body struck it; "
         "far: "
      << fmt("%g", experiments::far_from_edit)
      << " m or more between the rim and its side (expected ≤ 0.01 m/s).\n\n";
    timing_records().write_markdown(o);
    o << '\n' << step_ratios() << '\n';
    check_records().write_markdown(o);
    o << "\nEvery crater: `terrain_edits.csv`. Step by step in a browser: [the craters appearing "
         "under the crowd]("
      << page_file()
      << ") (Box2D's own contact as A beside the plug-in as B, the same craters; `dyop view "
         "terrain-craters` writes it alone).\n\n"
      << "**Kilometres streamed.** Two levels of " << fmt("%.0f", stream_.length)
      << " m, 20 m deep, a vertex of the top every 8 m: a flat one, its top the side y = 0 between "
         "two rows of chunks; a gently undulating one, its top's slope turning by 1/512 at each "
         "vertex, ±0.5 m around that side ("
      << stream_.chunks << " chunks, " << stream_.triangles
      << " triangles). On each, each everyday body alone (frictionless) launched at 4 m/s along "
         "the top and pushed along it against gravity's pull down its slopes (a free glide keeps "
         "its speed), "
      << fmt("%.0f", stream_.distance) << " m (" << stream_.steps
      << " steps), only the chunks overlapping a camera region loaded: a 24 × 16 m view centred "
         "on the body and a 10 m margin, `load(region)` after every step. Speed across the "
         "ground: |v·n|, n the normal of the top under the body's centre (on the flat level, its "
         "vertical speed), after the first step; a turn of 1/512 is 8 mm/s of it at 4 m/s. "
         "Travel: distance along x over 4 m/s × time (expected ≤ 0.01 m/s and ≥ 99 %).\n\n";
    glide_records().write_markdown(o);
    o << "\nWhat the world holds on the undulating level, over every body's run, after each "
         "`load` (the body's own included); per loaded chunk: mean over mean:\n\n";
    streaming_records().write_markdown(o);
    o << "\nMemory of the undulating level: Box2D's bodies, fixtures, shapes, chain vertices and "
         "proxies (proxy, tree "
         "leaf and an inner node each); the terrain's own (`OutlineTerrain::bytes`: its pieces "
         "of ground and triangle lists, every chunk's, loaded or not). Per metre of the outline's "
         "boundary ("
      << fmt("%.0f", stream_.boundary) << " m):\n\n";
    memory_records().write_markdown(o);
    o << '\n';
  }

  std::string files() const override {
    return "`terrain_edits.csv` (every crater: its cost, the step after it, the bodies near and "
           "far), `terrain_timing.csv`, `terrain_checks.csv`, `terrain_glides.csv`, "
           "`terrain_streaming.csv`, `terrain_memory.csv`, `view_terrain-craters.html` (viewer "
           "page: the craters under the crowd)";
  }

  void problems(std::vector<std::string>& lines) const override {
    if (skipped_) {
      lines.push_back(
          "terrain: not run (no dyop::box2d_outlines: GEOS not found at configure time)");
    }
  }

  void summarize(SummaryFigures& figures) const override {
    figures.viewer_pages = figures.viewer_pages || measured_;
  }

 private:
  static std::string page_file() { return viewer_page_file(experiments::terrain_recording_name); }

  // The step after an edit over the median step without one (wall): its median and largest.
  std::string step_ratios() const {
    const std::vector<double> after = of_edits(craters_, &TerrainEdit::step_ms);
    const double plain = scenes::median(craters_.plain_step_ms);
    return "The `Step` after an edit over the median `Step` without one (wall): median " +
           fmt("%.2f", scenes::median(after) / plain) + "×, largest " +
           fmt("%.2f", largest(after) / plain) + "×.\n";
  }

  Records edit_records() const {
    Records out({{"run", "", "", 3},
                 {"step", "", "", 5},
                 {"placement", "", "", -7},
                 {"x_m", "", "", 7},
                 {"y_m", "", "", 7},
                 {"radius_m", "", "", 5},
                 {"destroyed", "", "", 4},
                 {"created", "", "", 4},
                 {"kept", "", "", 4},
                 {"edit_ms", "", "", 7},
                 {"edit_cpu_ms", "", "", 7},
                 {"step_ms", "", "", 7},
                 {"step_cpu_ms", "", "", 7},
                 {"far_bodies", "", "", 4},
                 {"far_max_vertical_speed", "", "", 8},
                 {"near_bodies", "", "", 4},
                 {"near_max_vertical_speed", "", "", 8}});
    for (const TerrainEdit& e : craters_.edits) {
      out.add({Value::count(e.run), Value::count(e.step), Value::text(e.placement),
               Value::number(e.centre.x, "%.3f"), Value::number(e.centre.y, "%.3f"),
               Value::number(e.radius, "%.2f"), Value::count(e.destroyed), Value::count(e.created),
               Value::count(e.kept), Value::number(e.edit_ms, "%.4f"),
               Value::number(e.edit_cpu_ms, "%.4f"), Value::number(e.step_ms, "%.4f"),
               Value::number(e.step_cpu_ms, "%.4f"), Value::count(e.far_bodies),
               Value::number(e.far_vertical_speed, "%.5f"), Value::count(e.near_bodies),
               Value::number(e.near_vertical_speed, "%.5f")});
    }
    return out;
  }

  Records timing_records() const {
    Records out({{"part", "part", "", -10},
                 {"what", "what", "", -40},
                 {"count", "count", "", 6},
                 {"median_ms", "median (ms)", "", 8},
                 {"largest_ms", "largest (ms)", "", 8}});
    const auto row = [&](const char* part, const char* what, const std::vector<double>& v) {
      out.add({Value::text(part), Value::text(what), Value::count(static_cast<int>(v.size())),
               Value::number(scenes::median(v), "%.3f"), Value::number(largest(v), "%.3f")});
    };
    row("craters", "edit call (`remove`), wall", of_edits(craters_, &TerrainEdit::edit_ms));
    row("craters", "edit call (`remove`), CPU", of_edits(craters_, &TerrainEdit::edit_cpu_ms));
    row("craters", "`Step` after an edit, wall", of_edits(craters_, &TerrainEdit::step_ms));
    row("craters", "`Step` after an edit, CPU", of_edits(craters_, &TerrainEdit::step_cpu_ms));
    row("craters", "`Step` without an edit before it, wall", craters_.plain_step_ms);
    row("craters", "`Step` without an edit before it, CPU", craters_.plain_step_cpu_ms);
    out.add({Value::text("streaming"), Value::text("`load(region)` after each step, wall"),
             Value::count(stream_.load_calls), Value::number(stream_.load_ms_median, "%.4f"),
             Value::number(stream_.load_ms_max, "%.3f")});
    return out;
  }

  Records check_records() const {
    Records out({{"check", "check", "", -52},
                 {"value", "value", "", 10},
                 {"expected", "expected", "", -10}});
    const auto count = [&](const char* check, std::int64_t n, const char* expected) {
      out.add({Value::text(check), Value::count(n), Value::text(expected)});
    };
    const auto speed = [&](const char* check, double v, const char* expected) {
      out.add({Value::text(check), Value::number(v, "%.4f"), Value::text(expected)});
    };
    const auto sum = [&](auto of) {
      std::int64_t n = 0;
      for (const TerrainEdit& e : craters_.edits) n += of(e);
      return n;
    };
    const auto most = [&](auto of) {
      double v = 0;
      for (const TerrainEdit& e : craters_.edits) v = std::max(v, of(e));
      return v;
    };
    const double edits = std::max<std::size_t>(1, craters_.edits.size());
    count("crowd bodies (pushed ones included)", craters_.bodies, "");
    count("craters dug", static_cast<std::int64_t>(craters_.edits.size()), "");
    out.add({Value::text("triangles per crater: destroyed"),
             Value::number(sum([](const TerrainEdit& e) { return e.destroyed; }) / edits, "%.1f"),
             Value::text("")});
    out.add({Value::text("triangles per crater: created"),
             Value::number(sum([](const TerrainEdit& e) { return e.created; }) / edits, "%.1f"),
             Value::text("")});
    out.add({Value::text("triangles per crater: kept"),
             Value::number(sum([](const TerrainEdit& e) { return e.kept; }) / edits, "%.1f"),
             Value::text("")});
    count("body positions checked", craters_.checks, "");
    count("body centres found inside the ground", craters_.inside, "0");
    count("bodies ended below the level", craters_.below, "0");
    count("bodies ended in a crater (0.2 m below their rest)", craters_.fell_in, "");
    speed("deepest skin overlap with the ground (m)", craters_.deepest_overlap, "");
    count("resting bodies followed, 3 m or more from the edit",
          sum([](const TerrainEdit& e) { return e.far_bodies; }), "");
    speed("their largest vertical speed (m/s)",
          most([](const TerrainEdit& e) { return e.far_vertical_speed; }), "≤ 0.01");
    count("resting bodies followed, beside the crater nearer",
          sum([](const TerrainEdit& e) { return e.near_bodies; }), "");
    speed("their largest vertical speed (m/s)",
          most([](const TerrainEdit& e) { return e.near_vertical_speed; }), "");
    return out;
  }

  Records glide_records() const {
    Records out({{"level", "level", "", -10},
                 {"body", "body", "", -20},
                 {"max_off_ground_speed", "largest speed across the ground (m/s)", "", 9},
                 {"travel", "travel (of the free glide)", "", 9}});
    for (const experiments::TerrainGlide& g : stream_.glides) {
      out.add({Value::text(g.level), Value::text(g.body),
               Value::number(g.max_off_ground_speed, "%.4f"),
               Value::number(100 * g.travel, "%.2f%%")});
    }
    return out;
  }

  Records streaming_records() const {
    Records out({{"what", "in the world", "", -16},
                 {"largest", "largest", "", 8},
                 {"mean", "mean", "", 8},
                 {"per_loaded_chunk", "per loaded chunk", "", 8},
                 {"whole_level", "whole level (terrain's)", "", 8}});
    const auto row = [&](const char* what, int most, double mean, double whole) {
      out.add({Value::text(what), Value::count(most), Value::number(mean, "%.1f"),
               Value::number(mean / stream_.loaded_mean, "%.1f"), Value::number(whole, "%.0f")});
    };
    row("loaded chunks", stream_.loaded_max, stream_.loaded_mean, stream_.chunks);
    row("bodies", stream_.bodies_max, stream_.bodies_mean, stream_.chunks);
    row("fixtures", stream_.fixtures_max, stream_.fixtures_mean, stream_.triangles);
    row("proxies", stream_.proxies_max, stream_.proxies_mean, stream_.triangles);
    return out;
  }

  Records memory_records() const {
    Records out({{"ground", "ground", "", -36},
                 {"bodies", "bodies", "", 6},
                 {"fixtures", "fixtures", "", 7},
                 {"proxies", "proxies", "", 7},
                 {"box2d_bytes", "Box2D's bytes", "", 9},
                 {"own_bytes", "terrain's own bytes", "", 9},
                 {"bytes_per_m", "bytes per m", "", 7},
                 {"box2d_bytes_per_loaded_chunk", "Box2D's bytes per loaded chunk", "", 8},
                 {"own_bytes_per_chunk", "own bytes per chunk", "", 7}});
    const double none = std::numeric_limits<double>::quiet_NaN();
    for (const experiments::TerrainMemory& m : stream_.memory) {
      const bool terrain = m.loaded_chunks > 0;
      out.add({Value::text(m.ground), Value::number(m.bodies, "%.1f"),
               Value::number(m.fixtures, "%.0f"), Value::number(m.proxies, "%.0f"),
               Value::number(m.box2d_bytes, "%.0f"), Value::number(m.own_bytes, "%.0f"),
               Value::number((m.box2d_bytes + m.own_bytes) / stream_.boundary, "%.0f"),
               Value::number(terrain ? m.box2d_bytes / m.loaded_chunks : none, "%.0f"),
               Value::number(terrain ? m.own_bytes / stream_.chunks : none, "%.0f")});
    }
    return out;
  }

  experiments::TerrainTiming timing_;
  TerrainCraters craters_;
  TerrainStream stream_;
  std::string page_;
  std::string out_dir_;
  bool measured_ = false;
  bool skipped_ = false;
};

}  // namespace

std::unique_ptr<CompareSection> make_terrain_section() {
  return std::make_unique<TerrainSection>();
}

}  // namespace dyop::report
