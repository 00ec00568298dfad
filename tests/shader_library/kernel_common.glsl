// The shader-library conformance kernel's body, common to its GLSL and HLSL entries
// (conformance.comp, conformance.hlsl): vector i's record of kRecordFloats floats (the order of
// shader_material.cpp's pack_record) from `rec`, its f cos and pdf written to `res` (4 floats).

DSPBR_FN vec3 dspbr_test_vec3(uint k) { return vec3(rec[k], rec[k + 1u], rec[k + 2u]); }

DSPBR_FN void dspbr_test_run(uint i) {
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
  vec3 f = dspbr_eval(b, v, l) * abs(l.z);
  res[4u * i] = f.x;
  res[4u * i + 1u] = f.y;
  res[4u * i + 2u] = f.z;
  res[4u * i + 3u] = dspbr_pdf(b, v, l);
}
