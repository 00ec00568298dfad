#include "shader_material.h"

#include <cstdio>
#include <map>

namespace shader_test {

using dspbr_shader::vec3;

namespace {
vec3 v3(const dspbr::Rgb& c) { return vec3(float(c.r), float(c.g), float(c.b)); }
vec3 v3(const dspbr::Vec3& c) { return vec3(float(c.x), float(c.y), float(c.z)); }
}  // namespace

dspbr_shader::DspbrMaterial to_shader_material(const dspbr::Material& m) {
  dspbr_shader::DspbrMaterial s = dspbr_shader::dspbr_default_material();
  s.albedo = v3(m.albedo);
  s.metallic = float(m.metallic);
  s.roughness = float(m.roughness);
  s.anisotropy = float(m.anisotropy);
  s.anisotropyRotation = float(m.anisotropyRotation);
  s.normal = v3(m.normal);
  s.displacement = v3(m.displacement);
  s.translucency = float(m.translucency);
  s.translucencyColor = v3(m.translucencyColor);
  s.transparency = float(m.transparency);
  s.cutoutOpacity = float(m.cutoutOpacity);
  s.specular = float(m.specular);
  s.specularTint = v3(m.specularTint);
  s.thinFilm = float(m.thinFilm);
  s.thinFilmThickness = float(m.thinFilmThickness);
  s.thinFilmIor = float(m.thinFilmIor);
  s.sheenColor = v3(m.sheenColor);
  s.sheenRoughness = float(m.sheenRoughness);
  s.flakeCoverage = float(m.flakeCoverage);
  s.flakeColor = v3(m.flakeColor);
  s.flakeSize = float(m.flakeSize);
  s.flakeRoughness = float(m.flakeRoughness);
  s.flipFlop = float(m.flipFlop);
  s.flipFlopColor = v3(m.flipFlopColor);
  s.clearcoat = float(m.clearcoat);
  s.clearcoatRoughness = float(m.clearcoatRoughness);
  s.clearcoatNormal = v3(m.clearcoatNormal);
  s.emissionColor = v3(m.emissionColor);
  s.emissionValue = float(m.emissionValue);
  s.emissionMode = m.emissionMode == dspbr::EmissionMode::LuminousPower ? dspbr_shader::DSPBR_EMISSIONMODE_LUMINOUS_POWER
                                                                         : dspbr_shader::DSPBR_EMISSIONMODE_LUMINOUS_EMITTANCE;
  s.emissionEnergyNormalization = m.emissionEnergyNormalization;
  s.thinWalled = m.thinWalled;
  s.ior = float(m.ior);
  s.abbeNumber = float(m.abbeNumber);
  s.attenuationColor = v3(m.attenuationColor);
  s.attenuationDistance = std::isinf(m.attenuationDistance) ? 3.402823466e38f : float(m.attenuationDistance);
  s.subsurfaceColor = v3(m.subsurfaceColor);
  s.subsurfaceAnisotropy = float(m.subsurfaceAnisotropy);
  return s;
}

dspbr_shader::DspbrOptions to_shader_options(const dspbr::BsdfOptions& o) {
  dspbr_shader::DspbrOptions s = dspbr_shader::dspbr_default_options();
  s.sheen_model = o.sheen_model == dspbr::SheenModel::Ash ? dspbr_shader::DSPBR_SHEEN_ASH : dspbr_shader::DSPBR_SHEEN_MAIN;
  s.object_area_m2 = float(o.object_area_m2);
  s.wavelength_nm = float(o.wavelength_nm);
  s.position = vec3(float(o.position.x), float(o.position.y), float(o.position.z));
  s.object_normal = vec3(float(o.object_normal.x), float(o.object_normal.y), float(o.object_normal.z));
  return s;
}

void pack_record(const dspbr::conformance::Vector& x, float* out) {
  const dspbr_shader::DspbrMaterial m = to_shader_material(dspbr::conformance::vector_material(x));
  const dspbr_shader::DspbrOptions o = to_shader_options(dspbr::conformance::vector_options(x));
  int i = 0;
  auto put = [&](float f) { out[i++] = f; };
  auto put3 = [&](vec3 c) { put(c.x), put(c.y), put(c.z); };
  // The order of conformance.comp's dspbr_unpack (tests/shader_library/kernel_common.glsl).
  put3(m.albedo), put(m.metallic), put(m.roughness), put(m.anisotropy), put(m.anisotropyRotation);
  put3(m.normal), put(m.translucency), put3(m.translucencyColor), put(m.transparency), put(m.cutoutOpacity);
  put(m.specular), put3(m.specularTint), put3(m.sheenColor), put(m.sheenRoughness), put(m.clearcoat);
  put(m.clearcoatRoughness), put3(m.clearcoatNormal), put3(m.emissionColor), put(m.emissionValue);
  put(float(m.emissionMode)), put(m.emissionEnergyNormalization ? 1.0f : 0.0f), put(m.thinWalled ? 1.0f : 0.0f);
  put(m.ior), put(float(o.sheen_model)), put(o.object_area_m2);
  put(m.thinFilm), put(m.thinFilmThickness), put(m.thinFilmIor);
  put(m.flakeCoverage), put3(m.flakeColor), put(m.flakeSize), put(m.flakeRoughness), put(m.flipFlop);
  put3(m.flipFlopColor), put3(o.position), put3(o.object_normal);
  put3(vec3(float(x.v.x), float(x.v.y), float(x.v.z))), put3(vec3(float(x.l.x), float(x.l.y), float(x.l.z)));
  while (i < kRecordFloats) put(0.0f);
}

int judge(const std::vector<dspbr::conformance::Vector>& vectors, const std::vector<Outcome>& results,
          const std::string& what, int show) {
  struct Count {
    int passed = 0, failed = 0;
  };
  std::map<std::string, Count> groups;
  int failed = 0, shown = 0;
  double worst = 0;
  for (size_t k = 0; k < vectors.size(); ++k) {
    const dspbr::conformance::Vector& x = vectors[k];
    Count& c = groups[x.group];
    const Outcome& r = results[k];
    const double got[3] = {r.f_cos.x, r.f_cos.y, r.f_cos.z}, want[3] = {x.f_cos.r, x.f_cos.g, x.f_cos.b};
    double ratio = x.pdf_tolerance.ratio(r.pdf, x.pdf);
    for (int ch = 0; ch < 3; ++ch) ratio = std::max(ratio, x.tolerance.ratio(got[ch], want[ch]));
    if (!(ratio <= 1.0)) {
      ++c.failed, ++failed;
      if (shown++ < show)
        std::printf("%s FAIL %s: f_cos (%.7g %.7g %.7g) expected (%.7g %.7g %.7g); pdf %.7g expected %.7g; error/tol %.3g\n",
                    what.c_str(), x.id.c_str(), got[0], got[1], got[2], want[0], want[1], want[2], double(r.pdf), x.pdf,
                    ratio);
    } else {
      ++c.passed;
    }
    worst = std::isnan(ratio) ? INFINITY : std::max(worst, ratio);
  }
  int passed = 0;
  for (const auto& [name, c] : groups) {
    std::printf("%s %-24s %4d passed %4d failed\n", what.c_str(), name.c_str(), c.passed, c.failed);
    passed += c.passed;
  }
  std::printf("%s: %d passed, %d failed (worst error/tolerance %.3g)\n", what.c_str(), passed, failed, worst);
  return failed;
}

}  // namespace shader_test

