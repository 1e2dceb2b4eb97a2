// `dyop compare`'s grounds section: each level built as Box2D's chain loops and as two-sided
// edges, each under Box2D's own contact and under the plug-in, and through the plug-in's builders,
// side by side (`experiments/ground_comparison.hpp`): the ground's size and build time, everyday
// bodies gliding, boxes started inside or thrown at it, a crowd's narrow phase and step in wall
// time, and a viewer page per level (`view_grounds-<level>.html`: the glides and the boxes started
// inside, the chain's world under Box2D's own contact beside the builders').
#include <array>
#include <sstream>
#include <stdexcept>

#include "experiments/ground_comparison.hpp"
#include "experiments/progress.hpp"
#include "report/compare_section.hpp"
#include "report/compare_summary.hpp"
#include "report/format.hpp"
#include "report/records.hpp"
#include "report/viewer_page.hpp"

namespace dyop::report {
namespace {

using experiments::GroundLevel;
using experiments::GroundRun;

// Indices of `experiments::ground_ways`.
constexpr std::size_t kChainOwn = 0, kChainPlugin = 1, kEdgesOwn = 2, kEdgesPlugin = 3,
                      kBuilders = 4;
static_assert(experiments::ground_way_count == 5, "the ways the tables name");

// The placement trial the summary quotes: the one a one-sided chain cannot push out of.
constexpr const char* kSummaryTrial = "started 0.4 m inside (centre under the top)";

std::string level_label(GroundLevel level) {
  switch (level) {
    case GroundLevel::Flat:
      return "flat outline, 60 m";
    case GroundLevel::TileGrid:
      return "tile grid, 256 × 64 cells of 0.5 m";
    case GroundLevel::Outline:
      break;
  }
  return "outline with caves, 300 m";
}

class GroundsSection : public CompareSection {
 public:
  const char* section_name() const override { return "grounds"; }

  void run(const SectionContext& c) override {
    using experiments::detail::fixed;
    out_dir_ = c.options.out_dir;
    for (const GroundLevel level : experiments::ground_levels) {
      if (!experiments::builders_available(level)) {
        skipped_.push_back(level);
        continue;
      }
      const double start = c.elapsed();
      const experiments::GroundTiming t =
          experiments::ground_timing(level, c.options.quick, c.options.steps);
      std::ostringstream page;
      write_viewer_page(experiments::record_ground(level, {std::nullopt, box2d::Backend::Dyop},
                                                   experiments::ground_recording_steps,
                                                   {c.options.skips, c.options.skips}),
                        page);
      parts_.push_back(
          {level, experiments::compare_ground(level, t, c.options.skips), t, page.str()});
      c.progress << "[grounds] " << experiments::name(level)
                 << ", chain and edges each way, builders, crowd of " << t.bodies << " for "
                 << t.steps << " steps × " << t.runs
                 << " alternating runs: " << fixed(c.elapsed() - start, 2) << " s (total "
                 << fixed(c.elapsed(), 1) << " s)\n"
                 << std::flush;
    }
  }

  bool measured() const override { return !parts_.empty(); }

  void write_tables(std::ostream& out) const override {
    out << "\nGrounds built as Box2D's chains and two-sided edges (each under Box2D's own contact "
           "and the plug-in) and by the plug-in's builders, the same bodies on each:\n\n";
    tables(out);
    out << "\nViewer pages (the level as chains under Box2D's own contact, A, beside the "
           "builders' under the plug-in, B; open in a browser):\n";
    for (const Part& p : parts_) {
      out << "  " << out_dir_ << '/' << page_file(p.level) << "  ("
          << fmt("%.1f", double(p.page.size()) / 1e6) << " MB)\n";
    }
  }

  void write_files(ReportDirectory& dir, Charts&) const override {
    for (const Part& p : parts_) {
      dir.write(page_file(p.level), [&](std::ostream& o) { o << p.page; });
    }
    dir.write("grounds.csv", [&](std::ostream& o) { ground_records().write_csv(o); });
    dir.write("grounds_glides.csv", [&](std::ostream& o) { glide_records().write_csv(o); });
    dir.write("grounds_placements.csv", [&](std::ostream& o) { placement_records().write_csv(o); });
  }

