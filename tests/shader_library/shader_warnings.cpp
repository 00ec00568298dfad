// The shader library's C++ entry compiles without a warning under -Wall -Wextra -Wconversion
// -Wdouble-promotion -Wshadow -Wfloat-equal... (-Werror; CTest builds it as shader_cpp_warnings):
// every public call used once.
#include "dspbr.h"

int main() {
  using namespace dspbr_shader;
  DspbrMaterial m = dspbr_default_material();
  m.roughness = 0.3f;
  const DspbrBsdf b = dspbr_prepare(m, dspbr_identity_frame(), dspbr_default_options());
  const vec3 v(0.0f, 0.6f, 0.8f), l(0.0f, -0.6f, 0.8f);
  const vec3 f = dspbr_eval(b, v, l);
  const DspbrSample s = dspbr_sample(b, v, vec3(0.1f, 0.2f, 0.3f));
  const vec3 e = dspbr_emission(b, v);
  return (f.x > 0.0f && s.valid && dspbr_pdf(b, v, l) > 0.0f && !(e.x > 0.0f)) ? 0 : 1;
}
