// `dyop compare`'s sections: the one list of them, and the whole run (the main table, then each
// section). A new section is a file of its own and one line here.
#include <algorithm>
#include <chrono>

#include "report/compare_in_world.hpp"
#include "report/compare_section.hpp"

namespace dyop::report {

// Each section's file defines its factory.
std::unique_ptr<CompareSection> make_slide_section();
std::unique_ptr<CompareSection> make_skip_section();
std::unique_ptr<CompareSection> make_paper_section();
std::unique_ptr<CompareSection> make_thread_section();
std::unique_ptr<CompareSection> make_recycling_section();
std::unique_ptr<CompareSection> make_viewer_section();
std::unique_ptr<CompareSection> make_grounds_section();
std::unique_ptr<CompareSection> make_terrain_section();

std::vector<std::unique_ptr<CompareSection>> make_compare_sections() {
  std::vector<std::unique_ptr<CompareSection>> sections;
  sections.push_back(std::make_unique<InWorldSection>());
  sections.push_back(make_slide_section());
  sections.push_back(make_grounds_section());
  sections.push_back(make_terrain_section());
  sections.push_back(make_skip_section());
  sections.push_back(make_paper_section());
  sections.push_back(make_thread_section());
  sections.push_back(make_recycling_section());
  sections.push_back(make_viewer_section());
  return sections;
}

std::vector<std::string> compare_section_names() {
  std::vector<std::string> names;
  for (const auto& s : make_compare_sections()) names.emplace_back(s->section_name());
  return names;
}

bool SectionContext::selected(const std::string& name) const {
  return std::any_of(scenes.begin(), scenes.end(),
                     [&](const scenes::SceneInfo* s) { return name == s->name; });
}

void Charts::draw(ReportDirectory& dir, const std::string& name, const std::string& terminal,
                  const std::string& script) {
  if (dir.chart(name, terminal, script)) drawn_.push_back(name);
}

void Charts::image(std::ostream& o, const std::string& name, const std::string& alt) const {
  if (std::find(drawn_.begin(), drawn_.end(), name) != drawn_.end()) {
    o << "![" << alt << "](" << name << ".svg)\n\n";
  } else {
    o << "*Chart `" << name << ".svg` not drawn (see Problems); its data is in the CSV files.*\n\n";
  }
}

Comparison run_comparison(const experiments::CompareOptions& options, std::ostream& progress) {
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  Comparison c;
  c.main = experiments::run_compare(options, progress, elapsed);
  const std::vector<const scenes::SceneInfo*> scenes = experiments::selected_scenes(options);
  const SectionContext context{options, scenes, progress, elapsed};
  c.sections = make_compare_sections();
  const std::vector<std::string>& only = options.sections;
  for (const auto& s : c.sections) {
    const bool runs = only.empty()
                          ? !options.quick || s->in_quick_run()
                          : std::find(only.begin(), only.end(), s->section_name()) != only.end();
    if (runs) {
      s->run(context);
    }
  }
  c.seconds = elapsed();
  return c;
}

}  // namespace dyop::report
