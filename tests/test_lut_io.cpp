// LUT files: EXR / JSON / header round trips, the committed default set, the `dspbr lut`
// command (bad input, determinism across thread counts, --scene), the progress reporter.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "dspbr/lutgen/generate.h"
#include "dspbr/lutgen/lut_io.h"
#include "dspbr/tables/lut_set.h"
#include "dspbr/progress.h"
#include "dspbr/scene/scene_analysis.h"

// The committed header, with its definitions (this is the only translation unit that defines
// PBRLUT_IMPLEMENTATION).
#define PBRLUT_IMPLEMENTATION
#include "../luts/pbrlut.hpp"

using namespace dspbr;
namespace fs = std::filesystem;

namespace {

const std::string kLuts = DSPBR_SOURCE_DIR "/luts";

// A fresh, not yet existing folder under the temp directory.
fs::path temp_folder(const std::string& tag) {
  const fs::path p = fs::temp_directory_path() /
                     ("dspbr-test-lut-" + tag + "-" + std::to_string(::getpid()));
  fs::remove_all(p);
  return p;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `dspbr <args>` (stdout/stderr discarded) and returns its exit code.
int run_dspbr(const std::string& args) {
  const std::string cmd = std::string("'") + DSPBR_EXE + "' " + args + " >/dev/null 2>&1";
  const int st = std::system(cmd.c_str());
  return WIFEXITED(st) ? WEXITSTATUS(st) : 128;
}

Table small_table(const std::string& name, std::vector<int> size) {
  LutOptions opt;
  opt.tables = {name};
  opt.sizes[name] = size;
  opt.samples = 8 << 6;
  opt.target_error = 0;
  opt.progress = false;
  return generate_luts(opt).front();
}

}  // namespace

TEST(LutIo, ExrRoundTripFloatAndHalf) {
  const fs::path dir = temp_folder("exr");
  const Table t = small_table("GGX_E", {3, 5});
  for (bool half : {false, true}) {
    const double rounding = write_lut_exrs(t, dir.string(), half);
    int w = 0, h = 0;
    const std::vector<float> px = read_lut_exr((dir / "GGX_E.exr").string(), &w, &h);
    ASSERT_EQ(w, 5);
    ASSERT_EQ(h, 3);
    for (size_t i = 0; i < px.size(); ++i) {
      if (!half) EXPECT_EQ(px[i], float(t.values[i]));
      EXPECT_LE(std::abs(double(px[i]) - t.values[i]), rounding);
      // half keeps 11 significant bits: relative rounding error <= 2^-11
      EXPECT_LE(std::abs(double(px[i]) - t.values[i]), (half ? 0x1p-11 : 0x1p-24) * std::abs(t.values[i]));
    }
  }
  // Base_E: one image per f0 slice, scanlines = roughness, columns = cos theta.
  const Table b = small_table("Base_E", {2, 3, 4});
  write_lut_exrs(b, dir.string(), false);
  const std::vector<std::string> names = lut_exr_names(b);
  ASSERT_EQ(names, (std::vector<std::string>{"Base_0.25_E.exr", "Base_0.75_E.exr"}));
  int w = 0, h = 0;
  const std::vector<float> px = read_lut_exr((dir / names[1]).string(), &w, &h);
  ASSERT_EQ(w, 4);
  ASSERT_EQ(h, 3);
  EXPECT_EQ(px[1 * 4 + 2], float(b.at({1, 1, 2})));
  for (const auto& e : fs::directory_iterator(dir)) EXPECT_NE(e.path().filename().string().rfind(".tmp-", 0), 0u);
  fs::remove_all(dir);
}

TEST(LutIo, JsonRoundTrip) {
  const fs::path dir = temp_folder("json");
  LutOptions opt;
  opt.sizes = {{"GGX_E", {3, 4}},        {"GGX_E_avg", {3}},          {"Base_E", {2, 2, 3}},
               {"Base_E_avg", {2, 2}},    {"Sheen_E", {2, 3}},         {"Sheen_ash_E", {3, 2}},
               {"Glass_E", {2, 2, 3}},    {"Glass_inv_E", {2, 3, 2}},  {"Glass_E_avg", {2, 2}},
               {"Glass_inv_E_avg", {2, 2}}};
  opt.samples = 8 << 5;
  opt.target_error = 0;
  opt.grid = GridKind::Endpoint;
  opt.progress = false;
  const std::vector<Table> tables = generate_luts(opt);
  write_luts(tables, opt, dir.string(), LutFormats{false, false, true, false});
  const std::vector<Table> back = read_lut_json((dir / "dspbr_luts.json").string());
  ASSERT_EQ(back.size(), tables.size());
  for (size_t i = 0; i < tables.size(); ++i) {
    EXPECT_EQ(back[i].name, tables[i].name);
    EXPECT_EQ(back[i].values, tables[i].values);  // doubles round-trip exactly
    EXPECT_EQ(back[i].errors, tables[i].errors);
    ASSERT_EQ(back[i].axes.size(), tables[i].axes.size());
    for (size_t d = 0; d < tables[i].axes.size(); ++d) {
      EXPECT_EQ(back[i].axes[d].size, tables[i].axes[d].size);
      EXPECT_EQ(back[i].axes[d].name, tables[i].axes[d].name);
      EXPECT_TRUE(back[i].axes[d].kind == GridKind::Endpoint);
    }
  }
  EXPECT_THROW(read_lut_json((dir / "missing.json").string()), std::runtime_error);
  fs::remove_all(dir);
}

// The committed set has the published names and sizes, finite values, and per-cell standard
// errors that put 4 sigma under the 1e-4 accuracy goal.
TEST(LutIo, CommittedSetHasPublishedLayoutAndAccuracy) {
  const LutSet& s = LutSet::published();
  const std::pair<const Table*, std::vector<int>> expect[] = {
      {&s.ggx_e, {32, 32}}, {&s.ggx_e_avg, {32}},     {&s.base_e, {16, 16, 16}},
      {&s.base_e_avg, {16, 16}}, {&s.sheen_e, {16, 16}}, {&s.sheen_ash_e, {16, 16}}};
  for (const auto& [t, size] : expect) {
    ASSERT_EQ(t->axes.size(), size.size()) << t->name;
    for (size_t d = 0; d < size.size(); ++d) {
      EXPECT_EQ(t->axes[d].size, size[d]) << t->name;
      EXPECT_TRUE(t->axes[d].kind == GridKind::CellCentred);
    }
    for (size_t i = 0; i < t->size(); ++i) {
      EXPECT_TRUE(std::isfinite(t->values[i]) && t->values[i] >= 0) << t->name << " " << i;
      EXPECT_LE(t->errors[i], 2.5e-5) << t->name << " cell " << i;
    }
  }
  // Energy conservation where it must hold (the alternative sheen is allowed to exceed 1).
  for (const Table* t : {&s.ggx_e, &s.ggx_e_avg, &s.base_e, &s.base_e_avg, &s.sheen_e})
    for (double v : t->values) EXPECT_LE(v, 1.0 + 1e-4) << t->name;
}

// Header round trip: the committed header holds the committed JSON values rounded to float,
// with the published symbol names and *_size arrays.
TEST(LutIo, CommittedHeaderMatchesJson) {
  const LutSet& s = LutSet::published();
  EXPECT_EQ(GGX_E_size[0], 32);
  EXPECT_EQ(GGX_E_size[1], 32);
  EXPECT_EQ(GGX_E_avg_size[0], 32);
  EXPECT_EQ(Base_E_size[0], 16);
  EXPECT_EQ(Base_E_size[2], 16);
  EXPECT_EQ(Base_E_avg_size[1], 16);
  EXPECT_EQ(Sheen_E_size[0], 16);
  EXPECT_EQ(Sheen_ash_E_size[1], 16);
  for (int i = 0; i < 32; ++i) {
    EXPECT_EQ(GGX_E_avg[i], float(s.ggx_e_avg.at({i})));
    for (int j = 0; j < 32; ++j) EXPECT_EQ(GGX_E[i][j], float(s.ggx_e.at({i, j})));
  }
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j) {
      EXPECT_EQ(Base_E_avg[i][j], float(s.base_e_avg.at({i, j})));
      EXPECT_EQ(Sheen_E[i][j], float(s.sheen_e.at({i, j})));
      EXPECT_EQ(Sheen_ash_E[i][j], float(s.sheen_ash_e.at({i, j})));  // unclamped by default
      for (int k = 0; k < 16; ++k) EXPECT_EQ(Base_E[i][j][k], float(s.base_e.at({i, j, k})));
    }
  // The committed header is exactly what the current writer makes from the committed JSON.
  const std::vector<Table> tables = read_lut_json(kLuts + "/dspbr_luts.json");
  EXPECT_EQ(lut_header_text(tables, LutOptions{}), slurp(kLuts + "/pbrlut.hpp"));
}