namespace shader_test {

namespace {
vec3 to_f(const dspbr::Vec3& w) { return vec3(float(w.x), float(w.y), float(w.z)); }
dspbr::Rgb to_rgb(vec3 c) { return {double(c.x), double(c.y), double(c.z)}; }
}  // namespace

ShaderBsdf::ShaderBsdf(const dspbr::Material& m, const dspbr::BsdfOptions& o)
    : b_(dspbr_shader::dspbr_prepare(to_shader_material(m), dspbr_shader::dspbr_identity_frame(),
                                     to_shader_options(o))) {}

dspbr::Rgb ShaderBsdf::eval(const dspbr::Vec3& v, const dspbr::Vec3& l) const {
  return to_rgb(dspbr_shader::dspbr_eval(b_, to_f(v), to_f(l)));
}
double ShaderBsdf::pdf(const dspbr::Vec3& v, const dspbr::Vec3& l) const {
  return double(dspbr_shader::dspbr_pdf(b_, to_f(v), to_f(l)));
}
dspbr::BsdfSample ShaderBsdf::sample(const dspbr::Vec3& v, const dspbr::Vec3& u) const {
  const dspbr_shader::DspbrSample s = dspbr_shader::dspbr_sample(b_, to_f(v), to_f(u));
  dspbr::BsdfSample out;
  out.l = {double(s.l.x), double(s.l.y), double(s.l.z)};
  out.weight = to_rgb(s.weight);
  out.pdf = double(s.pdf);
  out.flags = s.flags;
  out.valid = s.valid;
  return out;
}
uint32_t ShaderBsdf::flags() const {
  uint32_t f = 0;
  for (int k = 0; k < dspbr_shader::DSPBR_LOBE_COUNT; ++k) {
    if (!dspbr_shader::dspbr_has_lobe(b_, k)) continue;
    const bool delta = dspbr_shader::dspbr_is_delta_lobe(b_, k);
    f |= delta ? dspbr::kLobeDelta : dspbr::kLobeGlossy;
    f |= k == dspbr_shader::DSPBR_LOBE_TRANSMISSION ? dspbr::kLobeTransmission : dspbr::kLobeReflection;
    if (k == dspbr_shader::DSPBR_LOBE_DIFFUSE && b_.translucency > 0) f |= dspbr::kLobeTransmission;
  }
  if (b_.alpha_cut < 1) f |= dspbr::kLobeTransmission | dspbr::kLobeDelta;
  return f;
}
dspbr::Rgb ShaderBsdf::emission(const dspbr::Vec3& v) const { return to_rgb(dspbr_shader::dspbr_emission(b_, to_f(v))); }

}  // namespace shader_test
