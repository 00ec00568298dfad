// Test doubles for the validation suite: tiny correct lobes (Lambert, GGX reflection from ggx.h,
// mirror + Lambert mixture, eta-scaled diffuse transmission) and deliberately broken variants
// that each check must catch. Not library lobes: they exist only to prove the checks can fail.
#pragma once
#include <cmath>
#include <limits>

#include "dspbr/bsdf/bsdf.h"
#include "dspbr/constants.h"
#include "dspbr/ggx.h"
#include "dspbr/bsdf/sampling.h"

namespace dspbr::testing {

// Lambertian reflection on the viewer's side: f = rho / pi; cosine sampling.
class LambertLobe : public Bsdf {
 public:
  explicit LambertLobe(double rho = 1.0) : rho_(rho) {}
  Rgb eval(const Vec3& v, const Vec3& l) const override {
    return v.z * l.z > 0 ? Rgb(rho_ / kPi) : Rgb(0.0);
  }
  double pdf(const Vec3& v, const Vec3& l) const override {
    return v.z * l.z > 0 ? std::abs(l.z) / kPi : 0.0;
  }
  BsdfSample sample(const Vec3& v, const Vec3& u) const override {
    BsdfSample s;
    if (v.z == 0) return s;
    s.l = sample_cosine_hemisphere(u.y, u.z);
    if (v.z < 0) s.l.z = -s.l.z;
    s.pdf = pdf(v, s.l);
    if (!(s.pdf > 0)) return s;
    s.weight = eval(v, s.l) * (std::abs(s.l.z) / s.pdf);
    s.flags = kLobeReflection | kLobeDiffuse;
    s.valid = true;
    return s;
  }
  uint32_t flags() const override { return kLobeReflection | kLobeDiffuse; }

 protected:
  double rho_;
};

// Single-scattering GGX reflection (no Fresnel) with VNDF sampling; viewer above the surface.
class GgxReflectionLobe : public Bsdf {
 public:
  explicit GgxReflectionLobe(double alpha) : a_(alpha) {}
  Rgb eval(const Vec3& v, const Vec3& l) const override { return Rgb(GgxDistribution(a_, a_).M_r(v, l)); }
  double pdf(const Vec3& v, const Vec3& l) const override {
    if (v.z <= 0 || l.z <= 0) return 0.0;
    const Vec3 h = normalize(v + l);
    return GgxDistribution(a_, a_).PDF(v, h) / (4.0 * dot(v, h));
  }
  BsdfSample sample(const Vec3& v, const Vec3& u) const override {
    BsdfSample s;
    if (v.z <= 0) return s;
    const Vec3 h = GgxDistribution(a_, a_).Sample_wm(v, u.y, u.z);
    s.l = reflect(v, h);
    if (s.l.z <= 0) return s;  // reflected below the horizon: the lobe's energy loss
    s.pdf = pdf(v, s.l);
    if (!(s.pdf > 0)) return s;
    s.weight = eval(v, s.l) * (s.l.z / s.pdf);
    s.flags = kLobeReflection | kLobeGlossy;
    s.valid = true;
    return s;
  }
  uint32_t flags() const override { return kLobeReflection | kLobeGlossy; }

 protected:
  double a_;
};

// A perfect mirror of reflectance r chosen with probability p, else Lambert (rho).
class MirrorPlusLambert : public Bsdf {
 public:
  MirrorPlusLambert(double r, double p, double rho) : r_(r), p_(p), lambert_(rho) {}
  Rgb eval(const Vec3& v, const Vec3& l) const override { return lambert_.eval(v, l); }
  double pdf(const Vec3& v, const Vec3& l) const override { return (1 - p_) * lambert_.pdf(v, l); }
  BsdfSample sample(const Vec3& v, const Vec3& u) const override {
    BsdfSample s;
    if (v.z <= 0) return s;
    if (u.x < p_) {
      s.l = reflect(v, Vec3{0, 0, 1});
      s.pdf = p_;
      s.weight = Rgb(r_ / p_);
      s.flags = kLobeReflection | kLobeDelta;
      s.valid = true;
      return s;
    }
    s = lambert_.sample(v, u);
    if (!s.valid) return s;
    s.pdf = pdf(v, s.l);
    s.weight = eval(v, s.l) * (std::abs(s.l.z) / s.pdf);
    return s;
  }
  uint32_t flags() const override { return kLobeReflection | kLobeDelta | kLobeDiffuse; }