// The library's default tables are the committed files, compiled in (no run-time read of luts/),
// and the text readers give what the file readers give, with the given name in their messages.
TEST(LutIo, BuiltinTablesAreTheCommittedFiles) {
  EXPECT_EQ(std::string(LutSet::builtin_text(LutLayout::Published)), slurp(kLuts + "/dspbr_luts.json"));
  EXPECT_EQ(std::string(LutSet::builtin_text(LutLayout::Renderer)), slurp(kLuts + "/dspbr_renderer_luts.json"));
  EXPECT_STREQ(LutSet::builtin_name(LutLayout::Renderer), "built-in luts/dspbr_renderer_luts.json");
  EXPECT_TRUE(LutSet::builtin().layout == LutLayout::Renderer);
  EXPECT_TRUE(LutSet::published().layout == LutLayout::Published);
  const LutSet file = LutSet::load(kLuts + "/dspbr_luts.json");
  EXPECT_EQ(file.ggx_e.values, LutSet::published().ggx_e.values);
  EXPECT_EQ(file.base_e.values, LutSet::published().base_e.values);
  const LutSet renderer = LutSet::load(kLuts + "/dspbr_renderer_luts.json");
  EXPECT_EQ(renderer.E_m(0.3, 0.4), LutSet::builtin().E_m(0.3, 0.4));
  try {
    read_lut_json_text("{\"format\": \"other\"}", "built-in x.json");
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("'built-in x.json': not a dspbr_luts file", 0), 0u) << e.what();
  }
  EXPECT_THROW(LutSet::from_text("not json", "x"), std::runtime_error);
  try {
    LutSet::load(kLuts);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
  }
}

