// `dyop scene`, `dyop compare` and `dyop view` as a user runs them: the program itself, with its
// exit status.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace {

struct Outcome {
  int status = -1;  // the program's exit status
  std::string out;  // standard output (standard error goes to `err`)
  std::string err;
};

// A fresh directory per test process: ctest runs the tests of this file in parallel.
std::filesystem::path temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("dyop_scene_cli_" + std::to_string(getpid()) + "_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

Outcome run(const std::string& args) {
  const std::string err_file = (temp_dir("stderr") / "err.txt").string();
  const std::string command = std::string(DYOP_PROGRAM) + " " + args + " 2>" + err_file;
  Outcome r;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return r;
  std::array<char, 4096> buf;
  for (std::size_t n; (n = fread(buf.data(), 1, buf.size(), pipe)) > 0;)
    r.out.append(buf.data(), n);
  const int status = pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(err_file);
  r.err.assign(std::istreambuf_iterator<char>(err), {});
  return r;
}

TEST(SceneCli, UnknownSceneOrRunnerIsAUsageError) {
  const Outcome scene = run("scene nope --runner dyop");
  EXPECT_EQ(scene.status, 1);
  EXPECT_NE(scene.err.find("nope"), std::string::npos) << scene.err;
  const Outcome backend = run("scene pyramid --runner nope");
  EXPECT_EQ(backend.status, 1);
  EXPECT_NE(backend.err.find("nope"), std::string::npos) << backend.err;
  EXPECT_EQ(run("scene pyramid").status, 1) << "--runner is required";
  EXPECT_EQ(run("scene pyramid --runner dyop --steps 0").status, 1);
  EXPECT_EQ(run("scene pyramid --runner dyop --json - --svg -").status, 1);
  EXPECT_EQ(run("compare --scene nope").status, 1);
}

TEST(SceneCli, CompareRunsTheNamedBackendsAloneAndRefusesAnUnknownOne) {
  const std::string dir = temp_dir("compare_backend").string();
  const Outcome r =
      run("compare --scene stack --steps 20 --section in-world --backend sat --out " + dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("| stack | sat | 20 |"), std::string::npos) << r.out;
  for (const char* other : {"| stack | dyop |", "| stack | box2d |", "| stack | epa |"}) {
    EXPECT_EQ(r.out.find(other), std::string::npos) << other << " was not named";
  }
  const Outcome unknown = run("compare --scene stack --backend nope --out " + dir);
  EXPECT_EQ(unknown.status, 1);
  EXPECT_NE(unknown.err.find("nope"), std::string::npos) << unknown.err;
}

TEST(SceneCli, FallingSizesTheRainsOnly) {
  const Outcome rain = run("scene rain-tall --runner dyop --steps 2 --falling 60 --json -");
  ASSERT_EQ(rain.status, 0) << rain.err;
  const nlohmann::json j = nlohmann::json::parse(rain.out);
  EXPECT_EQ(j["bodies"], 61) << "60 falling triangles and the bin";
  EXPECT_EQ(run("scene stack --runner dyop --steps 2 --falling 60").status, 1);
  EXPECT_EQ(run("scene rain --runner dyop --steps 2 --falling 0").status, 1);
}

TEST(SceneCli, SkipTakesAllNoneOrAListAndAnUnknownNameIsAUsageError) {
  const Outcome list = run("scene rain --runner dyop --steps 3 --skip warm-axis,bounds --json -");
  ASSERT_EQ(list.status, 0) << list.err;
  const nlohmann::json j = nlohmann::json::parse(list.out);
  EXPECT_EQ(j["skip_config"], nlohmann::json::array({"bounds", "warm-axis"}));
  ASSERT_TRUE(j["skips"].is_object());
  EXPECT_TRUE(j["skips"].contains("warm-axis"));
  EXPECT_NE(list.err.find("skips bounds,warm-axis"), std::string::npos) << list.err;
  EXPECT_EQ(run("scene stack --runner sat --steps 2 --skip none").status, 0);
  EXPECT_EQ(run("scene paper --runner dyop --steps 2 --skip all").status, 0)
      << "accepted, and ignored: no Box2D world";
  for (const std::string command : {"scene stack --runner dyop --steps 2 --skip bounds,nope",
                                    "compare --quick --steps 1 --skip nope"}) {
    const Outcome bad = run(command);
    EXPECT_EQ(bad.status, 1) << command;
    EXPECT_NE(bad.err.find("nope"), std::string::npos) << bad.err;
  }
}

// The rule switch: off keeps the ghost collisions, so the slide's world differs, and says so.
TEST(SceneCli, InternalEdgesTakesOnOrOffAndOffChangesTheSlide) {
  const auto hash = [](const Outcome& o) { return nlohmann::json::parse(o.out)["hash"]; };
  const Outcome on = run("scene slide --runner dyop --steps 60 --json -");
  const Outcome off = run("scene slide --runner dyop --steps 60 --internal-edges off --json -");
  ASSERT_EQ(on.status, 0) << on.err;
  ASSERT_EQ(off.status, 0) << off.err;
  EXPECT_NE(hash(on), hash(off));
  EXPECT_NE(off.err.find("internal edges: off"), std::string::npos) << off.err;
  EXPECT_EQ(on.err.find("internal edges: off"), std::string::npos) << on.err;
  EXPECT_EQ(hash(run("scene slide --runner dyop --steps 60 --internal-edges on --json -")),
            hash(on));
  EXPECT_EQ(run("scene slide --runner dyop --internal-edges maybe").status, 1);
}

// The spawner far away (`--spawn-far`), for both runners: the pyramid's world keeps about as many
// manifolds as without it, and Box2D's own contact runs it too.
TEST(SceneCli, SpawnFarRunsEitherRunnerAndThePyramidKeepsItsManifolds) {
  const auto kept = [](const Outcome& o) {
    return nlohmann::json::parse(o.out)["recycled"].get<double>();
  };
  const Outcome with = run("scene pyramid --runner dyop --steps 60 --spawn-far --json -");
  const Outcome without = run("scene pyramid --runner dyop --steps 60 --json -");
  ASSERT_EQ(with.status, 0) << with.err;
  ASSERT_EQ(without.status, 0) << without.err;
  EXPECT_GT(kept(without), 0.0);
  EXPECT_GT(kept(with), 0.9 * kept(without));
  EXPECT_EQ(run("scene pyramid --runner box2d-own --steps 60 --spawn-far").status, 0);
}

TEST(SceneCli, Box2DsOwnContactRunsBox2DScenesWithoutPlugInCounters) {
  const Outcome own = run("scene stack --runner box2d-own --steps 30 --json -");
  ASSERT_EQ(own.status, 0) << own.err;
  const nlohmann::json j = nlohmann::json::parse(own.out);
  EXPECT_EQ(j["runner"], "box2d-own");
  EXPECT_TRUE(j["plugin_evaluations"].is_null());
  EXPECT_TRUE(j["skips"].is_null());
  const Outcome paper = run("scene paper --runner box2d-own --steps 2");
  EXPECT_EQ(paper.status, 1) << "no Box2D world to leave the plug-in out of";
  EXPECT_NE(paper.err.find("paper"), std::string::npos) << paper.err;
}

TEST(SceneCli, UnwritableOutputIsAnIoError) {
  // A regular file where a directory should be: unwritable even for root.
  const auto dir = temp_dir("unwritable");
  std::ofstream(dir / "file") << "x";
  const std::string bad = (dir / "file" / "out.json").string();
  const Outcome json = run("scene stack --runner dyop --steps 2 --json " + bad);
  EXPECT_EQ(json.status, 2);
  EXPECT_NE(json.err.find("cannot write"), std::string::npos) << json.err;
  EXPECT_EQ(run("scene stack --runner dyop --steps 2 --svg " + bad).status, 2);
  const Outcome compare =
      run("compare --quick --steps 1 --out " + (dir / "file" / "report").string());
  EXPECT_EQ(compare.status, 2);
  EXPECT_NE(compare.err.find("cannot write"), std::string::npos) << compare.err;
}

TEST(SceneCli, JsonToStandardOutputIsOneValidObjectAndTheSummaryGoesToStandardError) {
  const Outcome r = run("scene mixed --runner sat --steps 20 --seed 3 --json -");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["scene"], "mixed");
  EXPECT_EQ(j["runner"], "sat");
  EXPECT_EQ(j["seed"], 3);
  EXPECT_NE(r.err.find("scene mixed / sat"), std::string::npos) << r.err;
}

