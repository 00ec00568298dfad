// A deliberately wrong implementation for the tests of `dspbr conformance run`
// (tests/conformance_run_test.sh): the shader library with every clearcoat 5 % too bright, the
// sheen not implemented (NOT SUPPLIED) and no pdf. The common subset: GLSL and HLSL alike.
void conformance_eval(DspbrConformanceInput x, inout DspbrConformanceResult y) {
  vec3 sheen = x.material.sheenColor;
  if (sheen.x + sheen.y + sheen.z > 0.0f) {
    y.supported = false;
    return;
  }
  DspbrBsdf b = dspbr_prepare(x.material, dspbr_identity_frame(), x.options);
  float k = x.material.clearcoat > 0.0f ? 1.05f : 1.0f;
  y.f_cos = dspbr_eval(b, x.v, x.l) * abs(x.l.z) * k;
}
