// A renderer that starts from glTF materials, for `dspbr conformance run` (docs/conformance.md,
// "Your shader on a Vulkan device"): the vector's glTF factors (x.gltf, as a glTF loader reads
// them) through the shader library's mapping (dspbr_material_from_gltf, docs/gltf_mapping.md)
// instead of the spec parameters. A vector without a glTF material is not supported (NOT SUPPLIED):
//   dspbr conformance run VECTORS.json --glsl examples/conformance/shader_gltf.glsl --out REPORT
void conformance_eval(DspbrConformanceInput x, inout DspbrConformanceResult y) {
  y.supported = x.has_gltf;
  if (!x.has_gltf) return;
  DspbrBsdf b = dspbr_prepare(dspbr_material_from_gltf(x.gltf), dspbr_identity_frame(), x.options);
  y.f_cos = dspbr_eval(b, x.v, x.l) * abs(x.l.z);
  y.has_pdf = true;
  y.pdf = dspbr_pdf(b, x.v, x.l);
}