TEST(SceneCli, WritesTheSummaryAndTheFiles) {
  const auto dir = temp_dir("files");
  const Outcome r = run("scene paper --runner box2d --steps 10 --json " +
                        (dir / "m.json").string() + " --svg " + (dir / "s.svg").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("scene paper / box2d"), std::string::npos) << r.out;
  std::ifstream json(dir / "m.json");
  const nlohmann::json j = nlohmann::json::parse(json, nullptr, false);  // discarded if invalid
  EXPECT_FALSE(j.is_discarded());
  EXPECT_EQ(j["steps"], 10);
  std::ifstream svg(dir / "s.svg");
  const std::string text(std::istreambuf_iterator<char>(svg), {});
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("</svg>"), std::string::npos);
  std::size_t polygons = 0;
  for (std::size_t at = 0; (at = text.find("<polygon", at)) != std::string::npos; ++at) ++polygons;
  EXPECT_EQ(polygons, 10u) << "the ten triangles of the paper scene";
}

TEST(SceneCli, SvgToStandardOutput) {
  const Outcome r = run("scene stack --runner box2d --steps 2 --svg -");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("<?xml", 0), 0u);
  EXPECT_NE(r.out.find("<polygon"), std::string::npos);
}

TEST(ViewCli, WritesOnePageAndTheCountsItShows) {
  const auto dir = temp_dir("view");
  const std::string page = (dir / "deep" / "slide.html").string();
  const Outcome r =
      run("view slide --steps 5 --out " + page + " --json " + (dir / "slide.json").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("box2d-own"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("page: " + page), std::string::npos) << r.out;
  std::ifstream html(page);
  const std::string text(std::istreambuf_iterator<char>(html), {});
  EXPECT_EQ(text.rfind("<!DOCTYPE html>", 0), 0u);
  std::ifstream json(dir / "slide.json");
  const nlohmann::json j = nlohmann::json::parse(json, nullptr, false);
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["steps"], 5);
  EXPECT_EQ(j["runners"], nlohmann::json({"box2d-own", "dyop"}));
  EXPECT_EQ(j["frames"].size(), 5u);
}

