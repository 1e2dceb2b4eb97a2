// `dyop compare`'s terrain section (report/compare_terrain.cpp, experiments/terrain_runs.hpp): in
// quick mode it runs and writes its tables, CSVs (with their columns) and viewer page; its crater
// scene leaves no body in the ground and bodies far from an edit still; bodies glide across the
// seams of a flat kilometre streamed around them, with only the chunks near them loaded; the
// recording's triangles come and go with the craters. No time is asserted.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "experiments/terrain_runs.hpp"
#include "program/compare_command.hpp"

namespace dyop::experiments {
namespace {

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

TEST(TerrainSection, QuickRunWritesItsTablesCsvsAndViewerPage) {
  if (!terrain_available()) GTEST_SKIP() << "built without dyop::box2d_outlines (GEOS)";
  const auto dir =
      std::filesystem::temp_directory_path() / ("dyop_terrain_test_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  CompareOptions options;
  options.quick = true;
  options.out_dir = dir.string();
  options.scenes = {"stack"};
  options.sections = {"terrain"};
  std::ostringstream out, err;
  ASSERT_EQ(cli::run_compare_command(options, out, err), 0) << err.str();
  EXPECT_NE(err.str().find("[terrain] craters under a crowd"), std::string::npos);
  EXPECT_NE(out.str().find("body centres found inside the ground"), std::string::npos);

  const std::vector<std::pair<const char*, const char*>> csvs = {
      {"terrain_edits.csv",
       "run,step,placement,x_m,y_m,radius_m,destroyed,created,kept,edit_ms,edit_cpu_ms,step_ms,"
       "step_cpu_ms,far_bodies,far_max_vertical_speed,near_bodies,near_max_vertical_speed"},
      {"terrain_timing.csv", "part,what,count,median_ms,largest_ms"},
      {"terrain_checks.csv", "check,value,expected"},
      {"terrain_glides.csv", "level,body,max_off_ground_speed,travel"},
      {"terrain_streaming.csv", "what,largest,mean,per_loaded_chunk,whole_level"},
      {"terrain_memory.csv",
       "ground,bodies,fixtures,proxies,box2d_bytes,own_bytes,bytes_per_m,"
       "box2d_bytes_per_loaded_chunk,own_bytes_per_chunk"}};
  const std::string report = read(dir / "report.md");
  EXPECT_NE(report.find("## A terrain edited and streamed while it is played"), std::string::npos);
  for (const auto& [file, header] : csvs) {
    const std::string csv = read(dir / file);
    EXPECT_EQ(first_line(csv), header) << file;
    EXPECT_GT(std::count(csv.begin(), csv.end(), '\n'), 1) << file << ": no record";
    EXPECT_NE(report.find(std::string("`") + file + "`"), std::string::npos) << file;
  }
  const std::string edits = read(dir / "terrain_edits.csv");
  EXPECT_EQ(std::count(edits.begin(), edits.end(), '\n'), terrain_timing(true).craters() + 1);
  const std::string glides = read(dir / "terrain_glides.csv");
  EXPECT_EQ(std::count(glides.begin(), glides.end(), '\n'), 2 * 4 + 1) << "two levels, 4 bodies";
  const std::string memory = read(dir / "terrain_memory.csv");
  for (const char* ground : {"b2ChainShape loop", "add_outline", "streamed (mean)"}) {
    EXPECT_NE(memory.find(ground), std::string::npos) << ground;
  }
  const std::string page = "view_terrain-craters.html";
  EXPECT_GT(std::filesystem::file_size(dir / page), 10000u);
  EXPECT_NE(report.find("](" + page + ")"), std::string::npos);
  if (!HasFailure()) std::filesystem::remove_all(dir);  // kept to look at when something failed
}

// Craters dug under, beside and ahead of the crowd for 5 s: no body's centre ever inside the
// ground or below the level, some fall into craters, and the resting bodies 3 m or more from an
// edit feel at most 0.01 m/s of vertical speed from it.
TEST(TerrainRuns, CratersLeaveNoBodyInTheGroundAndFarBodiesStill) {
  if (!terrain_available()) GTEST_SKIP() << "built without dyop::box2d_outlines (GEOS)";
  TerrainTiming timing = terrain_timing(true, 300);
  const TerrainCraters c = run_terrain_craters(timing, box2d::Config{}, 0);
  ASSERT_EQ(static_cast<int>(c.edits.size()), timing.craters());
  EXPECT_EQ(c.checks, static_cast<std::int64_t>(c.bodies) * timing.crater_steps);
  EXPECT_EQ(c.inside, 0);
  EXPECT_EQ(c.below, 0);
  EXPECT_GT(c.fell_in, 0) << "bodies over the craters fall in";
  EXPECT_EQ(c.plain_step_ms.size() + c.edits.size(), static_cast<std::size_t>(timing.crater_steps));
  int far = 0;
  for (const TerrainEdit& e : c.edits) {
    EXPECT_GT(e.created, 0) << "step " << e.step;
    EXPECT_GE(e.radius, 1.0f);
    EXPECT_LE(e.far_vertical_speed, 0.01) << "step " << e.step << ", " << e.placement;
    far += e.far_bodies;
  }
  EXPECT_GT(far, 100) << "resting bodies followed far from the edits";
}

// Each everyday body on the flat kilometre (its top a side between two rows of chunks), 80 m
// streamed around it: it glides across the seams, and the world holds a few chunks' bodies,
// fixtures and proxies, never the level's.
TEST(TerrainRuns, BodiesGlideAcrossTheSeamsOfAStreamedLevelThatKeepsAFewChunks) {
  if (!terrain_available()) GTEST_SKIP() << "built without dyop::box2d_outlines (GEOS)";
  const TerrainStream s = run_terrain_stream(terrain_timing(true, 1200), box2d::Config{});
  ASSERT_EQ(s.glides.size(), 8u);
  for (const TerrainGlide& g : s.glides) {
    if (g.level != "flat") continue;
    EXPECT_LE(g.max_off_ground_speed, 0.01) << g.body;
    EXPECT_GE(g.travel, 0.99) << g.body;
  }
  EXPECT_GT(s.loaded_max, 0);
  EXPECT_LE(s.loaded_max, 12) << "a 44 × 36 m region overlaps at most 4 × 3 chunks";
  EXPECT_LE(s.bodies_max, s.loaded_max + 1);
  EXPECT_EQ(s.proxies_max, s.fixtures_max) << "a proxy per triangle and per body fixture";
  EXPECT_LT(s.fixtures_max, s.triangles / 10);
  ASSERT_EQ(s.memory.size(), 5u);
  EXPECT_LT(s.memory[3].box2d_bytes, s.memory[2].box2d_bytes / 10)
      << "streamed against every chunk loaded";
}

// The crater scene recorded both ways for the viewer: craters dug at steps 0, 15 and 30 end
// triangles and make new ones; every contact of a frame names fixtures there at that frame.
TEST(TerrainRuns, TheRecordingsTrianglesComeAndGoWithTheCraters) {
  if (!terrain_available()) GTEST_SKIP() << "built without dyop::box2d_outlines (GEOS)";
  const LockstepRecording r = record_terrain_craters(
      {std::nullopt, box2d::Backend::Dyop}, 40, {box2d::Config::all(), box2d::Config::all()}, 0);
  EXPECT_EQ(r.scene, "terrain-craters");
  int appeared = 0, ended = 0;
  for (const ViewFixture& f : r.fixtures) {
    EXPECT_EQ(f.side, -1) << "one world both ways";
    appeared += f.appears > 0;
    ended += f.disappears >= 0;
    if (f.disappears >= 0) {
      EXPECT_LE(f.appears, f.disappears);  // an edit before the first step: in no frame
    }
  }
  EXPECT_GT(appeared, 0);
  EXPECT_GT(ended, 0);
  for (int k = 0; k < 2; ++k) {
    ASSERT_EQ(r.frames[k].size(), 40u);
    for (int step = 0; step < 40; ++step) {
      for (const ViewContact& c : r.frames[k][static_cast<std::size_t>(step)].contacts) {
        for (const int i : {c.fixture_a, c.fixture_b}) {
          const ViewFixture& f = r.fixtures[static_cast<std::size_t>(i)];
          EXPECT_TRUE(f.appears <= step && (f.disappears < 0 || step < f.disappears))
              << "runner " << k << ", step " << step << ", fixture " << i;
        }
      }
    }
  }
}

}  // namespace
}  // namespace dyop::experiments