  void write_markdown(std::ostream& o, const Charts&) const override {
    o << "## Grounds as users build them: chains, edges, the builders\n\n"
      << "Box2D's own remedy for ghost collisions is the chain: one-sided loops (since 2.4.0) "
         "with ghost vertices, hollow; most of its testbed stands on two-sided edges laid end to "
         "end. Each level is built from what a user has five ways: as `b2ChainShape` loops (the "
         "outline's rings; a tile grid's solid cells traced into loops, straight runs merged) and "
         "as two-sided `b2EdgeShape` segments along the same loops, each under Box2D's own contact "
         "(the plug-in not installed) and under the plug-in (`dyop`, installed by its two lines: "
         "no edge data fixed); and by the plug-in's builders (`dyop::box2d::add_outline` with its "
         "defaults, `dyop::box2d::TileGround` with chunks of 16 × 16 cells) under the plug-in. "
         "Levels: a flat 60 m outline with a vertex every 0.25 m; a 256 × 64 tile grid of 0.5 m "
         "cells with hills and eight caves; a 300 m outline with hills, ten caves and an "
         "overhang. Each has a flat stretch on top where bodies glide and are placed.\n\n"
      << "- **per metre**: per metre of the level's boundary (every loop); **bytes**: fixtures, "
         "shapes, chain vertices, broad-phase proxies and tree nodes (the plug-in's edge data "
         "lives in the shapes' spare vertex slots).\n"
      << "- **build**: making the ground's fixtures (median over every world built; a tile grid's "
         "chain includes tracing its loops); **refresh**: a cell dug (`TileGround::set_cell` "
         "builds its chunk again; the chain traces and makes every loop again) or, for outlines, "
         "the whole level made again.\n"
      << "- **crowd**: boxes, hexagons, balls and boxes of two triangles (friction 0.6) dropped "
         "along the level (sleeping off, as every world of this report); narrow phase "
         "(`b2Profile::collide`) and step summed over the steps, "
         "median of runs alternating between the five ways in one process; × own: over the same "
         "ground under Box2D's own contact (the builders': over the chain's).\n"
      << "- **glides**: each body pushed at 4 m/s for 4 s, frictionless: largest vertical speed "
         "after the first step and distance over 16 m (a glide: 0 m/s, 100 %).\n"
      << "- **placements**: 10 boxes (`SetAsBox` 0.25 × 0.3 m, friction 0.6) started inside the "
         "ground or thrown down at it from 5 m, 3 s: how many end with their centre above the "
         "top.\n\n";
    tables(o);
    o << "\nStep by step in a browser (`dyop view grounds-<level>`: the glides' bodies and the "
         "boxes started 0.4 m inside, 4 s, the chain's world under Box2D's own contact as A beside "
         "the builders' as B):";
    for (const Part& p : parts_) {
      o << " [" << experiments::name(p.level) << "](" << page_file(p.level) << ")";
    }
    o << ".\n";
    for (const GroundLevel level : skipped_) {
      o << "\n*Level `" << experiments::name(level)
        << "` not run: this build has no `dyop::box2d_outlines` (GEOS not found).*\n";
    }
    o << '\n';
  }

