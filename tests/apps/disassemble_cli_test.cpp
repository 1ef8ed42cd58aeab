// `swept disassemble` end to end: the JSON document, the path files, the same bytes at any
// --jobs, exit codes, and bad input that writes nothing.
#include "assembly/assembly_support.h"
#include "support/cli_support.h"
#include "support/test_support.h"
#include "swept/scenes/gearbox.h"
#include "swept/scenes/pin_in_bore.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace swept {
namespace {

namespace fs = std::filesystem;
using namespace swept::test;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(SWEPT_BINARY_DIR) / "tests_apps_scratch" / ("disassemble_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string bytes_of(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

// An assembly written as STL files plus a TOML file (the base fixed).
fs::path write_assembly(const fs::path& dir, const Assembly& a) {
  std::string toml;
  for (std::size_t i = 0; i < a.parts.size(); ++i) {
    const std::string file = a.parts[i].name + ".stl";
    EXPECT_TRUE(write_stl_binary(dir / file, a.parts[i].mesh).ok());
    toml += "[[part]]\nfile = \"" + file + "\"\n" + (i == 0 ? "fixed = true\n" : "");
  }
  std::ofstream(dir / "assembly.toml") << toml;
  return dir / "assembly.toml";
}

TEST(DisassembleCli, BoltedRingJsonAndPathFiles) {
  const fs::path dir = scratch("bolted");
  const fs::path toml = write_assembly(dir, bolted_ring());
  std::vector<std::string> docs, paths;
  for (int jobs : {1, 2}) {
    const fs::path out = dir / ("out" + std::to_string(jobs));
    const CliRun r = run_cli("disassemble " + toml.string() + " --json --jobs " + std::to_string(jobs) + " -o " +
                                 out.string(),
                             false);
    ASSERT_EQ(r.code, 0) << r.out;
    auto doc = nlohmann::json::parse(r.out);
    EXPECT_TRUE(doc["complete"].get<bool>());
    ASSERT_EQ(doc["parts"].size(), 3u);
    EXPECT_EQ(doc["parts"][0]["name"], "base");
    EXPECT_TRUE(doc["parts"][0]["fixed"].get<bool>());
    EXPECT_EQ(doc["parts"][2]["triangles"], 192);
    ASSERT_EQ(doc["sequence"].size(), 2u);
    EXPECT_EQ(doc["sequence"][0]["part"], "bolt");
    EXPECT_EQ(doc["sequence"][0]["status"], "removed");
    EXPECT_EQ(doc["sequence"][0]["direction"], nlohmann::json({0.0, 0.0, 1.0}));
    EXPECT_EQ(doc["sequence"][1]["part"], "ring");
    EXPECT_TRUE(doc["interferences"].empty());
    EXPECT_GT(doc["time_ms"]["total"].get<double>(), 0.0);
    const std::string path_file = doc["sequence"][0]["path"];
    EXPECT_EQ(path_file, "01-bolt.json");
    ASSERT_TRUE(fs::exists(out / path_file));
    auto path = read_path(out / path_file);
    ASSERT_TRUE(path.ok()) << path.error().message;
    ASSERT_EQ(path->poses.size(), 2u);
    EXPECT_NEAR(path->poses[1].translation.z(), doc["sequence"][0]["distance"].get<double>(), 1e-9);
    doc.erase("time_ms");  // the one thing that differs between runs
    docs.push_back(doc.dump());
    paths.push_back(bytes_of(out / "01-bolt.json") + bytes_of(out / "02-ring.json"));
  }
  EXPECT_EQ(docs[0], docs[1]);
  EXPECT_EQ(paths[0], paths[1]);
}

TEST(DisassembleCli, ViewPagePlaysTheWholeDisassembly) {
  const fs::path dir = scratch("view");
  const fs::path toml = write_assembly(dir, bolted_ring());
  const CliRun r = run_cli("disassemble " + toml.string() + " --view " + (dir / "view.html").string());
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string html = bytes_of(dir / "view.html");
  const auto begin = html.find("<script id=\"swept-data\" type=\"application/json\">");
  ASSERT_NE(begin, std::string::npos);
  const auto start = html.find('>', begin) + 1;
  const auto doc = nlohmann::json::parse(html.substr(start, html.find("</script>", start) - start));
  EXPECT_EQ(doc["format"], 2);
  ASSERT_EQ(doc["parts"].size(), 3u);
  EXPECT_EQ(doc["parts"][2]["name"], "bolt");
  EXPECT_EQ(doc["parts"][2]["mesh"]["triangles"], 192);
  ASSERT_EQ(doc["steps"].size(), 2u);
  EXPECT_EQ(doc["steps"][0]["parts"], nlohmann::json({2}));  // the bolt first, then the ring
  EXPECT_EQ(doc["steps"][1]["parts"], nlohmann::json({1}));
  ASSERT_EQ(doc["steps"][0]["waypoints"].size(), 2u);
  EXPECT_EQ(doc["steps"][0]["waypoints"][1]["s"], 1.0);
  EXPECT_TRUE(doc["complete"].get<bool>());
  EXPECT_NE(html.find("</html>"), std::string::npos);
}

TEST(DisassembleCli, LockedAssemblyExitsTwoWithItsBlockers) {
  const fs::path dir = scratch("riveted");
  const fs::path toml = write_assembly(dir, riveted_plates());
  const CliRun r = run_cli("disassemble " + toml.string() + " --json --plan-time 0.2", false);
  ASSERT_EQ(r.code, 2) << r.out;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_FALSE(doc["complete"].get<bool>());
  ASSERT_EQ(doc["sequence"].size(), 2u);
  EXPECT_EQ(doc["sequence"][0]["part"], "plate_b");
  EXPECT_EQ(doc["sequence"][0]["status"], "blocked");
  EXPECT_EQ(doc["sequence"][0]["blockers"], nlohmann::json({"plate_a", "rivet"}));
  EXPECT_EQ(doc["sequence"][1]["blockers"], nlohmann::json({"plate_a", "plate_b"}));
  // The table names them too.
  const CliRun table = run_cli("disassemble " + toml.string() + " --plan-time 0");
  EXPECT_EQ(table.code, 2);
  EXPECT_NE(table.out.find("blocked"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("not complete"), std::string::npos) << table.out;
}

// Long part names do not make long lines: the blockers column wraps after a comma, so no line
// of the table is wider than its limited columns allow, and every name is still there.
TEST(DisassembleCli, TableWrapsLongBlockerLists) {
  const fs::path dir = scratch("riveted_long_names");
  Assembly a = riveted_plates();
  for (AssemblyPart& part : a.parts) part.name = "the_" + part.name + "_with_a_long_catalogue_name";
  const fs::path toml = write_assembly(dir, a);
  const CliRun r = run_cli("disassemble " + toml.string() + " --plan-time 0");
  ASSERT_EQ(r.code, 2) << r.out;
  std::istringstream in(r.out);
  std::size_t rows = 0, widest = 0;
  std::string table_text;
  bool in_table = false;
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("#  ")) in_table = true;
    else if (in_table && (line.empty() || std::isalpha(static_cast<unsigned char>(line[0])))) in_table = false;
    if (!in_table) continue;
    ++rows;
    widest = std::max(widest, line.size());
    table_text += line + "\n";
  }
  // Each blocked part names two blockers of 40-odd characters each: one line would need ~90
  // characters for them; with the column limited to 48 they take two lines.
  EXPECT_GE(rows, 1u + 2u * 2u) << r.out;
  EXPECT_LE(widest, 150u) << r.out;
  for (const AssemblyPart& part : a.parts) EXPECT_NE(table_text.find(part.name), std::string::npos) << part.name << "\n" << r.out;
}

TEST(DisassembleCli, ViewPageDrawsTheBlockingGraphOfTheLockedParts) {
  const fs::path source = SWEPT_SOURCE_DIR;
  const fs::path dir = scratch("riveted_view");
  const fs::path toml = write_assembly(dir, riveted_plates());
  const CliRun json = run_cli("disassemble " + toml.string() + " --json --plan-time 0", false);
  ASSERT_EQ(json.code, 2) << json.out;
  const auto cli = nlohmann::json::parse(json.out);
  const CliRun r = run_cli("disassemble " + toml.string() + " --plan-time 0 --view " + (dir / "view.html").string());
  ASSERT_EQ(r.code, 2) << r.out;
  // The page's data: per part that stays, its directions and their blockers, as --json has them.
  const std::string html = bytes_of(dir / "view.html");
  const auto start = html.find('>', html.find("<script id=\"swept-data\"")) + 1;
  const auto doc = nlohmann::json::parse(html.substr(start, html.find("</script>", start) - start));
  std::vector<std::string> names;
  for (const auto& p : doc["parts"]) names.push_back(p["name"]);
  std::size_t blocked = 0;
  for (const auto& step : cli["sequence"]) {
    if (step["status"] != "blocked") continue;
    ASSERT_LT(blocked, doc["blocking"].size());
    const auto& b = doc["blocking"][blocked++];
    ASSERT_EQ(b["parts"].size(), 1u);
    EXPECT_EQ(names[b["parts"][0].get<std::size_t>()], step["part"]);
    ASSERT_EQ(b["directions"].size(), step["blocking"].size());
    for (std::size_t k = 0; k < b["directions"].size(); ++k) {
      EXPECT_EQ(b["directions"][k]["direction"], step["blocking"][k]["direction"]);
      nlohmann::json blockers = nlohmann::json::array();
      for (const auto& i : b["directions"][k]["blockers"]) blockers.push_back(names[i.get<std::size_t>()]);
      EXPECT_EQ(blockers, step["blocking"][k]["blockers"]);
    }
  }
  EXPECT_EQ(blocked, doc["blocking"].size());
  EXPECT_GT(blocked, 0u);

  // In a browser: the arrows are drawn at the end and the panel names the blockers.
  if (!fs::exists("/usr/bin/chromium")) GTEST_SKIP() << "no Chromium at /usr/bin/chromium (apt-get install chromium)";
  if (!fs::exists(source / "viewer" / "node_modules" / "playwright-core"))
    GTEST_SKIP() << "viewer/node_modules/playwright-core is missing (npm ci in viewer/)";
  const std::string cmd = "node '" + (source / "tests" / "viewer" / "disassembly_page.mjs").string() + "' '" +
                          (dir / "view.html").string() + "' '" + dir.string() + "' 2>&1";
  std::string out;
  FILE* pipe = ::popen(cmd.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) out.append(buf, n);
  const int status = ::pclose(pipe);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << out;
  const auto page = nlohmann::json::parse(out.substr(0, out.find('\n')));
  EXPECT_TRUE(page["arrows_visible_at_end"].get<bool>());
  EXPECT_GT(page["red_pixels_at_end"].get<int>(), 50);
  std::size_t arrows = 0;
  for (const auto& b : doc["blocking"]) arrows += b["directions"].size();
  EXPECT_EQ(page["blocking"].size(), arrows);
  for (const auto& step : cli["sequence"]) {
    if (step["status"] == "blocked") {
      EXPECT_NE(page["info_at_end"].get<std::string>().find(step["part"].get<std::string>() + " blocked:"), std::string::npos)
          << page["info_at_end"];
    }
  }
}

// A file with one part (a single-part STEP, one mesh): that part is the base, and there is
// nothing to take apart: complete, exit 0, an empty sequence, no part "removed" by a pull of
// length 0 (which is what a one-part file gave before).
TEST(DisassembleCli, APartAloneIsTheBaseWithNothingToTakeApart) {
  const fs::path dir = scratch("alone");
  const Assembly ring = bolted_ring();
  ASSERT_TRUE(write_stl_binary(dir / "ring.stl", ring.parts[1].mesh).ok());
  std::ofstream(dir / "assembly.toml") << "[[part]]\nfile = \"ring.stl\"\n";
  const CliRun json = run_cli("disassemble " + (dir / "assembly.toml").string() + " --json");
  ASSERT_EQ(json.code, 0) << json.out;
  const auto doc = nlohmann::json::parse(json.out);
  EXPECT_TRUE(doc["complete"].get<bool>());
  EXPECT_TRUE(doc["sequence"].empty()) << doc["sequence"];
  ASSERT_EQ(doc["parts"].size(), 1u);
  EXPECT_TRUE(doc["parts"][0]["fixed"].get<bool>());
  const CliRun table = run_cli("disassemble " + (dir / "assembly.toml").string());
  EXPECT_EQ(table.code, 0);
  EXPECT_NE(table.out.find("1 part, "), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("nothing to take apart"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("(fixed: ring)"), std::string::npos) << table.out;
  EXPECT_EQ(table.out.find("removed"), std::string::npos) << table.out;
}

TEST(DisassembleCli, BadInputIsExitOneAndWritesNothing) {
  const fs::path dir = scratch("bad");
  const fs::path toml = write_assembly(dir, bolted_ring());
  std::ofstream(dir / "dup.toml") << "[[part]]\nfile = \"bolt.stl\"\n[[part]]\nfile = \"bolt.stl\"\n";
  CliRun r = run_cli("disassemble " + (dir / "dup.toml").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("two parts are named 'bolt'"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::create_directories(dir / "empty");
  r = run_cli("disassemble " + (dir / "empty").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("empty"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir / "out"));
  r = run_cli("disassemble " + (dir / "missing.step").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("missing.step"), std::string::npos) << r.out;
}

// `swept plan ASSEMBLY --part NAME` (every other part in place), at disassemble's tolerance, for
// every part `swept disassemble` takes out by itself: the one of its first round (removed with
// every other part in place) must plan; every path planned, and the first round's pull, must pass
// `swept check ASSEMBLY PATH --part NAME`. Returns how many parts planned.
std::size_t parts_plan(const fs::path& assembly, const fs::path& dir) {
  const CliRun d = run_cli("disassemble " + assembly.string() + " --json -o " + (dir / "pulls").string(), false);
  EXPECT_TRUE(d.code == 0 || d.code == 2) << d.out;
  const auto doc = nlohmann::json::parse(d.out);
  const std::string tolerance = " --tolerance " + std::to_string(doc["tolerance"].get<double>());
  std::size_t solved = 0, k = 0;
  for (const auto& step : doc["sequence"]) {
    if (step["status"] != "removed" || !step.contains("part")) continue;
    const std::string name = step["part"];
    const std::string part = " --part '" + name + "'" + tolerance;
    const fs::path planned = dir / ("plan-" + std::to_string(k++) + ".json");
    const CliRun p = run_cli("plan " + assembly.string() + part + " -q --max-queries 20000 -o " + planned.string(), false);
    const bool first = step["round"] == 1;
    if (first) EXPECT_EQ(p.code, 0) << name << ": " << p.out;
    else EXPECT_TRUE(p.code == 0 || p.code == 2) << name << ": " << p.out;
    if (p.code == 0) {
      ++solved;
      const CliRun c = run_cli("check " + assembly.string() + " " + planned.string() + part, false);
      EXPECT_EQ(c.code, 0) << name << " (planned path): " << c.out;
    }
    if (first && !step["path"].is_null()) {
      const CliRun c = run_cli("check " + assembly.string() + " " + (dir / "pulls" / step["path"].get<std::string>()).string() + part, false);
      EXPECT_EQ(c.code, 0) << name << " (disassemble's path): " << c.out;
    }
  }
  return solved;
}

TEST(PartPlan, TheBoltedRingsBoltPlans) {
  const fs::path dir = scratch("part_bolted");
  EXPECT_GE(parts_plan(write_assembly(dir, bolted_ring()), dir), 1u);
}

TEST(PartPlan, TheGearboxAndThePinInBore) {
  const fs::path dir = scratch("part_gearbox");
  ASSERT_TRUE(scenes::generate_gearbox({.name = "gearbox", .scale = scenes::Scale::test, .output_dir = dir / "scene"}).ok());
  EXPECT_GE(parts_plan(dir / "scene" / "assembly.toml", dir), 1u);
  const fs::path pin = scratch("part_pin");
  ASSERT_TRUE(scenes::generate_pin_in_bore({.name = "pin-in-bore", .scale = scenes::Scale::test, .output_dir = pin / "scene"}).ok());
  EXPECT_GE(parts_plan(pin / "scene" / "assembly.toml", pin), 1u);
}

TEST(PartPlan, TheSharedAssembly) {
  const fs::path as1 = fs::path(SWEPT_SHARED_DATA) / "as1" / "as1-oc-214.stp";
  if (!fs::exists(as1)) GTEST_SKIP() << "shared data absent: " << as1;
  const fs::path dir = scratch("part_as1");
  // At least nut, nut#2 and rod come out with every other part in place (tried by hand).
  EXPECT_GE(parts_plan(as1, dir), 3u);
}

TEST(PartPlan, OpenCascadesMotor) {
  const auto motor = occt_sample("Motor-c.brep");
  if (!motor) GTEST_SKIP() << "OCCT's Motor-c.brep not found (shared data or occt-misc)";
  const fs::path dir = scratch("part_motor");
  EXPECT_GE(parts_plan(*motor, dir), 1u);
}

TEST(DisassembleCli, TargetWhyAndReassemble) {
  const fs::path dir = scratch("target");
  ASSERT_TRUE(scenes::generate_gearbox({.name = "gearbox", .scale = scenes::Scale::test, .output_dir = dir / "scene"}).ok());
  const std::string toml = (dir / "scene" / "assembly.toml").string();
  const CliRun r = run_cli("disassemble " + toml + " --target cover --reassemble --json -o " + (dir / "out").string(), false);
  ASSERT_EQ(r.code, 0) << r.out;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["target"]["parts"], nlohmann::json({"cover"}));
  EXPECT_EQ(doc["target"]["removals"], 5);
  EXPECT_TRUE(doc["target"]["fewest"].get<bool>());
  ASSERT_EQ(doc["sequence"].size(), 5u);
  EXPECT_EQ(doc["sequence"][4]["part"], "cover");
  EXPECT_EQ(doc["target"]["why"][0]["part"], "cover");
  EXPECT_EQ(doc["target"]["reassemble"][0], "cover");  // back in first, the screws after it
  // The way back: the same paths reversed, ending at the mounted pose.
  const auto out = read_path(dir / "out" / "05-cover.json");
  const auto back = read_path(dir / "out" / "reassemble" / "01-cover.json");
  ASSERT_TRUE(out.ok() && back.ok());
  ASSERT_EQ(back->poses.size(), out->poses.size());
  EXPECT_EQ(back->poses.back().translation, out->poses.front().translation);
  EXPECT_EQ(back->poses.front().translation, out->poses.back().translation);
  // The table and the why, without --json.
  const CliRun text = run_cli("disassemble " + toml + " --target gear");
  EXPECT_EQ(text.code, 0) << text.out;
  EXPECT_NE(text.out.find("gear: 7 removals (the target included), the fewest"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("why "), std::string::npos) << text.out;
  // Bad input: an unknown or a fixed target; --reassemble without --target.
  const CliRun unknown = run_cli("disassemble " + toml + " --target wheel");
  EXPECT_EQ(unknown.code, 1);
  EXPECT_NE(unknown.out.find("no part named 'wheel' (its parts: housing, cover,"), std::string::npos) << unknown.out;
  const CliRun fixed = run_cli("disassemble " + toml + " --target housing");
  EXPECT_EQ(fixed.code, 1);
  EXPECT_NE(fixed.out.find("the target 'housing' is fixed"), std::string::npos) << fixed.out;
  EXPECT_EQ(run_cli("disassemble " + toml + " --reassemble").code, 1);
}

TEST(PartPlan, BadPartNames) {
  const fs::path dir = scratch("part_bad");
  const fs::path toml = write_assembly(dir, bolted_ring());
  const CliRun r = run_cli("plan " + toml.string() + " --part nosuch");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("no part named 'nosuch' (its parts: base, ring, bolt)"), std::string::npos) << r.out;
  const CliRun c = run_cli("check " + toml.string() + " " + (dir / "x.json").string() + " --part nosuch");
  EXPECT_EQ(c.code, 1) << c.out;
}

}  // namespace
}  // namespace swept
