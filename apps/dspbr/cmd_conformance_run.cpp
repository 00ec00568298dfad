// `dspbr conformance run VECTORS --glsl FILE | --hlsl FILE --out REPORT`: the user's DSPBR shader on
// the first Vulkan device (Mesa's lavapipe without a GPU), judged like `conformance check`
// (docs/conformance.md, "Your shader on a Vulkan device"). The user's file defines
// conformance_eval (shaders/conformance/kit.glsl); the kit compiles it between its prelude and
// driver (shaders/conformance/run.comp, run.hlsl) with glslangValidator, runs every vector in
// batches and writes REPORT/results.json, report.json and index.html in one go. Exit 0: every
// judged vector passes; 1: one fails; 2: bad input (a file, a shader that does not compile); 77: no
// Vulkan device.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "child_process.h"
#include "commands.h"
#include "conformance_judge.h"
#include "interrupt_cleanup.h"
#include "provenance.h"
#include "report_script.h"
#include "dspbr/conformance/results.h"
#include "dspbr/conformance/vector_file.h"
#include "dspbr/conformance/vector_set.h"
#include "dspbr/shader/gltf_factors.h"
#include "dspbr/io/json_write.h"
#include "dspbr/io/read_file.h"
#include "dspbr/shader/material_mapping.h"
#ifdef DSPBR_HAVE_VULKAN
#include "dspbr/vulkan/vk_compute.h"
#endif