  void summarize(SummaryFigures& figures) const override {
    for (const Part& p : parts_) {
      const auto& r = p.runs;
      GroundFigures g;
      g.level = level_label(p.level);
      for (std::size_t k = 0; k < r[kChainOwn].glides.size(); ++k) {
        g.chain_vertical_speed =
            std::max(g.chain_vertical_speed, r[kChainOwn].glides[k].max_vertical_speed);
        g.chain_plugin_vertical_speed =
            std::max(g.chain_plugin_vertical_speed, r[kChainPlugin].glides[k].max_vertical_speed);
        g.builders_vertical_speed =
            std::max(g.builders_vertical_speed, r[kBuilders].glides[k].max_vertical_speed);
      }
      for (std::size_t k = 0; k < r[kChainOwn].placements.size(); ++k) {
        if (r[kChainOwn].placements[k].trial != kSummaryTrial) continue;
        g.boxes = r[kChainOwn].placements[k].boxes;
        g.chain_on_top = r[kChainOwn].placements[k].on_top;
        g.builders_on_top = r[kBuilders].placements[k].on_top;
      }
      g.chain_narrowphase_ratio = r[kChainPlugin].narrow_ms / r[kChainOwn].narrow_ms;
      g.chain_step_ratio = r[kChainPlugin].step_ms / r[kChainOwn].step_ms;
      g.edges_narrowphase_ratio = r[kEdgesPlugin].narrow_ms / r[kEdgesOwn].narrow_ms;
      g.edges_step_ratio = r[kEdgesPlugin].step_ms / r[kEdgesOwn].step_ms;
      g.narrowphase_ratio = r[kBuilders].narrow_ms / r[kChainOwn].narrow_ms;
      g.step_ratio = r[kBuilders].step_ms / r[kChainOwn].step_ms;
      figures.grounds.push_back(g);
    }
    figures.viewer_pages = figures.viewer_pages || !parts_.empty();
  }

  std::string files() const override {
    return "`grounds.csv` (each level's ground every way: size, build, crowd), "
           "`grounds_glides.csv`, `grounds_placements.csv`, `view_grounds-<level>.html` (viewer "
           "pages: chains against builders)";
  }

  void problems(std::vector<std::string>& lines) const override {
    for (const GroundLevel level : skipped_) {
      lines.push_back(std::string("grounds: level ") + experiments::name(level) +
                      " not run (no dyop::box2d_outlines: GEOS not found at configure time)");
    }
  }

 private:
  struct Part {
    GroundLevel level;
    std::array<GroundRun, experiments::ground_way_count> runs;  // `experiments::ground_ways`
    experiments::GroundTiming timing;
    std::string page;  // the level's viewer page (`record_ground`)
  };

  static std::string page_file(GroundLevel level) {
    return viewer_page_file(experiments::ground_recording_name(level));
  }

  void tables(std::ostream& out) const {
    Records grounds = ground_records(true);
    grounds.write_markdown(out);
    const auto header = [&](const char* first, const char* what) {
      out << "\n| level | " << first << " |";
      for (const experiments::GroundWay& w : experiments::ground_ways) {
        out << ' ' << experiments::name(w) << ": " << what << " |";
      }
      out << "\n|---|---|";
      for (std::size_t k = 0; k < experiments::ground_ways.size(); ++k) out << "--:|";
      out << '\n';
    };
    header("body", "vertical speed, travel");
    for (const Part& p : parts_) {
      for (std::size_t k = 0; k < p.runs[0].glides.size(); ++k) {
        out << "| " << experiments::name(p.level) << " | " << p.runs[0].glides[k].body << " |";
        for (const GroundRun& r : p.runs) {
          out << ' ' << fmt("%.3f", r.glides[k].max_vertical_speed) << " m/s, "
              << fmt("%.1f", 100 * r.glides[k].travel) << " % |";
        }
        out << '\n';
      }
    }
    header("boxes", "on top");
    for (const Part& p : parts_) {
      for (std::size_t k = 0; k < p.runs[0].placements.size(); ++k) {
        out << "| " << experiments::name(p.level) << " | " << p.runs[0].placements[k].trial << " |";
        for (const GroundRun& r : p.runs) {
          out << ' ' << r.placements[k].on_top << " of " << r.placements[k].boxes << " |";
        }
        out << '\n';
      }
    }
  }

  // The run a ratio of `r` is taken over: the same ground under Box2D's own contact (the
  // builders': the chain's).
  static const GroundRun& reference_of(const Part& p, const GroundRun& r) {
    return r.way.build == experiments::GroundBuild::Edges ? p.runs[kEdgesOwn] : p.runs[kChainOwn];
  }

