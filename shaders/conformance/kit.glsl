// The conformance kit's side of `dspbr conformance run --glsl/--hlsl` (docs/conformance.md, "Your
// shader on a Vulkan device"), in the shader library's common subset: what the kit gives the
// function the user writes and what it reads back. The user's file defines
//   void conformance_eval(DspbrConformanceInput x, inout DspbrConformanceResult y)
// (GLSL and HLSL alike) after this file and before kit_driver.glsl. Names beginning with dspbr_,
// Dspbr or DSPBR_ are the kit's and the shader library's.

// One conformance vector (docs/conformance.md, "Schema").
struct DspbrConformanceInput {
  DspbrMaterial material;  // the DSPBR 2025x parameters by their spec names (material.glsl)
  DspbrOptions options;    // sheen model, object area, position, object normal (bsdf.glsl)
  vec3 v;                  // towards the viewer, local frame: normal +z, tangent +x (docs/bsdf.md)
  vec3 l;                  // towards the light; both away from the surface
  // The vector's glTF material object as the factors a glTF loader reads (gltf.glsl), when it has
  // one (docs/conformance.md, "Schema": gltf_material); else has_gltf is false and gltf holds
  // dspbr_default_gltf(). A renderer that starts from glTF maps it with dspbr_material_from_gltf.
  bool has_gltf;
  DspbrGltf gltf;
};

// What the user's function supplies: f cos always (unless the material is not supported), the rest
// when it computes them; a quantity left unset is NOT SUPPLIED (not judged), never a fake value.
struct DspbrConformanceResult {
  bool supported;     // false: this material is not implemented (the vector is NOT SUPPLIED)
  vec3 f_cos;         // f(v, l) |l.z|, delta lobes excluded
  bool has_pdf;       // the sampler's solid-angle pdf of l is in pdf
  float pdf;
  bool has_albedo;    // the directional albedo at v (delta lobes included) is in albedo
  vec3 albedo;
  bool has_emission;  // the emitted radiance towards v is in emission
  vec3 emission;
};

// Floats per vector record (material, options, v, l, has_gltf, glTF factors) and per result
// (kit_driver.glsl's order).
DSPBR_CONST uint DSPBR_CONFORMANCE_RECORD_FLOATS = DSPBR_MATERIAL_FLOATS + 15u + DSPBR_GLTF_FLOATS;
DSPBR_CONST uint DSPBR_CONFORMANCE_RESULT_FLOATS = 14u;
