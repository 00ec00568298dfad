// Thin-film iridescence R(cos theta, eta_base, d, eta_film): the Airy-summed reflectance of a
// dielectric film between air and a base, integrated over the visible spectrum to linear sRGB
// (spec "Thin Film"; Belcour & Barla 2017), as the reference's spectral quadrature computes it
// (src/dspbr/bsdf/thin_film.cpp). Legal films (eta_film >= 1, bases eta >= 1) keep every wave
// propagating, so the Airy sum is real. A base of eta_base < 0 stands for a perfect mirror (the
// equivalent IOR of a metal of albedo 1): R = 1.

// Exact unpolarised Fresnel reflectance of air | eta (Born & Wolf 1.5.2); 1 under total internal
// reflection and at grazing incidence, 0 for eta = 1.
DSPBR_FN float dspbr_fresnel_exact(float cos_theta, float eta) {
  float c1 = min(1.0f, abs(cos_theta));
  if (eta == 1.0f) return 0.0f;
  if (eta < 0.0f || c1 == 0.0f) return 1.0f;
  float s2 = (1.0f - c1 * c1) / (eta * eta);
  if (s2 >= 1.0f) return 1.0f;
  float c2 = sqrt(1.0f - s2);
  float rs = (c1 - eta * c2) / (c1 + eta * c2);
  float rp = (eta * c1 - c2) / (eta * c1 + c2);
  return 0.5f * (rs * rs + rp * rp);
}

// The equivalent IOR of a metal base, (1 + sqrt(max rho)) / (1 - sqrt(max rho)) (spec "Thin
// Film"); -1 (a mirror) for max rho >= 1.
DSPBR_FN float dspbr_thin_film_metal_eta(vec3 rho) {
  float s = sqrt(clamp(dspbr_max3(rho), 0.0f, 1.0f));
  return s >= 1.0f ? -1.0f : (1.0f + s) / (1.0f - s);
}

// Wyman, Sloan & Shirley 2013 multi-lobe fit of the CIE 1931 2 deg colour-matching functions.
DSPBR_FN float dspbr_wss_lobe(float x, float mu, float s1, float s2) {
  float t = (x - mu) / (x < mu ? s1 : s2);
  return exp(-0.5f * t * t);
}
DSPBR_FN vec3 dspbr_cie1931_cmf(float l) {
  float x = 1.056f * dspbr_wss_lobe(l, 599.8f, 37.9f, 31.0f) + 0.362f * dspbr_wss_lobe(l, 442.0f, 16.0f, 26.7f) -
            0.065f * dspbr_wss_lobe(l, 501.1f, 20.4f, 26.2f);
  float y = 0.821f * dspbr_wss_lobe(l, 568.8f, 46.9f, 40.5f) + 0.286f * dspbr_wss_lobe(l, 530.9f, 16.3f, 31.1f);
  float z = 1.217f * dspbr_wss_lobe(l, 437.0f, 11.8f, 36.0f) + 0.681f * dspbr_wss_lobe(l, 459.0f, 26.0f, 13.8f);
  return vec3(x, y, z);
}

// The six-node Gauss-Legendre rule on [-1, 1] (nodes x_i, weights w_i), i = 0..5.
DSPBR_FN float dspbr_gl6_x(int i) {
  float a = i == 0 || i == 5 ? 0.9324695142f : (i == 1 || i == 4 ? 0.6612093865f : 0.2386191861f);
  return i < 3 ? -a : a;
}
DSPBR_FN float dspbr_gl6_w(int i) {
  return i == 0 || i == 5 ? 0.1713244924f : (i == 1 || i == 4 ? 0.3607615730f : 0.4679139346f);
}
// The kinks of the CMF fit (its lobe centres) bound the spectral panels, 360..830 nm.
DSPBR_FN float dspbr_cmf_edge(int e) {
  if (e == 0) return 360.0f;
  if (e == 1) return 437.0f;
  if (e == 2) return 442.0f;
  if (e == 3) return 459.0f;
  if (e == 4) return 501.1f;
  if (e == 5) return 530.9f;
  if (e == 6) return 568.8f;
  if (e == 7) return 599.8f;
  return 830.0f;
}