  // One row per level and build; `ratios`: with the crowd's figures over the chain's.
  Records ground_records(bool ratios = false) const {
    std::vector<Column> columns = {{"level", "level", "", -10},
                                   {"build", "built as, answered by", "", -20},
                                   {"boundary_m", "boundary (m)", "", 8},
                                   {"fixtures", "fixtures", "", 7},
                                   {"proxies_per_m", "proxies per m", "", 7},
                                   {"bytes_per_m", "bytes per m", "", 7},
                                   {"build_ms", "build (ms)", "", 8},
                                   {"refresh_ms", "refresh (ms)", "", 8},
                                   {"crowd_bodies", "crowd", "", 6},
                                   {"crowd_steps", "steps", "", 6},
                                   {"runs", "runs", "", 4},
                                   {"narrowphase_ms", "narrow phase (ms)", "", 8},
                                   {"step_ms", "step (ms)", "", 8}};
    if (ratios) {
      columns.push_back({"narrowphase_ratio", "narrow phase × own", "", 6});
      columns.push_back({"step_ratio", "step × own", "", 6});
    }
    Records out(columns);
    for (const Part& p : parts_) {
      for (const GroundRun& r : p.runs) {
        std::vector<Value> row = {Value::text(experiments::name(r.level)),
                                  Value::text(experiments::name(r.way)),
                                  Value::number(r.boundary, "%.1f"),
                                  Value::count(r.fixtures),
                                  Value::number(r.proxies / r.boundary, "%.2f"),
                                  Value::number(r.bytes / r.boundary, "%.0f"),
                                  Value::number(r.build_ms, "%.2f"),
                                  Value::number(r.refresh_ms, "%.2f"),
                                  Value::count(p.timing.bodies),
                                  Value::count(p.timing.steps),
                                  Value::count(p.timing.runs),
                                  Value::number(r.narrow_ms, "%.1f"),
                                  Value::number(r.step_ms, "%.1f")};
        if (ratios) {
          row.push_back(Value::number(r.narrow_ms / reference_of(p, r).narrow_ms, "%.2f"));
          row.push_back(Value::number(r.step_ms / reference_of(p, r).step_ms, "%.2f"));
        }
        out.add(std::move(row));
      }
    }
    return out;
  }

  Records glide_records() const {
    Records out({{"level", "", "", -10},
                 {"build", "", "", -20},
                 {"body", "", "", -20},
                 {"max_vertical_speed", "", "", 9},
                 {"travel", "", "", 9}});
    for (const Part& p : parts_) {
      for (const GroundRun& r : p.runs) {
        for (const experiments::GroundGlide& g : r.glides) {
          out.add({Value::text(experiments::name(r.level)), Value::text(experiments::name(r.way)),
                   Value::text(g.body), Value::number(g.max_vertical_speed, "%.4f"),
                   Value::number(g.travel, "%.4f")});
        }
      }
    }
    return out;
  }

  Records placement_records() const {
    Records out({{"level", "", "", -10},
                 {"build", "", "", -20},
                 {"trial", "", "", -40},
                 {"on_top", "", "", 6},
                 {"boxes", "", "", 6}});
    for (const Part& p : parts_) {
      for (const GroundRun& r : p.runs) {
        for (const experiments::GroundPlacement& t : r.placements) {
          out.add({Value::text(experiments::name(r.level)), Value::text(experiments::name(r.way)),
                   Value::text(t.trial), Value::count(t.on_top), Value::count(t.boxes)});
        }
      }
    }
    return out;
  }

  std::vector<Part> parts_;
  std::vector<GroundLevel> skipped_;
  std::string out_dir_;
};

}  // namespace

std::unique_ptr<CompareSection> make_grounds_section() {
  return std::make_unique<GroundsSection>();
}

}  // namespace dyop::report
