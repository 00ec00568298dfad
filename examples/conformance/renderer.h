/* The one function a renderer provides to the conformance harness (harness.c). */
#ifndef DSPBR_CONFORMANCE_RENDERER_H
#define DSPBR_CONFORMANCE_RENDERER_H
#ifdef __cplusplus
extern "C" {
#endif

/* material_json: the vector's material in the params instance form {"material": TYPE, "values":
 * {...}} (values not given are the generic defaults, docs/params.md); options_json: "" or
 * {"sheen": "ash"} / {"position": [...], "object_normal": [...]}; v, l: unit vectors in the local
 * frame of docs/bsdf.md (normal +z, both away from the surface). Writes f(v, l) |l.z| (delta lobes
 * excluded) and the sampler's pdf of l (0 when the renderer has none to compare). Returns 0, or
 * non-zero when the material cannot be evaluated. */
int renderer_eval(const char* material_json, const char* options_json, const double v[3], const double l[3],
                  double f_cos[3], double* pdf);

#ifdef __cplusplus
}
#endif
#endif
