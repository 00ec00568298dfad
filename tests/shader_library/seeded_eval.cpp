// One seeded mistake's compile of the shader library: the patched copy of seed_mistakes.py (include
// path), in its own namespace SEEDED_NS, behind the plain function SEEDED_FN of seeded_eval.h.
#include <cmath>

#include "dspbr.h"
#include "seeded_eval.h"

void SEEDED_FN(const float* in, float* out) {
  using namespace SEEDED_NS;
  // The inputs as pack_shader_inputs writes them (src/dspbr/shader/material_mapping.h): the
  // material, then the sheen model, the object's area, position and normal, v and l.
  DspbrMaterial m;
  DSPBR_MATERIAL_UNPACK(m, in, 0u);
  const unsigned k = DSPBR_MATERIAL_FLOATS;
  DspbrOptions o = dspbr_default_options();
  o.sheen_model = int(in[k]);
  o.object_area_m2 = in[k + 1];
  o.position = vec3(in[k + 2], in[k + 3], in[k + 4]);
  o.object_normal = vec3(in[k + 5], in[k + 6], in[k + 7]);
  const vec3 v(in[k + 8], in[k + 9], in[k + 10]), l(in[k + 11], in[k + 12], in[k + 13]);
  const DspbrBsdf b = dspbr_prepare(m, dspbr_identity_frame(), o);
  const vec3 f = dspbr_eval(b, v, l) * std::fabs(l.z), e = dspbr_emission(b, v);
  const float values[6] = {f.x, f.y, f.z, e.x, e.y, e.z};
  for (int i = 0; i < 6; ++i) out[i] = values[i];
}