// E-white normalised XYZ -> Bradford to D65 -> IEC 61966-2-1 linear sRGB, rows scaled so that
// XYZ = (1, 1, 1) maps to (1, 1, 1), as the reference's colour transform; clamped to [0, 1].
DSPBR_FN vec3 dspbr_thin_film_rgb(vec3 xyz) {
  vec3 rgb = vec3(3.146250862f * xyz.x - 1.666123795f * xyz.y - 0.480127066f * xyz.z,
                  -0.995535012f * xyz.x + 1.955763473f * xyz.y + 0.039771539f * xyz.z,
                  0.063597844f * xyz.x - 0.214596549f * xyz.y + 1.150998705f * xyz.z);
  return vec3(clamp(rgb.x, 0.0f, 1.0f), clamp(rgb.y, 0.0f, 1.0f), clamp(rgb.z, 0.0f, 1.0f));
}

#ifdef DSPBR_THIN_FILM_S_SAMPLES
// With the spectral sensitivity table (dspbr_thin_film_lookup.h, included by the C++ entry): the
// spectral integral in Fourier space (BB17 sec. 4), as the reference's thin_film_fourier.cpp. Per
// polarisation, with the real amplitudes a = r12, b = r23 and K = (1 - a^2)(1 - b^2) / (1 - a^2 b^2),
// |r|^2 = 1 - K (1 + 2 Sum_{m>=1} (-a b)^m cos(m phi)) (the Poisson kernel), and the spectral mean of
// cos(m phi) is Re S_c(m P), P the phase times lambda. False where the series needs more than
// dspbr_film_max_terms terms (|a b| near 1: grazing over a strongly reflecting base): the caller
// integrates per wavelength.
DSPBR_CONST int dspbr_film_max_terms = 64;
// The series stops when the bound of the remaining terms, 2 K |a b|^m / (1 - |a b|), is below this
// (float's resolution of R; the reference sums to 1e-7 in double).
DSPBR_CONST float dspbr_film_series_tolerance = 1e-7f;
// The envelope E_c(x) = S_c(x) exp(-i x nu_c) at 0 <= x < DSPBR_THIN_FILM_S_X_END (Catmull-Rom).
DSPBR_FN void dspbr_thin_film_envelope(float x, DSPBR_OUT(vec3) re, DSPBR_OUT(vec3) im) {
  float g = x / DSPBR_THIN_FILM_S_STEP;
  int k = min(int(g), DSPBR_THIN_FILM_S_SAMPLES - 4);  // samples k .. k + 3 hold x = (k - 1 .. k + 2) STEP
  float f = g - float(k), f2 = f * f, f3 = f2 * f;
  float w0 = 0.5f * (-f3 + 2.0f * f2 - f), w1 = 0.5f * (3.0f * f3 - 5.0f * f2 + 2.0f);
  float w2 = 0.5f * (-3.0f * f3 + 4.0f * f2 + f), w3 = 0.5f * (f3 - f2);
  re = vec3(0.0f, 0.0f, 0.0f);
  im = vec3(0.0f, 0.0f, 0.0f);
  for (int j = 0; j < 4; ++j) {
    float w = j == 0 ? w0 : (j == 1 ? w1 : (j == 2 ? w2 : w3));
    re += vec3(dspbr_thin_film_S_at(k + j, 0), dspbr_thin_film_S_at(k + j, 1), dspbr_thin_film_S_at(k + j, 2)) * w;
    im += vec3(dspbr_thin_film_S_at(k + j, 3), dspbr_thin_film_S_at(k + j, 4), dspbr_thin_film_S_at(k + j, 5)) * w;
  }
}
DSPBR_FN bool dspbr_thin_film_fourier_xyz(float r12s, float r23s, float r12p, float r23p, float phase_nm,
                                          DSPBR_OUT(vec3) xyz) {
  xyz = vec3(0.0f, 0.0f, 0.0f);
  float qs = -r12s * r23s, qp = -r12p * r23p;  // the series' ratios (-a b)
  float ks = (1.0f - r12s * r12s) * (1.0f - r23s * r23s) / (1.0f - qs * qs);
  float kp = (1.0f - r12p * r12p) * (1.0f - r23p * r23p) / (1.0f - qp * qp);
  if (!(abs(qs) < 1.0f) || !(abs(qp) < 1.0f)) return false;
  float tail_s = 2.0f * ks / (1.0f - abs(qs)), tail_p = 2.0f * kp / (1.0f - abs(qp));
  // S_c(m P) = E_c(m P) z_c^m, z_c = exp(i P nu_c), z_c^m by rotation.
  vec3 z_re = vec3(cos(phase_nm * dspbr_thin_film_S_nu[0]), cos(phase_nm * dspbr_thin_film_S_nu[1]),
                   cos(phase_nm * dspbr_thin_film_S_nu[2]));
  vec3 z_im = vec3(sin(phase_nm * dspbr_thin_film_S_nu[0]), sin(phase_nm * dspbr_thin_film_S_nu[1]),
                   sin(phase_nm * dspbr_thin_film_S_nu[2]));
  vec3 zm_re = vec3(1.0f, 1.0f, 1.0f), zm_im = vec3(0.0f, 0.0f, 0.0f);
  vec3 acc_s = vec3(0.0f, 0.0f, 0.0f), acc_p = vec3(0.0f, 0.0f, 0.0f);
  float qms = 1.0f, qmp = 1.0f;
  for (int m = 1; m <= dspbr_film_max_terms; ++m) {
    float x = float(m) * phase_nm;
    if (!(x < DSPBR_THIN_FILM_S_X_END)) break;  // S_c = 0 from here on
    vec3 e_re, e_im;
    dspbr_thin_film_envelope(x, e_re, e_im);
    vec3 r = zm_re * z_re - zm_im * z_im;
    zm_im = zm_re * z_im + zm_im * z_re;
    zm_re = r;
    vec3 s_re = e_re * zm_re - e_im * zm_im;  // Re S_c(m P)
    qms *= qs;
    qmp *= qp;
    acc_s += s_re * qms;
    acc_p += s_re * qmp;
    if (max(tail_s * abs(qms * qs), tail_p * abs(qmp * qp)) < dspbr_film_series_tolerance) break;
    if (m == dspbr_film_max_terms) return false;
  }
  vec3 one = vec3(1.0f, 1.0f, 1.0f);
  xyz = one - (ks * (one + acc_s * 2.0f) + kp * (one + acc_p * 2.0f)) * 0.5f;
  return true;
}
#endif

