// `dyop compare`'s viewer section: every scene selected recorded under Box2D's own contact and
// the plug-in's `dyop` (`experiments/lockstep_recording.hpp`), each written as a `dyop view` page
// (`view_<scene>.html`) that report.md links.
#include <array>
#include <sstream>
#include <string>
#include <vector>

#include "experiments/compare.hpp"
#include "experiments/lockstep_recording.hpp"
#include "report/compare_section.hpp"
#include "report/compare_summary.hpp"
#include "report/format.hpp"
#include "report/viewer_page.hpp"

namespace dyop::report {
namespace {

// One scene's page, written as soon as it is recorded (a recording of a large scene holds
// every contact of every step), and what the tables say about it.
struct ViewerPage {
  std::string scene;
  int steps = 0;
  std::string html;
  std::array<int, 2> touching{}, agreeing{}, marked{};  ///< at the last step, own then dyop
};

class ViewerSection : public CompareSection {
 public:
  const char* section_name() const override { return "viewer"; }

  void run(const SectionContext& c) override {
    out_dir_ = c.options.out_dir;
    for (const scenes::SceneInfo* s : c.scenes) {
      if (c.options.quick && experiments::left_out_of_quick_sections(s->name)) continue;
      const double start = c.elapsed();
      const experiments::LockstepRecording r =
          experiments::record_lockstep(s->name, {std::nullopt, box2d::Backend::Dyop}, c.steps(*s),
                                       c.options.seed, {c.options.skips, c.options.skips});
      ViewerPage page{s->name, r.steps, {}, {}, {}, {}};
      std::ostringstream html;
      write_viewer_page(r, html);
      page.html = html.str();
      for (int k = 0; k < 2; ++k) {
        const experiments::ViewFrame& f = r.frames[k].back();
        page.touching[k] = f.touching;
        page.agreeing[k] = f.agreeing;
        for (const experiments::ViewContact& v : f.contacts) {
          page.marked[k] += v.mark != experiments::EdgeMark::None;
        }
      }
      pages_.push_back(std::move(page));
      c.progress << "[viewer] " << s->name << ", " << r.steps
                 << " steps: " << fmt("%.2f", c.elapsed() - start) << " s (total "
                 << fmt("%.1f", c.elapsed()) << " s)\n"
                 << std::flush;
    }
  }

  bool measured() const override { return !pages_.empty(); }

  void write_tables(std::ostream& out) const override {
    out << "\nViewer pages (Box2D's own contact against dyop, step by step; open in a browser):\n";
    for (const ViewerPage& p : pages_) {
      out << "  " << out_dir_ << '/' << viewer_page_file(p.scene) << "  (" << p.steps << " steps, "
          << fmt("%.1f", double(p.html.size()) / 1e6) << " MB)\n";
    }
  }

  void write_files(ReportDirectory& dir, Charts&) const override {
    for (const ViewerPage& p : pages_) {
      dir.write(viewer_page_file(p.scene), [&](std::ostream& o) { o << p.html; });
    }
  }

  void write_markdown(std::ostream& o, const Charts&) const override {
    o << "## Viewer: Box2D's own contact and the plug-in side by side\n\n"
      << "Each scene recorded under Box2D's own contact (blue) and the plug-in's `dyop` (orange), "
         "same seed and steps, in one self-contained page (`dyop view`; no network): play, step, "
         "scrub, zoom and pan, the two worlds side by side or overlaid, contact points coloured "
         "by whether both runners have the pair within "
      << fmt("%g", experiments::agreement_tolerance * 1000)
      << " mm, the plug-in's differences from `b2CollidePolygons` on the same pose (the "
         "internal-edge rule) in magenta, a click on a contact for its numbers, and plots of the "
         "narrow phase's time, the contacts and the largest penetration per step. At the last "
         "step:\n\n"
      << "| scene | steps | page | contacts own / dyop | agreeing | dyop's marked |\n"
      << "|---|--:|--:|--:|--:|--:|\n";
    for (const ViewerPage& p : pages_) {
      o << "| [" << p.scene << "](" << viewer_page_file(p.scene) << ") | " << p.steps << " | "
        << fmt("%.2f", double(p.html.size()) / 1e6) << " MB | " << p.touching[0] << " / "
        << p.touching[1] << " | " << p.agreeing[0] << " | " << p.marked[1] << " |\n";
    }
    o << '\n';
  }

  std::string files() const override {
    return "`view_<scene>.html` (viewer pages: Box2D's own contact against dyop)";
  }

  void summarize(SummaryFigures& figures) const override { figures.viewer_pages = true; }

 private:
  std::string out_dir_;
  std::vector<ViewerPage> pages_;
};

}  // namespace

std::unique_ptr<CompareSection> make_viewer_section() { return std::make_unique<ViewerSection>(); }

}  // namespace dyop::report