namespace dspbr::cli {

namespace {

namespace fs = std::filesystem;
using OJson = nlohmann::ordered_json;

// A shader file is text of at most this size (docs/limits.md).
constexpr std::uint64_t kShaderBytes = limits::kDocumentBytes;
// Vectors per dispatch: bounded buffers whatever the set's size (a batch of 4096 is 1.4 MB of
// records); lavapipe runs a batch of the library's kernel in about a second.
constexpr std::size_t kBatch = 4096;

struct RunArgs {
  std::string vectors, glsl, hlsl, out;
  RepresentationOptions representation;
  std::string glslang = "glslangValidator";
  std::string python = kDefaultPython;
  bool html = true;
  conformance::Selection selection;
};

// The name a #line gives the user's file in the compiler's messages: the path as given, with
// anything a string literal of the preprocessor cannot hold replaced.
std::string line_name(const std::string& path) {
  std::string s;
  for (const char c : path) s += (c == '"' || c == '\\' || static_cast<unsigned char>(c) < 0x20) ? '_' : c;
  return s;
}

// The compiler's error messages, at most `count`, joined by " | " (the whole log when none is marked):
// "ERROR: FILE:2: '' :  syntax error" -> "FILE:2: '' : syntax error".
std::string compiler_errors(const std::string& log, std::size_t count) {
  std::istringstream in(log);
  std::string line, errors;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    if (line.rfind("ERROR: ", 0) != 0 || line.find("compilation errors") != std::string::npos ||
        line.find("Linking") != std::string::npos)
      continue;
    line = line.substr(7);
    for (std::size_t p; (p = line.find("  ")) != std::string::npos;) line.erase(p, 1);
    if (n++ < count) errors += (errors.empty() ? "" : " | ") + line;
  }
  if (n > count) errors += " | and " + std::to_string(n - count) + " more";
  return errors.empty() ? log : errors;
}

#ifdef DSPBR_HAVE_VULKAN
// The user's file with its own #include "..." lines replaced by the files they name, read by the
// kit (only regular files, inside the folder of the user's file, at most kShaderBytes in all, 16
// levels deep), each between #line directives that keep the compiler's messages naming the file
// and line. A name the folder does not hold is left to the compiler, which looks in the kit's
// folders (the shader library). The compiler itself then reads nothing of the user's folder (the
// fifth fresh tester's pass: an #include of a FIFO hung the run, and ../ reached any file).
std::string expand_includes(const std::string& text, const fs::path& file, const fs::path& top, int depth,
                            std::uint64_t& total, const char* option) {
  static const std::regex include_line(R"re(^\s*#\s*include\s*"([^"]*)"\s*(//.*)?\r?$)re");
  const auto refuse = [&](std::size_t line, const std::string& why) {
    return UsageError(std::string(option) + ": " + quote_input(file.string()) + ":" + std::to_string(line) + ": " + why);
  };
  if (depth > 16) throw refuse(1, "#include nested more than 16 levels deep (an include cycle?)");
  std::istringstream in(text);
  std::string line, out;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    std::smatch m;
    if (!std::regex_match(line, m, include_line)) {
      out += line + "\n";
      continue;
    }
    const fs::path named = file.parent_path() / m[1].str();
    std::error_code ec;
    if (m[1].str().empty() || fs::path(m[1].str()).is_absolute()) throw refuse(n, "#include names no file of its folder");
    const fs::path resolved = fs::weakly_canonical(named, ec);
    const std::string inside = top.string() + "/";
    if (ec || resolved.string().rfind(inside, 0) != 0)
      throw refuse(n, "#include \"" + quote_input(m[1].str()) + "\" leaves the folder of " + option + "'s file");
    if (!fs::exists(fs::symlink_status(named, ec))) {  // the kit's (the shader library's)
      out += line + "\n";
      continue;
    }
    std::string included;
    try {
      included = read_file(named.string(), kShaderBytes);
    } catch (const std::exception& e) {
      throw refuse(n, std::string("#include: ") + e.what());
    }
    total += included.size();
    if (total > kShaderBytes) throw refuse(n, "#include: the files included exceed " + bytes_text(kShaderBytes) + " in all");
    out += "#line 1 \"" + line_name(named.string()) + "\"\n" +
           expand_includes(included, named, top, depth + 1, total, option) + "#line " + std::to_string(n + 1) + " \"" +
           line_name(file.string()) + "\"\n";
  }
  return out;
}

// The kernel compiled (SPIR-V words) from the user's file: written into the staging folder's
// .kernel/ as "dspbr_conformance_user" after a #line naming it, and included by the kit's entry.
std::vector<uint32_t> compile_kernel(const RunArgs& a, const OutputFolder& out) {
  const std::string work = out.staging() + "/.kernel";
  const bool hlsl = !a.hlsl.empty();
  const std::string user = hlsl ? a.hlsl : a.glsl;
  const char* option = hlsl ? "--hlsl" : "--glsl";
  std::string text;
  try {
    text = read_file(user, kShaderBytes);
  } catch (const std::exception& e) {
    throw UsageError(std::string(option) + ": " + e.what());
  }
  const std::string shaders = shared_path("shaders", "; the shader library is installed with dspbr");
  std::error_code ec;
  const fs::path top = fs::canonical(fs::absolute(user).parent_path(), ec);
  // Without the folder every #include would pass the containment check below: refused instead.
  if (ec) throw UsageError(std::string(option) + ": the folder of '" + quote_input(user) + "' cannot be read: " + ec.message());
  std::uint64_t total = text.size();
  text = expand_includes(text, fs::absolute(user), top, 0, total, option);
  write_text(out, ".kernel/dspbr_conformance_user", "#line 1 \"" + line_name(user) + "\"\n" + text + "\n");
  const std::string spv = work + "/kernel.spv", log = work + "/compiler.txt";
  std::vector<std::string> argv = {a.glslang, "-V", "-S", "comp"};
  if (hlsl) argv.insert(argv.end(), {"-D", "-e", "main", "--shift-texture-binding", "2"});
  // Includes: the kit's copy of the user's file (its own includes expanded above), then the shader
  // library with the lookups.
  argv.insert(argv.end(), {"-I" + work, "-I" + shaders, "-o", spv,
                           shaders + (hlsl ? "/conformance/run.hlsl" : "/conformance/run.comp")});
  const ChildExit r = run_child(argv, log);
  if (!r.started)
    throw UsageError("--glslang: cannot run '" + a.glslang + "': " + std::strerror(r.error) +
                     " (Debian package glslang-tools; --glslang PATH names the compiler)");
  if (r.status != 0) {
    std::string messages;
    try {
      messages = read_file(log, kShaderBytes);
    } catch (const std::exception&) {
    }
    const std::string errors = compiler_errors(messages, 3);
    throw UsageError(user + ": does not compile as the kit's " + (hlsl ? "HLSL" : "GLSL") + " kernel (" + a.glslang +
                     "): " + (errors.find_first_not_of(" \t\r\n") == std::string::npos
                                  ? "it exited with status " + std::to_string(r.status) + " and printed nothing"
                                  : errors));
  }
  std::error_code spv_ec;
  if (!fs::is_regular_file(spv, spv_ec))  // a "compiler" that succeeds without output (--glslang /bin/true)
    throw UsageError("--glslang: '" + quote_input(a.glslang) + "' exited 0 but wrote no SPIR-V (is it glslangValidator?)");
  std::vector<uint32_t> words;
  try {
    words = vk_compute::read_spirv(spv);
  } catch (const std::invalid_argument&) {  // random bytes from a "compiler" that exits 0
    throw UsageError("--glslang: '" + quote_input(a.glslang) + "' exited 0 but wrote no SPIR-V module (is it glslangValidator?)");
  }
  for (const std::string& f : {spv, log, work + "/dspbr_conformance_user"}) fs::remove(f);
  fs::remove(work);
  return words;
}

// kit.glsl's DSPBR_CONFORMANCE_RECORD_FLOATS: the shader inputs, has_gltf and the glTF factors.
constexpr std::size_t kRecordFloats = shader::kShaderInputFloats + 1 + std::size_t(dspbr_shader::DSPBR_GLTF_FLOATS);

// Vector x as the driver reads it (kit_driver.glsl): the material, the options, v and l, then
// whether it has a glTF material and that material's factors (glTF's defaults without one).
void pack(const conformance::Vector& x, float* out) {
  shader::pack_shader_inputs(conformance::vector_material(x), conformance::vector_options(x), x.v, x.l, out);
  std::size_t k = shader::kShaderInputFloats;
  const bool has_gltf = !x.gltf_material.is_null();
  out[k] = has_gltf ? 1.0f : 0.0f;
  const dspbr_shader::DspbrGltf g =
      has_gltf ? shader::gltf_factors(nlohmann::json(x.gltf_material)) : dspbr_shader::dspbr_default_gltf();
  DSPBR_GLTF_PACK(g, out, k + 1);
}

// A value the shader wrote: as it is when finite, else 1e300 (fails wherever it is judged; a
// results file holds finite numbers only).
double finite_or_huge(float x) { return std::isfinite(x) ? double(x) : 1e300; }

// The driver's result for a vector (DSPBR_CONFORMANCE_RESULT_FLOATS floats), or nothing when the
// shader does not support its material.
std::optional<conformance::Result> result_of(const std::string& id, const float* r) {
  if (!(r[0] > 0.5f)) return std::nullopt;
  const auto rgb = [](const float* c) { return Rgb(finite_or_huge(c[0]), finite_or_huge(c[1]), finite_or_huge(c[2])); };
  conformance::Result out{id, rgb(r + 1), std::nullopt, std::nullopt, std::nullopt, std::nullopt};
  if (r[4] > 0.5f) out.pdf = finite_or_huge(r[5]);
  if (r[6] > 0.5f) out.albedo = rgb(r + 7);
  if (r[10] > 0.5f) out.emission = rgb(r + 11);
  return out;
}

#endif

void run_shader(const RunArgs& a) {
  if (a.glsl.empty() == a.hlsl.empty()) throw UsageError("name the shader with one of --glsl FILE and --hlsl FILE");
#ifndef DSPBR_HAVE_VULKAN
  throw UsageError("this dspbr was built without Vulkan (libvulkan-dev): `conformance run` cannot run shaders");
#else
  parse_tables_option(a.representation.tables);  // before any work
  const std::string script = a.html ? report_script("conformance_report.py", a.python) : std::string();
  std::vector<conformance::Vector> vectors;
  try {
    vectors = conformance::read_vectors(a.vectors);
    std::vector<conformance::Result> none(vectors.size());
    conformance::select_vectors(a.selection, vectors, none);
  } catch (const std::exception& e) {
    throw UsageError(e.what());
  }
  const std::string user = a.glsl.empty() ? a.hlsl : a.glsl;
  InterruptCleanup cleanup(a.out);  // the handlers first, then the folder
  OutputFolder& out = cleanup.out();
  // The compile's files live in the staging folder (removed before the commit; an interrupt or an
  // error discards them with it).
  fs::create_directory(out.staging() + "/.kernel");
  const std::vector<uint32_t> spirv = compile_kernel(a, out);

  vk_compute::Device device("dspbr conformance run");
  if (!device.has_device())
    throw Unavailable("no Vulkan device (Mesa's lavapipe runs on the CPU: Debian package mesa-vulkan-drivers)");
  std::printf("%s on %s: %zu vectors\n", user.c_str(), device.device_name().c_str(), vectors.size());
  std::fflush(stdout);
  const std::vector<vk_compute::TableImage> textures =
      vk_compute::read_lookup_textures(shared_path("luts", "; the tables are installed with dspbr"), false);

  // kit.glsl's DSPBR_CONFORMANCE_RECORD_FLOATS and DSPBR_CONFORMANCE_RESULT_FLOATS
  const std::size_t rec = kRecordFloats, res = 14;
  std::vector<conformance::Result> results(vectors.size());
  for (std::size_t first = 0; first < vectors.size(); first += kBatch) {
    const std::size_t n = std::min(kBatch, vectors.size() - first);
    std::vector<float> records(n * rec);
    for (std::size_t k = 0; k < n; ++k) pack(vectors[first + k], &records[k * rec]);
    const uint32_t push[1] = {uint32_t(n)};
    const std::vector<float> out =
        device.run(vk_compute::item_job(spirv, records.data(), records.size() * sizeof(float), n, res, textures, 2, push, sizeof push));
    for (std::size_t k = 0; k < n; ++k) {
      const std::string& id = vectors[first + k].id;
      results[first + k] = result_of(id, &out[k * res]).value_or(
          conformance::Result{id, std::nullopt, std::nullopt, std::nullopt, std::nullopt, std::nullopt});
    }
    if (vectors.size() > kBatch) std::printf("  %zu of %zu vectors\n", first + n, vectors.size()), std::fflush(stdout);
  }

  OJson provenance = output_provenance();
  provenance["vectors"] = a.vectors;
  provenance["shader"] = {{"file", user}, {"language", a.glsl.empty() ? "HLSL" : "GLSL"},
                          {"device", device.device_name()}};
  expect_with(a.representation, vectors, provenance, a.vectors);
  Judgement j{a.vectors, user, a.out, a.python, script, a.selection};
  write_text(out, "results.json", json_text(conformance::results_document(results), -1, "results.json") + "\n");
  judge_results(j, out, vectors, results, provenance, a.representation);
#endif
}

}  // namespace

void add_conformance_run_command(CLI::App& conformance) {
  auto r = std::make_shared<RunArgs>();
  auto* run = conformance.add_subcommand(
      "run", "Run a GLSL or HLSL implementation of DSPBR on the Vulkan device over the vectors and judge it; writes "
             "REPORT/results.json, report.json and index.html (exit 0: all judged pass, 1: a failure, 2: bad input, "
             "77: no Vulkan device)");
  run->add_option("VECTORS", r->vectors, "vectors.json written by `dspbr conformance generate`")->required();
  run->add_option("--glsl", r->glsl,
                  "GLSL file defining void conformance_eval(DspbrConformanceInput x, inout DspbrConformanceResult y) "
                  "(docs/conformance.md)");
  run->add_option("--hlsl", r->hlsl, "The same in HLSL (compiled by glslang's HLSL front end)");
  run->add_option("--out", r->out, "Report folder")->required();
  run->add_option("--glslang", r->glslang, "The GLSL/HLSL compiler (glslangValidator, Debian glslang-tools)")
      ->capture_default_str();
  run->add_option("--python", r->python, "Python interpreter with numpy, matplotlib and jinja2")->capture_default_str();
  run->add_flag("--no-html", [r](int64_t) { r->html = false; }, "Write only results.json and report.json");
  add_list_option(run, "--groups", r->selection.groups, "Run and judge only the vectors of these groups (comma-separated)");
  add_list_option(run, "--components", r->selection.components,
                  "Run and judge only the vectors whose material has one of these components (comma-separated)");
  add_representation_options(run, r->representation);
  run->callback([r] { run_shader(*r); });
}

}  // namespace dspbr::cli
