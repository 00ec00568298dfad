// Compile-time specialization (docs/renderer.md, "Only what a scene needs"): DSPBR_HAS_<COMPONENT>
// 0 removes that component's terms and its layering factor, as the reference's component masks do
// (src/dspbr/component.h), and lets the compiler drop its code. Each defaults to 1 (the generic
// build); `dspbr shader --scene` writes a header that sets them for a scene's materials.
#ifndef DSPBR_HAS_METALLIC
#define DSPBR_HAS_METALLIC 1
#endif
#ifndef DSPBR_HAS_OPAQUE_DIELECTRIC
#define DSPBR_HAS_OPAQUE_DIELECTRIC 1
#endif
#ifndef DSPBR_HAS_THIN_TRANSPARENT
#define DSPBR_HAS_THIN_TRANSPARENT 1
#endif
#ifndef DSPBR_HAS_VOLUMETRIC_TRANSPARENT
#define DSPBR_HAS_VOLUMETRIC_TRANSPARENT 1
#endif
#ifndef DSPBR_HAS_TRANSLUCENCY
#define DSPBR_HAS_TRANSLUCENCY 1
#endif
#ifndef DSPBR_HAS_THIN_FILM
#define DSPBR_HAS_THIN_FILM 1
#endif
#ifndef DSPBR_HAS_SHEEN
#define DSPBR_HAS_SHEEN 1
#endif
#ifndef DSPBR_HAS_FLAKES
#define DSPBR_HAS_FLAKES 1
#endif
#ifndef DSPBR_HAS_CLEARCOAT
#define DSPBR_HAS_CLEARCOAT 1
#endif
#ifndef DSPBR_HAS_EMISSION
#define DSPBR_HAS_EMISSION 1
#endif
#ifndef DSPBR_HAS_DISPERSION
#define DSPBR_HAS_DISPERSION 1
#endif