// The Base_E atlas holds the slices stacked vertically; every PNG decodes (offset + scale * pixel /
// 65535 from its own attribute) to the JSON values within 16-bit rounding; the attributes name the
// table and its axes.
TEST(LutIo, CommittedAtlasAndPngsMatchJson) {
  for (const Table& t : read_lut_json(kLuts + "/dspbr_luts.json")) {
    if (!lut_atlas_name(t).empty()) {
      int w = 0, h = 0;
      const std::vector<float> px = read_lut_exr(kLuts + "/" + lut_atlas_name(t), &w, &h);
      ASSERT_EQ(size_t(w) * size_t(h), t.size());
      EXPECT_EQ(h, t.axes[0].size * t.axes[1].size);
      for (size_t i = 0; i < t.size(); ++i) EXPECT_EQ(px[i], float(t.values[i]));
    }
    auto in = OIIO::ImageInput::open(kLuts + "/" + lut_png_names(t)[0]);
    ASSERT_TRUE(in) << t.name;
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(spec.format, OIIO::TypeDesc::UINT16);
    EXPECT_EQ(spec.get_string_attribute("dspbr:table"), t.name);
    EXPECT_NE(spec.get_string_attribute("dspbr:axes").find(t.axes.back().name), std::string::npos);
    double lo = 0, scale = 0;
    ASSERT_EQ(std::sscanf(spec.get_string_attribute("dspbr:png_decode").c_str(), "value = %lf + %lf", &lo, &scale), 2);
    std::vector<uint16_t> px(size_t(spec.width) * size_t(spec.height));
    ASSERT_TRUE(in->read_image(0, 0, 0, 1, OIIO::TypeDesc::UINT16, px.data()));
    ASSERT_EQ(px.size(), t.size());
    for (size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(lo + scale * px[i] / 65535.0, t.values[i], 0.51 * scale / 65535.0 + 1e-9);
  }
}

TEST(LutIo, CommittedExrsMatchJson) {
  for (const Table& t : read_lut_json(kLuts + "/dspbr_luts.json")) {
    const std::vector<std::string> names = lut_exr_names(t);
    const size_t per_image = t.size() / names.size();
    for (size_t k = 0; k < names.size(); ++k) {
      int w = 0, h = 0;
      const std::vector<float> px = read_lut_exr(kLuts + "/" + names[k], &w, &h);
      ASSERT_EQ(size_t(w) * size_t(h), per_image) << names[k];
      EXPECT_EQ(w, t.axes.back().size);
      for (size_t i = 0; i < per_image; ++i) EXPECT_EQ(px[i], float(t.values[k * per_image + i])) << names[k];
    }
  }
}

TEST(LutGenerate, SameBitsWhateverTheThreadCount) {
  LutOptions opt;
  opt.sizes = {{"GGX_E", {5, 6}},        {"GGX_E_avg", {3}},          {"Base_E", {2, 3, 4}},
               {"Base_E_avg", {2, 3}},    {"Sheen_E", {3, 3}},         {"Sheen_ash_E", {3, 3}},
               {"Glass_E", {2, 3, 3}},    {"Glass_inv_E", {2, 3, 3}},  {"Glass_E_avg", {2, 3}},
               {"Glass_inv_E_avg", {2, 3}}};
  opt.samples = 8 << 6;
  opt.progress = false;
  opt.threads = 1;
  const std::vector<Table> a = generate_luts(opt);
  opt.threads = 2;
  const std::vector<Table> b = generate_luts(opt);
  ASSERT_EQ(a.size(), 10u);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(0, std::memcmp(a[i].values.data(), b[i].values.data(), a[i].values.size() * sizeof(double)));
    EXPECT_EQ(0, std::memcmp(a[i].errors.data(), b[i].errors.data(), a[i].errors.size() * sizeof(double)));
  }
}

