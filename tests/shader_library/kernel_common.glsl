// The shader-library conformance kernel's body, common to its GLSL and HLSL entries
// (conformance.comp, conformance.hlsl): vector i's record of kRecordFloats floats (the order of
// shader_material.cpp's pack_record) from `rec`, and in `res`:
//   mode 0  f cos, pdf, emission of vector i (10 floats: f cos, pdf, 3 unused, emission);
//   mode 1  invocation i = a * DSPBR_TEST_ALBEDO_NODES + node: one cos-theta node of the albedo of
//           vector a (3 floats), albedo.glsl;
//   mode 2  invocation i = a * 8192 + k: the sample of vector a at the k-th of 8192 stratified lobe
//           choices (u = ((k + 0.5) / 8192, 0.5, 0.5)): 1 when it is a Dirac sample, l, weight x pdf
//           (7 floats), from which the host finds the Dirac lobes (shader_material.h, delta_lobes).
// The albedo is split so: on lavapipe (Mesa 22.3, LLVM 15) nested loops around dspbr_eval returned
// wrong sums and corrupted the caller's values, a loop of 8192 dspbr_sample calls missed Dirac
// lobes, and a workgroup in which some invocations ran the albedo and others did not returned
// wrong pdfs for the others; one loop over phi per invocation does not.

DSPBR_FN vec3 dspbr_test_vec3(uint k) { return vec3(rec[k], rec[k + 1u], rec[k + 2u]); }

DSPBR_FN void dspbr_test_run(uint id, uint mode) {
  uint i = mode == 1u ? id / uint(DSPBR_TEST_ALBEDO_NODES) : (mode == 2u ? id / 8192u : id);
  uint k = i * 64u;
  DspbrMaterial m = dspbr_default_material();
  m.albedo = dspbr_test_vec3(k); k += 3u;
  m.metallic = rec[k]; k += 1u;
  m.roughness = rec[k]; k += 1u;
  m.anisotropy = rec[k]; k += 1u;
  m.anisotropyRotation = rec[k]; k += 1u;
  m.normal = dspbr_test_vec3(k); k += 3u;
  m.translucency = rec[k]; k += 1u;
  m.translucencyColor = dspbr_test_vec3(k); k += 3u;
  m.transparency = rec[k]; k += 1u;
  m.cutoutOpacity = rec[k]; k += 1u;
  m.specular = rec[k]; k += 1u;
  m.specularTint = dspbr_test_vec3(k); k += 3u;
  m.sheenColor = dspbr_test_vec3(k); k += 3u;
  m.sheenRoughness = rec[k]; k += 1u;
  m.clearcoat = rec[k]; k += 1u;
  m.clearcoatRoughness = rec[k]; k += 1u;
  m.clearcoatNormal = dspbr_test_vec3(k); k += 3u;
  m.emissionColor = dspbr_test_vec3(k); k += 3u;
  m.emissionValue = rec[k]; k += 1u;
  m.emissionMode = int(rec[k]); k += 1u;
  m.emissionEnergyNormalization = rec[k] > 0.5f; k += 1u;
  m.thinWalled = rec[k] > 0.5f; k += 1u;
  m.ior = rec[k]; k += 1u;
  DspbrOptions o = dspbr_default_options();
  o.sheen_model = int(rec[k]); k += 1u;
  o.object_area_m2 = rec[k]; k += 1u;
  m.thinFilm = rec[k]; k += 1u;
  m.thinFilmThickness = rec[k]; k += 1u;
  m.thinFilmIor = rec[k]; k += 1u;
  m.flakeCoverage = rec[k]; k += 1u;
  m.flakeColor = dspbr_test_vec3(k); k += 3u;
  m.flakeSize = rec[k]; k += 1u;
  m.flakeRoughness = rec[k]; k += 1u;
  m.flipFlop = rec[k]; k += 1u;
  m.flipFlopColor = dspbr_test_vec3(k); k += 3u;
  o.position = dspbr_test_vec3(k); k += 3u;
  o.object_normal = dspbr_test_vec3(k); k += 3u;
  vec3 v = dspbr_test_vec3(k); k += 3u;
  vec3 l = dspbr_test_vec3(k);
  DspbrBsdf b = dspbr_prepare(m, dspbr_identity_frame(), o);
#ifndef DSPBR_TEST_NO_ALBEDO  // (specializations.sh: mode 0 alone, a smaller kernel)
  if (mode == 1u) {
    vec3 a = dspbr_test_albedo_node(b, v, int(id % uint(DSPBR_TEST_ALBEDO_NODES)));
    res[3u * id] = a.x;
    res[3u * id + 1u] = a.y;
    res[3u * id + 2u] = a.z;
    return;
  }
  if (mode == 2u) {
    DspbrSample d = dspbr_sample(b, v, vec3((float(id % 8192u) + 0.5f) / 8192.0f, 0.5f, 0.5f));
    bool delta = d.valid && (d.flags & DSPBR_FLAG_DELTA) != 0u;
    vec3 value = d.weight * d.pdf;
    res[7u * id] = delta ? 1.0f : 0.0f;
    res[7u * id + 1u] = d.l.x;
    res[7u * id + 2u] = d.l.y;
    res[7u * id + 3u] = d.l.z;
    res[7u * id + 4u] = value.x;
    res[7u * id + 5u] = value.y;
    res[7u * id + 6u] = value.z;
    return;
  }
#endif
  uint r = 10u * i;
  vec3 f = dspbr_eval(b, v, l) * abs(l.z);
  vec3 e = dspbr_emission(b, v);
  res[r] = f.x;
  res[r + 1u] = f.y;
  res[r + 2u] = f.z;
  res[r + 3u] = dspbr_pdf(b, v, l);
  res[r + 7u] = e.x;
  res[r + 8u] = e.y;
  res[r + 9u] = e.z;
}