// R as linear sRGB in [0, 1] (dspbr_thin_film_rgb of the spectral mean).
DSPBR_FN vec3 dspbr_thin_film_reflectance(float cos_theta, float eta_base, float thickness_um, float eta_film) {
  float c1 = min(1.0f, abs(cos_theta));
  if (eta_base < 0.0f) return dspbr_splat(1.0f);
  if (!(thickness_um > 0.0f) || eta_film == 1.0f) return dspbr_splat(dspbr_fresnel_exact(c1, eta_base));
  if (c1 == 0.0f) return dspbr_splat(1.0f);
  // Amplitudes [s, p] of air | film and film | base, and the round-trip phase times lambda.
  float s2_1 = 1.0f - c1 * c1;
  float c2 = sqrt(max(0.0f, 1.0f - s2_1 / (eta_film * eta_film)));
  float c3 = sqrt(max(0.0f, 1.0f - s2_1 / (eta_base * eta_base)));
  float r12s = (c1 - eta_film * c2) / (c1 + eta_film * c2);
  float r12p = (eta_film * c1 - c2) / (eta_film * c1 + c2);
  float r23s = (eta_film * c2 - eta_base * c3) / (eta_film * c2 + eta_base * c3);
  float r23p = (eta_base * c2 - eta_film * c3) / (eta_base * c2 + eta_film * c3);
  float phase_nm = 4.0f * dspbr_pi * eta_film * (thickness_um * 1000.0f) * c2;
#ifdef DSPBR_THIN_FILM_S_SAMPLES
  vec3 xyz_fourier;
  if (dspbr_thin_film_fourier_xyz(r12s, r23s, r12p, r23p, phase_nm, xyz_fourier)) return dspbr_thin_film_rgb(xyz_fourier);
#endif
  // Panel width: the coarsest of 16, 8, ..., 1/16 nm on which the phase turns by at most two
  // resonance widths (1 - |r12 r23|) per panel at 360 nm (the reference's rule ladder, which goes
  // on to 1/64 nm; here 1/16 nm bounds a call to 7520 panels, 2 ms in C++ on this machine).
  float width = 1.0f - max(abs(r12s * r23s), abs(r12p * r23p));
  float rate = phase_nm / (360.0f * 360.0f);
  float panel = 16.0f;
  for (int k = 0; k < 8 && rate * panel > 2.0f * width; ++k) panel *= 0.5f;
  // Resonances narrower than the finest panel resolves (near grazing over a base of ior about 1,
  // where r12 r23 -> -1): each covers less than 1e-4 of the spectrum, and R is the Airy sum's
  // phase average, the incoherent (R12 + R23 - 2 R12 R23) / (1 - R12 R23) per polarisation (-> 1
  // at grazing; f within 0.2 % of the 1/64 nm ladder's at cos 1.2e-4). Without this the sum was
  // 0/0 (NaN) at cos 1e-5 and took 30000 panels, 8.5 ms (the fourth fresh tester's pass).
  if (rate * panel > 2.0f * width) {
    float R12s = r12s * r12s, R23s = r23s * r23s, R12p = r12p * r12p, R23p = r23p * r23p;
    float ds = 1.0f - R12s * R23s, dp = 1.0f - R12p * R23p;
    float Rs = ds > 0.0f ? (R12s + R23s - 2.0f * R12s * R23s) / ds : 1.0f;
    float Rp = dp > 0.0f ? (R12p + R23p - 2.0f * R12p * R23p) / dp : 1.0f;
    return dspbr_splat(clamp(0.5f * (Rs + Rp), 0.0f, 1.0f));
  }
  vec3 xyz = dspbr_splat(0.0f), norm = dspbr_splat(0.0f);
  for (int e = 0; e < 8; ++e) {
    float a = dspbr_cmf_edge(e), b = dspbr_cmf_edge(e + 1);
    int panels = int(ceil((b - a) / panel));
    float h = (b - a) / float(panels);
    for (int p = 0; p < panels; ++p) {
      float mid = a + (float(p) + 0.5f) * h;
      for (int i = 0; i < 6; ++i) {
        float lambda = mid + 0.5f * h * dspbr_gl6_x(i);
        vec3 w = dspbr_cie1931_cmf(lambda) * (0.5f * h * dspbr_gl6_w(i));
        // Airy sum (BB17 eq. 2) per polarisation: |r12 + r23 e^{i phi}|^2 / |1 + r12 r23 e^{i phi}|^2,
        // written without cancellation for float: with a = r12 r23 and 1 - cos phi = 2 sin^2(phi/2),
        // ((r12 + r23)^2 - 2 a (1 - cos phi)) / ((1 + a)^2 - 2 a (1 - cos phi)). Near a resonance
        // (a -> -1) the plain form's denominator is the difference of numbers near 2 (0 or negative
        // in float: NaN at cos 1.2e-4 over a base of ior 1).
        float half_phi = sin(0.5f * phase_nm / lambda);
        float omc = 2.0f * half_phi * half_phi;
        float as = r12s * r23s, ap = r12p * r23p;
        float ds = (1.0f + as) * (1.0f + as) - 2.0f * as * omc, dp = (1.0f + ap) * (1.0f + ap) - 2.0f * ap * omc;
        float rs = ds > 0.0f ? ((r12s + r23s) * (r12s + r23s) - 2.0f * as * omc) / ds : 1.0f;
        float rp = dp > 0.0f ? ((r12p + r23p) * (r12p + r23p) - 2.0f * ap * omc) / dp : 1.0f;
        xyz += w * clamp(0.5f * (rs + rp), 0.0f, 1.0f);
        norm += w;
      }
    }
  }
  return dspbr_thin_film_rgb(xyz / norm);
}
