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
 * excluded) and the sampler's pdf of l; *pdf is NAN on entry and left so when the renderer has no
 * pdf to compare (the checker then does not judge it). Returns RENDERER_OK, RENDERER_UNSUPPORTED
 * when the renderer does not implement the material (the vector is NOT SUPPLIED, not judged), or
 * another value when the material cannot be evaluated (the harness stops). */
enum { RENDERER_OK = 0, RENDERER_UNSUPPORTED = 1 };
int renderer_eval(const char* material_json, const char* options_json, const double v[3], const double l[3],
                  double f_cos[3], double* pdf);

/* The batched form (the harness built with -DRENDERER_BATCH): the n vectors of one material at
 * once, v and l as 3 n numbers (x, y, z of each), f_cos as 3 n, pdf as n (NAN on entry: leave a
 * pdf NAN when there is none). One status for the batch. */
int renderer_eval_batch(const char* material_json, const char* options_json, int n, const double* v, const double* l,
                        double* f_cos, double* pdf);

#ifdef __cplusplus
}
#endif
#endif
