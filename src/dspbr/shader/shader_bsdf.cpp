#include "dspbr/shader/shader_bsdf.h"

#include "dspbr/shader/material_mapping.h"

namespace dspbr::shader {

namespace {
dspbr_shader::vec3 to_f(const Vec3& w) { return dspbr_shader::vec3(float(w.x), float(w.y), float(w.z)); }
Rgb to_rgb(dspbr_shader::vec3 c) { return {double(c.x), double(c.y), double(c.z)}; }
}  // namespace

ShaderBsdf::ShaderBsdf(const Material& m, const BsdfOptions& o)
    : b_(dspbr_shader::dspbr_prepare(to_shader_material(m), dspbr_shader::dspbr_identity_frame(),
                                     to_shader_options(o))) {}

Rgb ShaderBsdf::eval(const Vec3& v, const Vec3& l) const { return to_rgb(dspbr_shader::dspbr_eval(b_, to_f(v), to_f(l))); }
double ShaderBsdf::pdf(const Vec3& v, const Vec3& l) const { return double(dspbr_shader::dspbr_pdf(b_, to_f(v), to_f(l))); }
BsdfSample ShaderBsdf::sample(const Vec3& v, const Vec3& u) const {
  const dspbr_shader::DspbrSample s = dspbr_shader::dspbr_sample(b_, to_f(v), to_f(u));
  BsdfSample out;
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
    f |= delta ? kLobeDelta : kLobeGlossy;
    f |= k == dspbr_shader::DSPBR_LOBE_TRANSMISSION ? kLobeTransmission : kLobeReflection;
    if (k == dspbr_shader::DSPBR_LOBE_DIFFUSE && b_.translucency > 0) f |= kLobeTransmission;
  }
  if (b_.alpha_cut < 1) f |= kLobeTransmission | kLobeDelta;
  return f;
}
Rgb ShaderBsdf::emission(const Vec3& v) const { return to_rgb(dspbr_shader::dspbr_emission(b_, to_f(v))); }

}  // namespace dspbr::shader
