// The shader-library conformance kernel's body, common to its GLSL and HLSL entries
// (conformance.comp, conformance.hlsl): vector i's record of DSPBR_TEST_RECORD_FLOATS floats
// (shader_material.cpp's pack_record: the material as DSPBR_MATERIAL_PACK writes it, then the
// options, v and l) from `rec`, and in `res`:
//   mode 0  f cos, pdf, emission of vector i (10 floats: f cos, pdf, 3 unused, emission);
//   mode 1  invocation i = a * DSPBR_TEST_ALBEDO_NODES + node: one cos-theta node of the albedo of
//           vector a (3 floats), albedo.glsl;
//   mode 2  invocation i = a * 8192 + k: the sample of vector a at the k-th of 8192 stratified lobe
//           choices (u = ((k + 0.5) / 8192, 0.5, 0.5)): 1 when it is a Dirac sample, l, weight x pdf
//           (7 floats), from which the host finds the Dirac lobes (shader_material.h, delta_lobes);
//   mode 3  invocation i: vector 0's sample at the i-th u after its record (9 floats: valid, l,
//           weight, pdf, flags), for the chi-square test on the device (shader_vk_chi2);
//   mode 4  (DSPBR_TEST_STABILITY alone) invocation i: vector 0's material at the i-th query
//           (v, l) after its record, 6 floats each: f (not times the cosine) and pdf (4 floats);
//   mode 5  (the same) the sample at the i-th query (v, u) (9 floats, as mode 3), for the
//           stability scan on the device (shader_vk_stability).
// The albedo is split so: on lavapipe (Mesa 22.3, LLVM 15) nested loops around dspbr_eval returned
// wrong sums and corrupted the caller's values, a loop of 8192 dspbr_sample calls missed Dirac
// lobes, and a workgroup in which some invocations ran the albedo and others did not returned
// wrong pdfs for the others; one loop over phi per invocation does not.

DSPBR_CONST int DSPBR_TEST_RECORD_FLOATS = 80;  // shader_material.h's kRecordFloats
DSPBR_FN vec3 dspbr_test_vec3(uint k) { return vec3(rec[k], rec[k + 1u], rec[k + 2u]); }
#if !defined(DSPBR_TEST_NO_ALBEDO) || defined(DSPBR_TEST_STABILITY)
// A sample as modes 3 and 5 write it: valid, l, weight, pdf, flags (the 9 floats from 9 id on).
DSPBR_FN void dspbr_test_write_sample(uint id, DspbrSample d) {
  res[9u * id] = d.valid ? 1.0f : 0.0f;
  res[9u * id + 1u] = d.l.x;
  res[9u * id + 2u] = d.l.y;
  res[9u * id + 3u] = d.l.z;
  res[9u * id + 4u] = d.weight.x;
  res[9u * id + 5u] = d.weight.y;
  res[9u * id + 6u] = d.weight.z;
  res[9u * id + 7u] = d.pdf;
  res[9u * id + 8u] = float(d.flags);
}
#endif

DSPBR_FN void dspbr_test_run(uint id, uint mode) {
  uint i = mode == 1u ? id / uint(DSPBR_TEST_ALBEDO_NODES) : (mode == 2u ? id / 8192u : (mode >= 3u ? 0u : id));
  uint k = i * uint(DSPBR_TEST_RECORD_FLOATS);
  DspbrMaterial m;
  DSPBR_MATERIAL_UNPACK(m, rec, k);
  k += DSPBR_MATERIAL_FLOATS;
  DspbrOptions o = dspbr_default_options();
  o.sheen_model = int(rec[k]);
  o.object_area_m2 = rec[k + 1u];
  o.position = dspbr_test_vec3(k + 2u);
  o.object_normal = dspbr_test_vec3(k + 5u);
  vec3 v = dspbr_test_vec3(k + 8u);
  vec3 l = dspbr_test_vec3(k + 11u);
  DspbrBsdf b = dspbr_prepare(m, dspbr_identity_frame(), o);
#ifdef DSPBR_TEST_STABILITY
  // Modes 4 and 5 alone (shader_stability_*.spv): the directions and random numbers of
  // validate::stability_scan, finite or not, as the host recorded them.
  uint q = uint(DSPBR_TEST_RECORD_FLOATS) + 6u * id;
  vec3 qv = dspbr_test_vec3(q), qw = dspbr_test_vec3(q + 3u);
  if (mode == 4u) {
    vec3 f = dspbr_eval(b, qv, qw);
    res[4u * id] = f.x;
    res[4u * id + 1u] = f.y;
    res[4u * id + 2u] = f.z;
    res[4u * id + 3u] = dspbr_pdf(b, qv, qw);
    return;
  }
  dspbr_test_write_sample(id, dspbr_sample(b, qv, qw));
#else
// DSPBR_TEST_NO_ALBEDO: mode 0 alone (specializations.sh); DSPBR_TEST_SAMPLES_ONLY: mode 3 alone
// (shader_vk_chi2's kernels: lavapipe builds its pipeline in 11 s instead of 27 s, as it inlines
// every call site).
#if !defined(DSPBR_TEST_NO_ALBEDO) && !defined(DSPBR_TEST_SAMPLES_ONLY)
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
#ifndef DSPBR_TEST_NO_ALBEDO
  // Mode 3: the chi-square test's samples (shader_vk_chi2), vector 0's material and v; the id-th u
  // follows the record.
  if (mode == 3u) {  // valid, l, weight, pdf, flags (9 floats)
    dspbr_test_write_sample(id, dspbr_sample(b, v, dspbr_test_vec3(uint(DSPBR_TEST_RECORD_FLOATS) + 3u * id)));
    return;
  }
#endif
#ifndef DSPBR_TEST_SAMPLES_ONLY
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
#endif
#endif
}
