// The conformance kit's own implementation for `dspbr conformance run` (docs/conformance.md, "Your
// shader on a Vulkan device"): the shader library itself (shaders/dspbr.glsl, included by the kit)
// behind the function a renderer writes. In the shader library's common subset (vec3, abs), so the
// same file runs as GLSL and as HLSL:
//   dspbr conformance run VECTORS.json --glsl examples/conformance/shader_reference.glsl --out REPORT
//   dspbr conformance run VECTORS.json --hlsl examples/conformance/shader_reference.glsl --out REPORT
// Your own file defines the same function over your BSDF; set only what it computes.
void conformance_eval(DspbrConformanceInput x, inout DspbrConformanceResult y) {
  DspbrBsdf b = dspbr_prepare(x.material, dspbr_identity_frame(), x.options);
  y.f_cos = dspbr_eval(b, x.v, x.l) * abs(x.l.z);
  y.has_pdf = true;
  y.pdf = dspbr_pdf(b, x.v, x.l);
  y.has_emission = true;
  y.emission = dspbr_emission(b, x.v);
}