TEST(ViewCli, TakesAnyTwoRunnersAndTheRuleSwitch) {
  const auto dir = temp_dir("view_runners");
  const Outcome r =
      run("view paper --steps 3 --runner sat --runner box2d-own --internal-edges "
          "off --out " +
          (dir / "p.html").string() + " --json -");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["runners"], nlohmann::json({"sat", "box2d-own"}));
  EXPECT_EQ(j["internal_edges"], nlohmann::json({false, false}));
  EXPECT_NE(r.err.find("page: "), std::string::npos) << "the summary goes to standard error";
}

TEST(ViewCli, SetsTheSameBackendAgainstItselfWithTwoSettings) {
  const auto dir = temp_dir("view_settings");
  const Outcome r =
      run("view slide --steps 3 --runner dyop --runner dyop --internal-edges on "
          "--internal-edges off --skip all --skip none --recycle 0.002 --out " +
          (dir / "s.html").string() + " --json -");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["internal_edges"], nlohmann::json({true, false}));
  EXPECT_EQ(j["skips"], nlohmann::json({"all", "none"}));
  EXPECT_NEAR(j["recycle_distance"][1].get<double>(), 0.002, 1e-9) << "once: both runners";
}

// A level of the grounds comparison is a view target: the chain's world as A, the builders' as
// B, their 240 steps by default.
TEST(ViewCli, ShowsAGroundsLevelAsChainAgainstBuilders) {
  const auto dir = temp_dir("view_grounds");
  const Outcome r =
      run("view grounds-tile-grid --steps 4 --out " + (dir / "g.html").string() + " --json -");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["scene"], "grounds-tile-grid");
  EXPECT_EQ(j["frames"].size(), 4u);
  EXPECT_EQ(run("view grounds-nowhere").status, 1);
}

TEST(ViewCli, BadArgumentsAreUsageErrorsAndAnUnwritablePageAnIoError) {
  EXPECT_EQ(run("view nope").status, 1);
  EXPECT_EQ(run("view slide --runner nope --runner dyop").status, 1);
  EXPECT_EQ(run("view slide --runner dyop").status, 1) << "two runners";
  EXPECT_EQ(run("view slide --steps 0").status, 1);
  EXPECT_EQ(run("view slide --internal-edges maybe").status, 1);
  EXPECT_EQ(run("view slide --skip all --skip all --skip all").status, 1);
  EXPECT_EQ(run("view slide --recycle -1").status, 1);
  EXPECT_EQ(run("view slide --steps 2 --out - --json -").status, 1);
  const auto dir = temp_dir("view_unwritable");
  std::ofstream(dir / "file") << "x";
  const Outcome bad = run("view slide --steps 2 --out " + (dir / "file" / "p.html").string());
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("cannot write"), std::string::npos) << bad.err;
}

}  // namespace
