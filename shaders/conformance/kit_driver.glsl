// The conformance kit's driver (kit.glsl says what it is for): vector i's record from `rec`
// (DSPBR_MATERIAL_PACK's material, then the options' sheen model, object area, position and
// object normal, then v and l, then has_gltf and DSPBR_GLTF_PACK's factors), the user's conformance_eval, and its result into `res`
// (DSPBR_CONFORMANCE_RESULT_FLOATS floats: supported, f cos, has_pdf, pdf, has_albedo, albedo,
// has_emission, emission; booleans as 0 or 1). The entries (run.comp, run.hlsl) declare rec and res.

DSPBR_FN vec3 dspbr_conformance_vec3(uint k) { return vec3(rec[k], rec[k + 1u], rec[k + 2u]); }

DSPBR_FN void dspbr_conformance_run(uint i) {
  uint k = i * DSPBR_CONFORMANCE_RECORD_FLOATS;
  DspbrConformanceInput x;
  DSPBR_MATERIAL_UNPACK(x.material, rec, k);
  k += DSPBR_MATERIAL_FLOATS;
  x.options = dspbr_default_options();
  x.options.sheen_model = int(rec[k]);
  x.options.object_area_m2 = rec[k + 1u];
  x.options.position = dspbr_conformance_vec3(k + 2u);
  x.options.object_normal = dspbr_conformance_vec3(k + 5u);
  x.v = dspbr_conformance_vec3(k + 8u);
  x.l = dspbr_conformance_vec3(k + 11u);
  x.has_gltf = rec[k + 14u] > 0.5f;
  DSPBR_GLTF_UNPACK(x.gltf, rec, k + 15u);
  DspbrConformanceResult y;
  y.supported = true;
  y.f_cos = vec3(0.0f, 0.0f, 0.0f);
  y.has_pdf = false;
  y.pdf = 0.0f;
  y.has_albedo = false;
  y.albedo = vec3(0.0f, 0.0f, 0.0f);
  y.has_emission = false;
  y.emission = vec3(0.0f, 0.0f, 0.0f);
  conformance_eval(x, y);
  uint r = i * DSPBR_CONFORMANCE_RESULT_FLOATS;
  res[r] = y.supported ? 1.0f : 0.0f;
  res[r + 1u] = y.f_cos.x;
  res[r + 2u] = y.f_cos.y;
  res[r + 3u] = y.f_cos.z;
  res[r + 4u] = y.has_pdf ? 1.0f : 0.0f;
  res[r + 5u] = y.pdf;
  res[r + 6u] = y.has_albedo ? 1.0f : 0.0f;
  res[r + 7u] = y.albedo.x;
  res[r + 8u] = y.albedo.y;
  res[r + 9u] = y.albedo.z;
  res[r + 10u] = y.has_emission ? 1.0f : 0.0f;
  res[r + 11u] = y.emission.x;
  res[r + 12u] = y.emission.y;
  res[r + 13u] = y.emission.z;
}