TEST(LutCli, SameFilesWithOneAndTwoThreads) {
  const fs::path d1 = temp_folder("t1"), d2 = temp_folder("t2");
  const std::string common =
      " --tables GGX_E,Base_E,Sheen_ash_E --size GGX_E=4x4 --size Base_E=2x3x3 --size Sheen_ash_E=3x3 --samples 1024 --seed 7";
  ASSERT_EQ(run_dspbr("lut --out '" + d1.string() + "' --threads 1" + common), 0);
  ASSERT_EQ(run_dspbr("lut --out '" + d2.string() + "' --threads 2" + common), 0);
  int files = 0;
  for (const auto& e : fs::directory_iterator(d1)) {
    ++files;
    EXPECT_NE(e.path().filename().string().rfind(".tmp-", 0), 0u) << "temporary file left: " << e.path();
    EXPECT_EQ(slurp(e.path()), slurp(d2 / e.path().filename())) << e.path().filename();
  }
  EXPECT_EQ(files, 1 + 2 + 1 + 1 + 3 + 2);  // GGX_E, 2 Base slices + atlas, Sheen_ash_E, 3 PNGs, header, JSON
  fs::remove_all(d1);
  fs::remove_all(d2);
}

// Bad input: non-zero exit, and no output folder or file is left behind.
TEST(LutCli, BadArgumentsFailAndLeaveNoFiles) {
  const fs::path dir = temp_folder("bad");
  const std::string out = " --out '" + dir.string() + "'";
  const char* cases[] = {"--tables GGX_E,Nope", "--tables ''",           "--samples -3",
                         "--samples abc",       "--samples 4",           "--size GGX_E=0x4",
                         "--size GGX_E=4",      "--size Foo=4x4",        "--size GGX_E=4xq",
                         "--grid middle",       "--formats exr,gif",     "--integrator simpson",
                         "--threads -1",        "--randomizations 1",    "--target-error -1",
                         "--grid endpoint --size GGX_E=1x4",             "--scene /nonexistent.gltf"};
  for (const char* c : cases) {
    EXPECT_NE(run_dspbr(std::string("lut") + out + " " + c), 0) << c;
    EXPECT_FALSE(fs::exists(dir)) << c;
  }
  EXPECT_NE(run_dspbr("lut --tables GGX_E"), 0) << "missing --out";
  // Unwritable or impossible output folders.
  EXPECT_NE(run_dspbr("lut --tables GGX_E_avg --out /proc/dspbr-lut-test"), 0);
  EXPECT_FALSE(fs::exists("/proc/dspbr-lut-test"));
  fs::create_directories(dir);
  const fs::path file = dir / "a_file";
  std::ofstream(file) << "x";
  EXPECT_NE(run_dspbr("lut --tables GGX_E_avg --out '" + file.string() + "'"), 0);
  EXPECT_NE(run_dspbr("lut --tables GGX_E_avg --out '" + (file / "sub").string() + "'"), 0);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

// --scene generates exactly the tables tables_for_scene() names for the scene.
TEST(LutCli, SceneSelectsTheTablesItNeeds) {
  const std::string scene = DSPBR_REFERENCE_DIR "/scenes/sphere/00-metal-roughness-0.40.gltf";
  const std::vector<std::string> need = tables_for_scene(scene);
  const fs::path dir = temp_folder("scene");
  // Small sizes for the tables it needs (a size for a table not generated is refused).
  std::string sizes;
  for (const std::string& t : need) {
    std::string dims;
    for (size_t d = 0; d < lut_axis_names(t).size(); ++d) dims += (d ? "x" : "") + std::string("2");
    sizes += " --size " + t + "=" + dims;
  }
  ASSERT_EQ(run_dspbr("lut --out '" + dir.string() + "' --scene '" + scene + "' --formats json --samples 64" + sizes), 0);
  if (need.empty()) {
    EXPECT_FALSE(fs::exists(dir / "dspbr_luts.json"));
  } else {
    std::vector<std::string> got;
    for (const Table& t : read_lut_json((dir / "dspbr_luts.json").string())) got.push_back(t.name);
    EXPECT_EQ(got, need);
  }
  fs::remove_all(dir);
}

// --half writes 16-bit half EXRs (and --formats exr only the images).
TEST(LutCli, HalfWritesHalfFloatImages) {
  const fs::path dir = temp_folder("half");
  ASSERT_EQ(run_dspbr("lut --out '" + dir.string() + "' --tables GGX_E_avg --size GGX_E_avg=4 --samples 64 --half --formats exr"), 0);
  auto in = OIIO::ImageInput::open((dir / "GGX_E_avg.exr").string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().format, OIIO::TypeDesc::HALF);
  EXPECT_EQ(in->spec().channelnames, std::vector<std::string>{"Y"});
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

TEST(LutProgress, CountsAndStaysQuietWhenDisabled) {
  testing::internal::CaptureStderr();
  {
    Progress p("test", 10, false);
    for (int i = 0; i < 10; ++i) p.add();
    EXPECT_EQ(p.done(), 10u);
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}