 private:
  double r_, p_;
  LambertLobe lambert_;
};

// Diffuse transmission through an interface between media eta_above (+z) and eta_below (-z):
// f(v, l) = t / pi * eta_v^2 for v, l on opposite sides (eta_v: medium of v), so that
// f(v,l) / eta_v^2 = f(l,v) / eta_l^2 (the eta^2 rule). scale_eta = false drops eta_v^2.
class DiffuseTransmission : public Bsdf {
 public:
  DiffuseTransmission(double t, double eta_above, double eta_below, bool scale_eta = true)
      : t_(t), ea_(eta_above), eb_(eta_below), scale_(scale_eta) {}
  Rgb eval(const Vec3& v, const Vec3& l) const override {
    if (!(v.z * l.z < 0)) return Rgb(0.0);
    const double ev = v.z > 0 ? ea_ : eb_;
    return Rgb(t_ / kPi * (scale_ ? ev * ev : 1.0));
  }
  double pdf(const Vec3& v, const Vec3& l) const override { return v.z * l.z < 0 ? std::abs(l.z) / kPi : 0.0; }
  BsdfSample sample(const Vec3& v, const Vec3& u) const override {
    BsdfSample s;
    if (v.z == 0) return s;
    s.l = sample_cosine_hemisphere(u.y, u.z);
    if (v.z > 0) s.l.z = -s.l.z;
    s.pdf = pdf(v, s.l);
    if (!(s.pdf > 0)) return s;
    s.weight = eval(v, s.l) * (std::abs(s.l.z) / s.pdf);
    s.flags = kLobeTransmission | kLobeDiffuse;
    s.valid = true;
    return s;
  }
  uint32_t flags() const override { return kLobeTransmission | kLobeDiffuse; }

 private:
  double t_, ea_, eb_;
  bool scale_;
};

// ---- Broken lobes ------------------------------------------------------------------------

// pdf() off by a constant factor (sample() itself is right).
class PdfScaledGgx : public GgxReflectionLobe {
 public:
  PdfScaledGgx(double alpha, double k) : GgxReflectionLobe(alpha), k_(k) {}
  double pdf(const Vec3& v, const Vec3& l) const override { return k_ * GgxReflectionLobe::pdf(v, l); }
  BsdfSample sample(const Vec3& v, const Vec3& u) const override {
    BsdfSample s = GgxReflectionLobe::sample(v, u);
    if (s.valid) s.pdf /= k_;  // keep the sampler's own (correct) density
    return s;
  }

 private:
  double k_;
};

// Sample weight off by a factor (pdf and distribution right).
class WeightScaledGgx : public GgxReflectionLobe {
 public:
  WeightScaledGgx(double alpha, double k) : GgxReflectionLobe(alpha), k_(k) {}
  BsdfSample sample(const Vec3& v, const Vec3& u) const override {
    BsdfSample s = GgxReflectionLobe::sample(v, u);
    s.weight *= k_;
    return s;
  }

 private:
  double k_;
};

// Self-consistent numbers but the wrong distribution: draws uniformly over the hemisphere while
// claiming the cosine density. Only the histogram can see it.
class WrongDistributionLambert : public LambertLobe {
 public:
  using LambertLobe::LambertLobe;
  BsdfSample sample(const Vec3& v, const Vec3& u) const override {
    BsdfSample s;
    if (v.z <= 0) return s;
    const double z = u.y, phi = 2 * kPi * u.z, r = std::sqrt(std::max(0.0, 1 - z * z));
    s.l = {r * std::cos(phi), r * std::sin(phi), z};
    s.pdf = pdf(v, s.l);
    if (!(s.pdf > 0)) return s;
    s.weight = eval(v, s.l) * (s.l.z / s.pdf);
    s.flags = kLobeReflection | kLobeDiffuse;
    s.valid = true;
    return s;
  }
};

// Sends a fraction of its samples below the surface, where pdf() (and f) are zero.
class LeakyLambert : public LambertLobe {
 public:
  LeakyLambert(double rho, double leak) : LambertLobe(rho), leak_(leak) {}
  BsdfSample sample(const Vec3& v, const Vec3& u) const override {
    if (u.x >= leak_) return LambertLobe::sample(v, Vec3{(u.x - leak_) / (1 - leak_), u.y, u.z});
    BsdfSample s = LambertLobe::sample(v, u);
    s.l.z = -s.l.z;
    s.weight = Rgb(0.0);
    return s;
  }

 private:
  double leak_;
};

// A non-reciprocal term: f(v, l) = rho / pi (1 + k (v.z - l.z)).
class NonReciprocalLambert : public LambertLobe {
 public:
  NonReciprocalLambert(double rho, double k) : LambertLobe(rho), k_(k) {}
  Rgb eval(const Vec3& v, const Vec3& l) const override {
    return LambertLobe::eval(v, l) * (1.0 + k_ * (std::abs(v.z) - std::abs(l.z)));
  }
  BsdfSample sample(const Vec3& v, const Vec3& u) const override {
    BsdfSample s = LambertLobe::sample(v, u);
    if (s.valid) s.weight = eval(v, s.l) * (std::abs(s.l.z) / s.pdf);
    return s;
  }

 private:
  double k_;
};

// GGX without the grazing guards: 0/0 at v.z = 0 and l.z = 0.
class UnguardedGgx : public GgxReflectionLobe {
 public:
  using GgxReflectionLobe::GgxReflectionLobe;
  Rgb eval(const Vec3& v, const Vec3& l) const override {
    if (v.z < 0 || l.z < 0) return Rgb(0.0);
    const Vec3 h = normalize(v + l);
    return Rgb(GgxDistribution(a_, a_).M_r(v, l, h));  // D G2 / (4 v.z l.z), unguarded
  }
};

}  // namespace dspbr::testing
