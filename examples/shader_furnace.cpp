// A minimal path-tracer loop on the shader library's C++ compile (shaders/dspbr.h): a white
// furnace sphere seen orthographically (one bounce into a white environment of radiance 1, which
// a convex object cannot see twice), each pixel the mean sample weight of dspbr_sample in the
// pixel's shading frame. That is the directional albedo at the pixel's view cosine, which the
// reference BSDF (dspbr::MaterialBsdf, double) gives by quadrature of its eval over the sphere;
// the example prints both per material and exits 1 when they disagree beyond the Monte Carlo
// error (5 standard errors of the image mean, plus 1e-3 for the quadrature).
//   example_shader_furnace        (CTest runs it; links dspbr::shaders and dspbr::core)
#include <cmath>
#include <cstdio>

#include "dspbr.h"
#include "dspbr/bsdf/material_bsdf.h"
#include "dspbr/rng.h"

namespace {

namespace ds = dspbr_shader;

struct Case {
  const char* name;
  dspbr::Material m;
};

// The reference's directional albedo at v (local frame): Gauss-Legendre in cos theta_l (each
// hemisphere) by midpoints in phi, of f |cos|.
double reference_albedo(const dspbr::MaterialBsdf& b, const dspbr::Vec3& v) {
  static const double x[8] = {-0.9602898565, -0.7966664774, -0.5255324099, -0.1834346425,
                              0.1834346425,  0.5255324099,  0.7966664774,  0.9602898565};
  static const double w[8] = {0.1012285363, 0.2223810345, 0.3137066459, 0.3626837834,
                              0.3626837834, 0.3137066459, 0.2223810345, 0.1012285363};
  const int panels = 8, phis = 128;
  double sum = 0;
  for (double side : {1.0, -1.0})
    for (int p = 0; p < panels; ++p)
      for (int i = 0; i < 8; ++i) {
        const double mu = (p + 0.5 + 0.5 * x[i]) / panels, wt = w[i] * 0.5 / panels * mu * (2 * M_PI / phis);
        const double s = std::sqrt(1 - mu * mu);
        for (int j = 0; j < phis; ++j) {
          const double phi = (j + 0.5) * 2 * M_PI / phis;
          const dspbr::Rgb f = b.eval(v, {s * std::cos(phi), s * std::sin(phi), side * mu});
          sum += (f.r + f.g + f.b) / 3 * wt;
        }
      }
  return sum;
}

}  // namespace

int main() {
  Case cases[3];
  cases[0].name = "white plastic r=0.5";
  cases[0].m.roughness = 0.5;
  cases[1].name = "white metal r=0.8";
  cases[1].m.metallic = 1, cases[1].m.roughness = 0.8;
  cases[2].name = "white velvet (sheen over plastic)";
  cases[2].m.roughness = 0.6, cases[2].m.sheenColor = {1, 1, 1}, cases[2].m.sheenRoughness = 0.5;
  const int res = 24, spp = 256;
  int failed = 0;
  for (const Case& c : cases) {
    ds::DspbrMaterial m = ds::dspbr_default_material();
    m.albedo = ds::vec3(float(c.m.albedo.r), float(c.m.albedo.g), float(c.m.albedo.b));
    m.metallic = float(c.m.metallic), m.roughness = float(c.m.roughness);
    m.sheenColor = ds::vec3(float(c.m.sheenColor.r), float(c.m.sheenColor.g), float(c.m.sheenColor.b));
    m.sheenRoughness = float(c.m.sheenRoughness);
    const dspbr::MaterialBsdf ref(c.m);
    dspbr::Pcg32 rng(1, 0);
    double image = 0, image2 = 0, expected = 0;
    int pixels = 0;
    for (int py = 0; py < res; ++py)
      for (int px = 0; px < res; ++px) {
        // The sphere's normal under the pixel; the camera looks down -z, so v = +z.
        const float x = (2.0f * float(px) + 1.0f) / float(res) - 1.0f, y = (2.0f * float(py) + 1.0f) / float(res) - 1.0f;
        const float z2 = 1.0f - x * x - y * y;
        if (z2 <= 0.01f) continue;
        const ds::vec3 n(x, y, std::sqrt(z2)), v(0.0f, 0.0f, 1.0f);
        const ds::DspbrBsdf b = ds::dspbr_prepare(m, ds::dspbr_frame_from_normal(n), ds::dspbr_default_options());
        double radiance = 0, radiance2 = 0;
        for (int s = 0; s < spp; ++s) {
          const ds::vec3 u(float(rng.next_double()), float(rng.next_double()), float(rng.next_double()));
          const ds::DspbrSample smp = ds::dspbr_sample(b, v, u);
          const double w = smp.valid ? (smp.weight.x + smp.weight.y + smp.weight.z) / 3 : 0.0;  // environment = 1
          radiance += w, radiance2 += w * w;
        }
        radiance /= spp, radiance2 /= spp;
        image += radiance, image2 += (radiance2 - radiance * radiance) / spp;  // variance of the pixel mean
        const ds::vec3 vl = ds::dspbr_to_local(b.frame, v);
        expected += reference_albedo(ref, {vl.x, vl.y, vl.z});
        ++pixels;
      }
    const double mean = image / pixels, want = expected / pixels, err = std::sqrt(image2) / pixels;
    const bool ok = std::abs(mean - want) <= 5 * err + 1e-3;
    std::printf("%-34s furnace %.5f  reference albedo %.5f  (MC error %.1e) %s\n", c.name, mean, want, err,
                ok ? "agree" : "DISAGREE");
    failed += ok ? 0 : 1;
  }
  return failed ? 1 : 0;
}
